#pragma once
// Kinematics of the nominal (clearance-free) four-bar, thesis ch. 2
// (eq. 2.1-1 to 2.1-3, Smith & Maunder), in closed form.
//
// Loop: A = l2·u2 (crank pin), B = A + l3·u3 = O4 + l4·u4 (coupler–rocker
// joint), with u_i = (cos θi, sin θi). The crank state (θ2, ω2, α2) is an
// input, so a measured, non-constant crank speed can be used.

#include <array>

#include "mechanism/rig.hpp"
#include "mechanism/vec2.hpp"

namespace fourbar {

/// Prescribed crank motion at one instant.
struct CrankState {
  double angle_rad = 0;     ///< θ2
  double speed_rad_s = 0;   ///< ω2
  double accel_rad_s2 = 0;  ///< α2
};

/// Link directions at one crank angle (unit vectors along each link).
struct Pose {
  Vec2 u2, u3, u4;
  double theta3_rad() const;  ///< principal value in (−π, π]
  double theta4_rad() const;
};

/// Full nominal motion at one instant.
struct NominalMotion {
  CrankState crank;
  Pose pose;
  double omega3_rad_s = 0, omega4_rad_s = 0;
  double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0;
};

/// Positions θ3, θ4 (eq. 2.1-1) on the rig's assembly branch, computed as the
/// intersection of the circles about A (radius l3) and O4 (radius l4).
Pose solve_pose(const Rig& rig, double theta2_rad);

/// The same on an explicitly chosen branch (sign +1 open, −1 crossed).
Pose solve_pose(const Rig& rig, double theta2_rad, double branch_sign);

/// Velocities (eq. 2.1-2) and accelerations (eq. 2.1-3, with α2 ≠ 0 allowed).
NominalMotion solve_motion(const Rig& rig, const CrankState& crank);

/// Velocities and accelerations for a pose already solved.
void solve_rates(const Rig& rig, NominalMotion& m);

/// The two roots of the corrected thesis eq. 2.1-1a for cos θ3
/// (A·cos θ3 + C·sin θ3 = B; see THESIS-ERRATA.md). For cross-checks.
std::array<double, 2> thesis_cos_theta3_roots(const Rig& rig, double theta2_rad);

/// Transmission angle (between coupler and rocker), in [0, π].
double transmission_angle_rad(const Pose& pose);

}  // namespace fourbar
