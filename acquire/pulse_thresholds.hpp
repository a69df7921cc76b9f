#pragma once
// The Schmitt thresholds acquire uses on the pulse channel: the manifest's
// when it gives them, else the automatic ones from the pulse channel's level
// histogram (level_histogram.hpp) or, on a wandering baseline, from its
// local levels (local_levels.hpp); and what the two levels say about the
// set-up (a polarity that times the trailing edge; a channel so noisy that
// the automatic hysteresis was widened, warned exactly when it was).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "acquire/channel_scan.hpp"
#include "acquire/level_histogram.hpp"
#include "acquire/local_levels.hpp"
#include "acquire/manifest.hpp"

namespace fourbar {

struct ThresholdChoice {
  PulseThresholds thresholds;         ///< as used
  std::vector<std::string> warnings;  ///< about the pulse channel's levels
};

/// InputError when the manifest gives no thresholds and the pulse channel has
/// no two distinct levels, globally or window by window (no pulses);
/// `recording_file` names it. With `local` levels, automatic thresholds follow
/// the local mid-level when the global levels fail or the baseline wanders by
/// more than kBaselineWanderOfSwing of the swing (`follows_baseline`).
ThresholdChoice pulse_thresholds(const LevelHistogram& histogram, const ChannelStats& pulse_stats,
                                 const Manifest& manifest, const std::filesystem::path& recording_file,
                                 const LocalLevels* local = nullptr);

}  // namespace fourbar
