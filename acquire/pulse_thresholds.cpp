#include "acquire/pulse_thresholds.hpp"

#include "acquire/channel_inputs.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

const char* polarity_name(PulsePolarity p) { return p == PulsePolarity::rising ? "rising" : "falling"; }

/// Pulses are short: the level the channel spends most time at is idle. The
/// marking edge should be the pulse's leading edge.
std::optional<std::string> polarity_warning(const LevelHistogram& histogram, const ChannelSpec& pulse) {
  const auto levels = histogram.two_levels();
  if (!levels) return std::nullopt;
  const bool idle_high = levels->high.count > levels->low.count;
  if (idle_high != (pulse.polarity == PulsePolarity::rising)) return std::nullopt;
  return pulse_channel_label(pulse) + ": the pulses go " + (idle_high ? "down from a high" : "up from a low") +
         " idle level, so polarity = \"" + polarity_name(pulse.polarity) +
         "\" times their trailing edge; if the leading edge marks the crank angle, set polarity = \"" +
         (idle_high ? "falling" : "rising") + "\"";
}

}  // namespace

ThresholdChoice pulse_thresholds(const LevelHistogram& histogram, const ChannelStats& pulse_stats,
                                 const Manifest& manifest, const std::filesystem::path& recording_file) {
  const ChannelSpec& pulse = manifest.pulse_channel();
  const std::string label = pulse_channel_label(pulse);
  const auto automatic = automatic_thresholds(histogram);
  ThresholdChoice choice;
  PulseThresholds& t = choice.thresholds;
  if (pulse.threshold_low_V) {
    t.low = *pulse.threshold_low_V;
    t.high = *pulse.threshold_high_V;
    t.automatic = false;
    if (automatic) {
      t.bottom_level = automatic->bottom_level, t.top_level = automatic->top_level;
      t.noise = automatic->noise;
    }
  } else if (automatic) {
    t = *automatic;
  } else {
    throw InputError(recording_file.string() + ": no crank pulses: " + label +
                     " has no two distinct levels (it spans " + format_number(pulse_stats.min) + " to " +
                     format_number(pulse_stats.max) + " V); check the channel index in " + manifest.file.string() +
                     " and the pickup, or set threshold_low_V/threshold_high_V");
  }
  if (automatic)
    if (auto w = polarity_warning(histogram, pulse)) choice.warnings.push_back(*w);
  if (t.hysteresis_widened)
    choice.warnings.push_back(label + " is noisy (noise " + format_number(t.noise) + " V against a swing of " +
                              format_number(t.top_level - t.bottom_level) + " V); hysteresis widened");
  return choice;
}

}  // namespace fourbar
