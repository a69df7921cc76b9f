#include "acquire/pulse_pass.hpp"

#include <algorithm>
#include <cmath>

#include "acquire/channel_inputs.hpp"
#include "acquire/edge_detector.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/statistics.hpp"

namespace fourbar {

EdgePassResult edge_pass(const BlockStream& stream, const Manifest& manifest, const PulseThresholds& thresholds,
                         const LocalLevels* baseline) {
  const RecordingInfo& info = stream.reader.info();
  const auto channels = static_cast<std::size_t>(info.channels);
  const ChannelSpec& pulse = manifest.pulse_channel();
  const PulseInput input = pulse_input(manifest);
  EdgeDetector detector(thresholds, pulse.polarity, info.sample_rate_hz, info.start_time_s, pulse.debounce_s);
  const bool detrend = thresholds.follows_baseline && baseline;
  for_each_block(stream, AcquirePass::pulses, [&](std::span<const double> block, std::size_t frames,
                                                  std::uint64_t first) {
    std::vector<double> volts(frames);
    for (std::size_t f = 0; f < frames; ++f) volts[f] = block[f * channels + input.index] * input.volts_per_unit;
    if (detrend)
      for (std::size_t f = 0; f < frames; ++f) volts[f] -= baseline->mid_at(first + f);
    detector.push(volts.data(), frames, 1);
  });
  EdgePassResult result{detector.edges(), detector.widths(), detector.debounced(), detector.mid_level()};
  if (result.edges_s.empty())
    throw InputError(info.file.string() + ": no crank pulses: " + pulse_channel_label(pulse) + " never crosses from " +
                     format_number(thresholds.low) + " V to " + format_number(thresholds.high) + " V (" +
                     (pulse.polarity == PulsePolarity::rising ? "rising" : "falling") +
                     " edges); check the channel, its polarity and thresholds in " + manifest.file.string());
  return result;
}

namespace {

std::string ms(double s) { return format_number(s * 1e3, 3) + " ms"; }

/// What a twofold period step is, and how the manifest settles it.
std::string ambiguous_step_message(const PeriodStep& step, const Manifest& manifest) {
  const ChannelSpec& pulse = manifest.pulse_channel();
  const bool halves = step.period_after_s < step.period_before_s;
  std::string widths = std::isfinite(step.width_before_s) && std::isfinite(step.width_after_s)
                           ? "the pulse widths (" + ms(step.width_before_s) + " before, " + ms(step.width_after_s) +
                                 " after) do not scale with the period"
                           : "the pulse widths are unknown";
  std::string s = "the crank pulse period " + std::string(halves ? "halves" : "doubles") + " abruptly after " +
                  format_number(step.time_s) + " s (from " + ms(step.period_before_s) + " to " +
                  ms(step.period_after_s) + ") and stays; ";
  if (halves)
    return s + "either the crank sped up twofold within a turn or every pulse from there on has a second edge " +
           ms(step.period_after_s) + " after it (an echo, a second mark), and " + widths +
           "; if those edges are spurious set debounce_ms = " +
           format_number(0.75 * step.period_after_s * 1e3, 3) + " for " + pulse_channel_label(pulse) + " in " +
           manifest.file.string() + ", if the speed really changed cut the recording there";
  return s + "either the crank slowed twofold within a turn or every other pulse is lost from there on, and " + widths +
         "; check the pickup and threshold_low_V/threshold_high_V for " + pulse_channel_label(pulse) + " in " +
         manifest.file.string() + ", or cut the recording there";
}

}  // namespace

PulseTrain pulse_train_from_edges(const EdgePassResult& edges, const PulseTrainOptions& options,
                                  const Manifest& manifest, const std::filesystem::path& recording_file) {
  PulseTrain train = clean_pulse_train(edges.edges_s, options, edges.widths_s);
  const auto ambiguous = train.ambiguous();
  if (!ambiguous.empty())
    throw InputError(recording_file.string() + ": " + ambiguous_step_message(ambiguous.front(), manifest) +
                     (ambiguous.size() > 1 ? " (" + std::to_string(ambiguous.size()) + " such steps)" : ""));
  const std::size_t revolutions = train.revolutions();
  if (revolutions < 2)
    throw InputError(recording_file.string() + ": " + std::to_string(revolutions) + " complete revolution" +
                     (revolutions == 1 ? "" : "s") + " between the " + std::to_string(edges.edges_s.size()) +
                     " crank pulse edges of " + pulse_channel_label(manifest.pulse_channel()) +
                     "; need at least 2: record longer or check the pulse channel");
  return train;
}

std::size_t revolutions_lost(const PulseGap& gap) {
  return static_cast<std::size_t>(std::max(1.0, std::round(gap.periods)));
}

double median_width_deg(std::span<const double> widths_s, double period_s) {
  std::vector<double> finite;
  finite.reserve(widths_s.size());
  for (double w : widths_s)
    if (std::isfinite(w) && w > 0) finite.push_back(w);
  if (finite.empty() || !(period_s > 0)) return NAN;
  return 360.0 * median(std::move(finite)) / period_s;
}

}  // namespace fourbar
