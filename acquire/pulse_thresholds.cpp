#include "acquire/pulse_thresholds.hpp"

#include "acquire/channel_inputs.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

const char* polarity_name(PulsePolarity p) { return p == PulsePolarity::rising ? "rising" : "falling"; }

/// Pulses are short: the level the channel spends most time at is idle. The
/// marking edge should be the pulse's leading edge.
std::optional<std::string> polarity_warning(bool idle_high, const ChannelSpec& pulse) {
  if (idle_high != (pulse.polarity == PulsePolarity::rising)) return std::nullopt;
  return pulse_channel_label(pulse) + ": the pulses go " + (idle_high ? "down from a high" : "up from a low") +
         " idle level, so polarity = \"" + polarity_name(pulse.polarity) +
         "\" times their trailing edge; if the leading edge marks the crank angle, set polarity = \"" +
         (idle_high ? "falling" : "rising") + "\"";
}

}  // namespace

ThresholdChoice pulse_thresholds(const LevelHistogram& histogram, const ChannelStats& pulse_stats,
                                 const Manifest& manifest, const std::filesystem::path& recording_file,
                                 const LocalLevels* local) {
  const ChannelSpec& pulse = manifest.pulse_channel();
  const std::string label = pulse_channel_label(pulse);
  const auto global_levels = histogram.two_levels();
  const auto automatic = automatic_thresholds(histogram);
  // Local levels, when the global ones fail or the baseline wanders.
  std::optional<PulseThresholds> following;
  const auto local_summary = local ? local->summary() : std::nullopt;
  if (local_summary && (!automatic || local_summary->wander > kBaselineWanderOfSwing * local_summary->swing)) {
    following = thresholds_between(-0.5 * local_summary->swing, 0.5 * local_summary->swing, local_summary->noise);
    if (following) following->follows_baseline = true;
  }
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
  } else if (following) {
    t = *following;
    choice.warnings.push_back(label + ": the baseline wanders by " + format_number(local_summary->wander) +
                              " V against a swing of " + format_number(local_summary->swing) +
                              " V; automatic thresholds follow the local levels (" +
                              format_number(kLocalLevelWindow_s) + " s windows)");
  } else if (automatic) {
    t = *automatic;
  } else {
    throw InputError(recording_file.string() + ": no crank pulses: " + label +
                     " has no two distinct levels (it spans " + format_number(pulse_stats.min) + " to " +
                     format_number(pulse_stats.max) + " V), not even over " + format_number(kLocalLevelWindow_s) +
                     " s windows; check the channel index in " + manifest.file.string() +
                     " and the pickup, or set threshold_low_V/threshold_high_V");
  }
  if (following && !pulse.threshold_low_V) {
    if (auto w = polarity_warning(local_summary->top_count > local_summary->bottom_count, pulse))
      choice.warnings.push_back(*w);
  } else if (automatic && global_levels) {
    if (auto w = polarity_warning(global_levels->high.count > global_levels->low.count, pulse))
      choice.warnings.push_back(*w);
  }
  if (t.hysteresis_widened)
    choice.warnings.push_back(label + " is noisy (noise " + format_number(t.noise) + " V against a swing of " +
                              format_number(t.top_level - t.bottom_level) + " V); hysteresis widened");
  return choice;
}

}  // namespace fourbar
