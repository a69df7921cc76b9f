#pragma once
// From the edges of a tooth wheel or an encoder to numbered positions on the
// wheel: each edge gets its position p (p mod P is the tooth or encoder edge,
// P positions per turn; p = 0 at the first turn's reference edge), so its
// nominal angle is 2π·p/P.
//   • wheel + crank_index: the tooth each index mark names (index_marks.hpp:
//     the tooth it coincides with, or the first after it) is position 0 of
//     a turn; exactly pulses_per_rev teeth must lie between marks;
//   • wheel with missing teeth: an interval of about missing_teeth + 1
//     pitches is the gap, the tooth after it position 0; pulses_per_rev −
//     missing_teeth teeth between gaps;
//   • quadrature encoder: the four edges of A and B in turn count ±1 each
//     (A leading B counts up), P = 4·lines_per_rev; the edge each index mark
//     (Z) names — the A or B edge it coincides with (Z gated to one A/B
//     state), or the first after it — is position 0 of a turn, or the first
//     edge of the recording without one; B must lie a quarter line from A.
// What the signal contradicts (a tooth count, an index that never comes, A/B
// not in quadrature) is bad input: InputError naming the key, the counts and
// the fix — never an angle from a wrong count. A single turn with a wrong
// count (a glitch) is cut out and warned about.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "acquire/wheel_pass.hpp"

namespace fourbar {

struct NumberedSegment {
  std::vector<double> time_s;
  std::vector<std::int64_t> position;  ///< increasing; consecutive except across missing teeth
};

struct NumberedEdges {
  int positions_per_rev = 0;               ///< P
  std::vector<NumberedSegment> segments;   ///< each starts at a turn's position 0
  double count_direction = 1;              ///< encoder: +1 when A leads B, −1 when B leads A
  std::size_t turns_cut = 0;               ///< turns dropped for a wrong count
  std::vector<std::string> warnings;
};

NumberedEdges number_edges(const WheelEdges& edges, const Manifest& manifest,
                           const std::filesystem::path& recording_file);

}  // namespace fourbar
