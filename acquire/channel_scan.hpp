#pragma once
// Pass 1 of acquire: one read of the whole recording for each accelerometer's
// statistics and clipped samples, the check that every value of every channel
// is finite, and the pulse channel's statistics and level histogram and local levels (from
// which pulse_thresholds.hpp sets the Schmitt thresholds).

#include <cstdint>
#include <span>
#include <vector>

#include "acquire/channel_inputs.hpp"
#include "acquire/level_histogram.hpp"
#include "acquire/local_levels.hpp"
#include "acquire/streaming_pass.hpp"

namespace fourbar {

/// Per accelerometer channel (m/s², calibrated) or the pulse channel (V).
struct ChannelStats {
  double min = 0, max = 0, mean = 0, rms = 0;
  std::uint64_t clipped_samples = 0;  ///< samples at the input range
  double first_clip_s = 0;            ///< time of the first clipped sample
};

struct ScanResult {
  std::vector<ChannelStats> channel_stats;  ///< per accelerometer, as `accelerometers`
  ChannelStats pulse_stats;                 ///< volts
  LevelHistogram pulse_histogram;           ///< volts
  LocalLevels pulse_local{1.0};             ///< volts, window by window
};

/// Reads the recording once. InputError naming the channel, frame and time
/// of the first non-finite value.
ScanResult scan_pass(const BlockStream& stream, std::span<const AccelerometerInput> accelerometers,
                     const ClipRange& clip, const PulseInput& pulse);

}  // namespace fourbar
