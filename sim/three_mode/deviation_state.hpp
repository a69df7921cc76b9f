#pragma once
// The free-flight state as deviations from the nominal mechanism:
// δ3 = θ3 − θ3,nom(t), δ4 = θ4 − θ4,nom(t) scaled by ξ/l3, their rates by
// |ω2|·ξ/l3, so every component is of order one and the eccentricity keeps
// full relative precision (|e| ≤ ξ ≪ link lengths). Shared by the three-mode
// simulator's free flight and the compliant simulator.

#include <cmath>

#include "mechanism/kinematics.hpp"
#include "sim/three_mode/model.hpp"

namespace fourbar {

struct DeviationScales {
  double delta = 1;        ///< ξ/l3
  double speed_rad_s = 1;  ///< |ω2|
};

inline Vec2 rotate_by(Vec2 u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * u.x - s * u.y, s * u.x + c * u.y};
}

/// Link motion from the scaled deviations y[0..3] about the nominal motion `nm`.
inline LinkMotion deviation_links(const NominalMotion& nm, const DeviationScales& k, const double* y) {
  LinkMotion m;
  m.u3 = rotate_by(nm.pose.u3, y[0] * k.delta);
  m.u4 = rotate_by(nm.pose.u4, y[1] * k.delta);
  m.omega3_rad_s = nm.omega3_rad_s + y[2] * k.delta * k.speed_rad_s;
  m.omega4_rad_s = nm.omega4_rad_s + y[3] * k.delta * k.speed_rad_s;
  return m;
}

/// The scaled deviations y[0..3] of a link motion about the nominal motion `nm`.
inline void deviation_state(const NominalMotion& nm, const DeviationScales& k, const LinkMotion& m, double* y) {
  auto angle_between = [](Vec2 a, Vec2 b) { return std::atan2(cross(a, b), dot(a, b)); };
  y[0] = angle_between(nm.pose.u3, m.u3) / k.delta;
  y[1] = angle_between(nm.pose.u4, m.u4) / k.delta;
  y[2] = (m.omega3_rad_s - nm.omega3_rad_s) / (k.delta * k.speed_rad_s);
  y[3] = (m.omega4_rad_s - nm.omega4_rad_s) / (k.delta * k.speed_rad_s);
}

}  // namespace fourbar
