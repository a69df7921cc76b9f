#include "acquire/acquisition_warnings.hpp"

#include <algorithm>

#include "acquire/acquisition.hpp"
#include "acquire/pulse_pass.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

/// Times listed in one warning: enough to find them, short enough for a line.
constexpr std::size_t kTimesShown = 5;

std::string time_list(const std::vector<double>& times) {
  std::string s;
  for (std::size_t i = 0; i < std::min(times.size(), kTimesShown); ++i)
    s += (i ? ", " : "") + format_number(times[i]) + " s";
  if (times.size() > kTimesShown) s += ", …";
  return s;
}

void pulse_train_warnings(const PulseTrain& train, std::vector<std::string>& warnings) {
  if (!train.removed_s.empty())
    warnings.push_back(std::to_string(train.removed_s.size()) +
                       " spurious pulse edges removed (echoes, doubled marks or noise) at " +
                       time_list(train.removed_s));
  if (!train.inserted_s.empty())
    warnings.push_back(std::to_string(train.inserted_s.size()) + " missing pulses inserted at " +
                       time_list(train.inserted_s));
  for (const auto& g : train.gaps)
    warnings.push_back("pulse train broken between " + format_number(g.from_s) + " s and " + format_number(g.to_s) +
                       " s (" + format_number(g.periods, 3) + " periods, no whole number): about " +
                       std::to_string(revolutions_lost(g)) + " revolutions dropped");
  for (const auto& st : train.steps)
    if (st.resolved)
      warnings.push_back("crank speed changed twofold within a turn after " + format_number(st.time_s) +
                         " s (period " + format_number(st.period_before_s * 1e3, 3) + " → " +
                         format_number(st.period_after_s * 1e3, 3) +
                         " ms; the pulse widths scale with it, so the pulses are real)");
  if (!train.orphan_s.empty())
    warnings.push_back(std::to_string(train.orphan_s.size()) +
                       " isolated pulses without a neighbour one period away, at " + time_list(train.orphan_s));
}

}  // namespace

std::vector<std::string> collect_warnings(const AcquisitionReport& report) {
  std::vector<std::string> warnings;
  for (std::size_t a = 0; a < report.channel_stats.size(); ++a)
    if (report.channel_stats[a].clipped_samples > 0)
      warnings.push_back("channel '" + report.channels[a].name + "' clipped: " +
                         std::to_string(report.channel_stats[a].clipped_samples) +
                         " samples at the input range, first at " +
                         format_number(report.channel_stats[a].first_clip_s) + " s; " +
                         std::to_string(report.revolutions_clipped) +
                         " revolutions are marked clipped (lower the gain)");
  pulse_train_warnings(report.pulses, warnings);
  if (report.frames_per_rev < kMinFramesPerRev)
    warnings.push_back("only " + format_number(report.frames_per_rev, 3) +
                       " samples per revolution: too coarse for impact bursts; record faster");
  return warnings;
}

}  // namespace fourbar
