#pragma once
// What an accelerometer on the coupler or rocker of the linkage model reads,
// rigid or elastic, and an elastic link's mid-span deflection.
//
// The sensor sits at arc length r from the link's first joint (A for the
// coupler, O4 for the rocker) and lateral offset h along the link frame's
// normal n = u⊥; it measures specific force f = a_P + g·ŷ. Its tangential
// axis is n_s = t⊥, t the axis direction at r: the link's u on a rigid link,
// sim/flex's axis_tangent (the deformed axis) on an elastic one. The reading
// is f·n_s (sign +1 in analyze/conversion.hpp's terms), the normal one f·t.
// On a rigid link this is analyze/conversion.hpp's
//   m_t = a_J·n + r·α − h·ω² + g·cos θ.
// On an elastic link a_P is sim/flex's point_acceleration (frame plus
// Φη̈ − ω²Φη + 2ωEΦη̇); the offset h is carried by the floating frame
// (h(−α·u − ω²·n) with the frame's α, ω): the section's own rotation by the
// local slope is left out, an error of order h·slope.

#include "sim/linkage/linkage_dynamics.hpp"

namespace fourbar {

struct LinkSensor {
  int body = 1;           ///< coupler (1) or rocker (2)
  double distance_m = 0;  ///< r, from the link's first joint along it
  double offset_m = 0;    ///< h, along the frame's normal
};

struct SensorReading {
  double tangential_m_s2 = 0, normal_m_s2 = 0;
};

/// Needs evaluate()'s full pass (forward_kinematics, pair_forces, solve_accelerations).
SensorReading sensor_reading(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w,
                             const LinkSensor& s);

/// The lateral deflection Φy(L/2)·η (m) of an elastic body at mid-span; 0 on a rigid one.
double midspan_deflection_m(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w, int body);

}  // namespace fourbar
