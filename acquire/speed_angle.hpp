#pragma once
// A crank angle from a processed speed channel (role = "crank_speed": an rpm
// track, as many DAQ suites store the tacho): the calibrated speed read once
// per sample, integrated by the trapezoid rule (the speed linear between
// samples, so the angle is exactly quadratic there), and cut into virtual
// edges, kSpeedPositionsPerRev per turn, numbered like a wheel's
// (wheel_decode.hpp) so that plan_wheel_revolutions and everything after it
// is unchanged. The angle's zero: the median phase of the integrated angle at
// the once-per-turn crank_pulse edges when there is one; without one it is
// 0° at the first sample analysed plus the channel's crank_offset_deg when
// given; with neither a pulse nor an offset it is unknown and said so: the
// turns and speeds are right, the crank-angle phase arbitrary, and α/ω wrong
// too (the conversion needs the crank angle: gravity, the sensor's offset;
// 37 % α3 error on the virtual rig, tests/analyze/test_speed_channel). A speed ≤ 0 or not finite in
// the part analysed is bad input naming the channel and the span.

#include <filesystem>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "acquire/streaming_pass.hpp"
#include "acquire/time_range.hpp"
#include "acquire/wheel_decode.hpp"

namespace fourbar {

/// Virtual edges per turn: one per degree.
inline constexpr int kSpeedPositionsPerRev = 360;

/// The calibrated speed of `speed` (rpm), one value per frame.
std::vector<double> speed_track_pass(const BlockStream& stream, const Manifest& manifest, const ChannelSpec& speed);

struct SpeedAngle {
  NumberedEdges edges;
  std::string source;                 ///< for WheelReport::source
  bool zero_known = false;            ///< from a crank_pulse channel
  double zero_spread_deg = 0;         ///< largest |phase at a pulse − median|
  std::vector<std::string> warnings;
};

/// `rpm[i]` at start_time_s + i/sample_rate_hz; `pulse_s` the crank_pulse
/// edges (empty without one); `range` the part analysed (checked for speed ≤ 0).
SpeedAngle speed_angle_edges(const std::vector<double>& rpm, double sample_rate_hz, double start_time_s,
                             const ChannelSpec& speed, const ChannelSpec* pulse, const std::vector<double>& pulse_s,
                             const TimeRange& range, const std::filesystem::path& manifest_file);

}  // namespace fourbar
