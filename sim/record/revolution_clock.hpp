#pragma once
// Which crank revolution a time falls in, and the revolution records opened
// on demand: the same clock for the three-mode and the compliant simulator.
// Revolution k spans the crank angles origin + dir·2π·[k, k + 1).

#include <vector>

#include "sim/drive/crank_motion.hpp"
#include "sim/record/run_records.hpp"

namespace fourbar {

/// Turns added before flooring a crank angle to its revolution index, so a
/// time located on a turn boundary to round-off counts in the new turn.
inline constexpr double kTurnBoundarySlack_turns = 1e-12;

struct RevolutionClock {
  double origin_rad = 0;
  int dir = 1;

  /// The revolution holding absolute time `time_s`.
  int index_at(const CrankMotion& crank, double time_s) const;
  /// Absolute start time of revolution k.
  double start_s(const CrankMotion& crank, int k) const;
  /// Record k, opening the records up to it (index, start and end times).
  RevolutionRecord& record(const CrankMotion& crank, std::vector<RevolutionRecord>& records, int k) const;
};

}  // namespace fourbar
