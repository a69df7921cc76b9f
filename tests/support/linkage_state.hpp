#pragma once
// A seeded random instant of the linkage model for the stage tests
// (tests/sim/linkage): the crank anywhere at up to 40 rad/s and 300 rad/s²,
// the links 1 mrad off their nominal directions with rates 1 rad/s off, every
// joint offset and modal coordinate within 10 µm and its rate within 1 cm/s
// (inside a 0.254 mm clearance: no pin placed by its offsets touches its
// bushing; the loop-closing joint's pin moves with the links' 1 mrad, ~0.3 mm).

#include <cmath>
#include <random>

#include "mechanism/kinematics.hpp"
#include "sim/linkage/linkage_dynamics.hpp"

namespace fourbar {

inline void random_linkage_state(const Rig& rig, const LinkageModel& lm, std::mt19937& gen, LinkageCoordinates& q) {
  std::uniform_real_distribution<double> u(-1, 1);
  const CrankState c{3.2 * u(gen), 40 * u(gen), 300 * u(gen)};
  const NominalMotion nm = solve_motion(rig, c);
  const int n = lm.coordinates();
  q.crank = c;
  q.u2 = unit(c.angle_rad);
  q.u = {unit(std::atan2(nm.pose.u3.y, nm.pose.u3.x) + 1e-3 * u(gen)),
         unit(std::atan2(nm.pose.u4.y, nm.pose.u4.x) + 1e-3 * u(gen))};
  q.q_offsets = ZVec::Zero(n);
  q.z_rate = ZVec::Zero(n + 1);
  q.z_rate(0) = nm.omega3_rad_s + u(gen);
  q.z_rate(1) = nm.omega4_rad_s + u(gen);
  for (int i = 2; i < n; ++i) {
    q.q_offsets(i) = 1e-5 * u(gen);
    q.z_rate(i) = 1e-2 * u(gen);
  }
  q.z_rate(n) = c.speed_rad_s;
}

}  // namespace fourbar
