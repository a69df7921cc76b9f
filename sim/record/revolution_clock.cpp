#include "sim/record/revolution_clock.hpp"

#include <cmath>

#include "common/units.hpp"

namespace fourbar {

int RevolutionClock::index_at(const CrankMotion& crank, double time_s) const {
  const double turns = (crank.at(time_s).angle_rad - origin_rad) * dir / units::kTwoPi;
  return static_cast<int>(std::floor(turns + kTurnBoundarySlack_turns));
}

double RevolutionClock::start_s(const CrankMotion& crank, int k) const {
  return crank.time_at_angle(origin_rad + dir * units::kTwoPi * k);
}

RevolutionRecord& RevolutionClock::record(const CrankMotion& crank, std::vector<RevolutionRecord>& records,
                                          int k) const {
  while (static_cast<int>(records.size()) <= k) {
    RevolutionRecord r;
    r.index = static_cast<int>(records.size());
    r.start_time_s = start_s(crank, r.index);
    r.end_time_s = start_s(crank, r.index + 1);
    records.push_back(r);
  }
  return records[k];
}

}  // namespace fourbar
