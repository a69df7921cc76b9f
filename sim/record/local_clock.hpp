#pragma once
// A simulator's local time: absolute time = origin + local time, the origin
// moved to each segment's start, so long runs keep the resolution of the
// local time (crank_motion.hpp). The same clock for the three-mode and the
// compliant simulator.

#include <cmath>

#include "mechanism/kinematics.hpp"
#include "sim/drive/crank_motion.hpp"

namespace fourbar {

struct LocalClock {
  double origin_s = 0;  ///< absolute time of local time 0

  double absolute(double time) const { return origin_s + time; }
  double local(double absolute_time) const { return absolute_time - origin_s; }
  CrankState crank_at(const CrankMotion& crank, double time) const { return crank.at_local(origin_s, time); }
  /// Moves the origin to the local time `time`; returns that instant in the
  /// new local time (the rounding remainder of origin + time, ~1e-13 s at most).
  double rebase(double time) {
    const double o = origin_s + time;
    const double r = std::abs(origin_s) >= std::abs(time) ? (origin_s - o) + time : (time - o) + origin_s;
    origin_s = o;
    return r;
  }
};

}  // namespace fourbar
