#pragma once
// A tooth wheel or a quadrature encoder on the virtual rig's crank, in place
// of the once-per-turn pulse: the edge times of each of its channels, from
// the crank drive's own motion (motion_source.hpp), so that what acquire
// reads back is checked against kinematics it never saw.
//
//   • tooth wheel: `teeth` positions per turn, tooth k's leading edge where
//     the crank has turned angle_deg + k·pitch + e_k past its start (e_k the
//     tooth's spacing error, uniform within ±tooth_error_deg, seeded), the
//     tooth half a pitch wide; the last `missing_teeth` positions left out;
//   • encoder: line k's A edges at angle_deg + k·pitch + e_k and half a pitch
//     later, B's a quarter pitch after A's;
//   • index (optional): once per turn, a quarter pitch wide, its leading
//     edge index_offset_pitch pitches after position 0's edge (default a
//     quarter pitch, encoder an eighth, before it). At 0 it rises with
//     position 0's edge: a tooth wheel's index pickup rising with tooth 0,
//     or an encoder's Z gated to one A/B state (high while A is high and B
//     low, from line 0's A rising edge to B's), as standard encoders do.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "virtual_rig/motion_source.hpp"

namespace fourbar {

struct WheelSpec {
  int teeth = 0;                   ///< > 0: a tooth wheel with this many positions
  int missing_teeth = 0;
  int encoder_lines = 0;           ///< > 0: a quadrature encoder instead
  bool index = false;              ///< an index channel (once per turn)
  /// Index leading edge after position 0's edge, in pitches (lines); unset:
  /// −0.25 (encoder −0.125). 0: on the edge (Z gated to A high, B low).
  std::optional<double> index_offset_pitch;
  double tooth_error_rad = 0;      ///< each tooth (line) off by up to ± this
  bool correct_tooth_spacing = false;  ///< written into the manifest
  bool active() const { return teeth > 0 || encoder_lines > 0; }
};

/// One channel of pulses (leading and trailing edge times, s).
struct EdgeChannel {
  std::string name;
  ChannelRole role = ChannelRole::crank_pulse;
  std::vector<std::pair<double, double>> pulses;
};

/// The wheel's channels (main first: crank_pulse or encoder_a; then
/// encoder_b; then crank_index) over [0, duration_s]; `angle_rad` is the
/// crank angle at position 0's edge, `main_name` the main channel's name.
std::vector<EdgeChannel> wheel_channels(const WheelSpec& wheel, const CrankDrive& drive, double angle_rad,
                                        double duration_s, double margin_s, const std::string& main_name,
                                        std::uint64_t seed);

/// Each position's angle error (rad), as wheel_channels draws it for `seed`;
/// position 0 has none (it defines angle_deg).
std::vector<double> wheel_tooth_errors_rad(const WheelSpec& wheel, std::uint64_t seed);

/// The manifest channel of an edge channel (keys of the wheel on the main one).
ChannelSpec wheel_manifest_channel(const WheelSpec& wheel, const EdgeChannel& channel, double angle_rad);

}  // namespace fourbar
