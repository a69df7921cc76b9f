#include "mechanism/kinematics.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace fourbar {

double Pose::theta3_rad() const { return std::atan2(u3.y, u3.x); }
double Pose::theta4_rad() const { return std::atan2(u4.y, u4.x); }

Pose solve_pose(const Rig& rig, double theta2_rad) { return solve_pose(rig, theta2_rad, rig.assembly_sign()); }

Pose solve_pose(const Rig& rig, double theta2_rad, double branch_sign) {
  const double l1 = rig.ground_length_m, l2 = rig.crank.length_m;
  const double l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  Pose p;
  p.u2 = unit(theta2_rad);
  // v: from the crank pin A to the rocker pivot O4; B sits at angle ±φ from v
  // seen from A, with cos φ from the triangle A–B–O4 (law of cosines).
  const Vec2 a = l2 * p.u2;
  const Vec2 v{l1 - a.x, -a.y};
  const double r = v.norm();
  assert(r > 0);
  const double cos_phi = std::clamp((l3 * l3 + r * r - l4 * l4) / (2.0 * l3 * r), -1.0, 1.0);
  const double sin_phi = branch_sign * std::sqrt(std::max(0.0, 1.0 - cos_phi * cos_phi));
  const Vec2 vh = v * (1.0 / r);
  p.u3 = {cos_phi * vh.x - sin_phi * vh.y, sin_phi * vh.x + cos_phi * vh.y};
  // u4 from B − O4 = A + l3·u3 − O4 = l3·u3 − v, normalised by its length l4.
  p.u4 = (l3 * p.u3 - v) * (1.0 / l4);
  return p;
}

void solve_rates(const Rig& rig, NominalMotion& m) {
  const double l2 = rig.crank.length_m, l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  const Vec2 u2 = m.pose.u2, u3 = m.pose.u3, u4 = m.pose.u4;
  const double w2 = m.crank.speed_rad_s, a2 = m.crank.accel_rad_s2;
  // Loop derivative: l2·ω2·n2 + l3·ω3·n3 − l4·ω4·n4 = 0 with n = u⊥.
  // Dotting with u4 removes ω4, dotting with u3 removes ω3 (eq. 2.1-2):
  //   ω3 = −ω2·l2·sin(θ2−θ4)/(l3·sin(θ3−θ4)),  ω4 = −ω2·l2·sin(θ2−θ3)/(l4·sin(θ3−θ4)).
  const double s34 = cross(u4, u3);  // sin(θ3 − θ4)
  assert(std::abs(s34) > 0);
  const double s24 = cross(u4, u2), s23 = cross(u3, u2);
  m.omega3_rad_s = -w2 * l2 * s24 / (l3 * s34);
  m.omega4_rad_s = -w2 * l2 * s23 / (l4 * s34);
  const double w3 = m.omega3_rad_s, w4 = m.omega4_rad_s;
  // Second derivative: l2(α2·n2 − ω2²·u2) + l3(α3·n3 − ω3²·u3) − l4(α4·n4 − ω4²·u4) = 0.
  // Known part k = l2(α2·n2 − ω2²·u2) − l3·ω3²·u3 + l4·ω4²·u4; then
  // l3·α3·n3 − l4·α4·n4 = −k, solved by the same two crosses (eq. 2.1-3).
  const Vec2 k = l2 * (a2 * u2.perp() - w2 * w2 * u2) - l3 * w3 * w3 * u3 + l4 * w4 * w4 * u4;
  // With n3·u4 = −sin(θ3−θ4) and n4·u3 = sin(θ3−θ4): dotting with u4 gives
  // α3 = k·u4/(l3·sin(θ3−θ4)); dotting with u3 gives α4 = k·u3/(l4·sin(θ3−θ4)).
  m.alpha3_rad_s2 = dot(k, u4) / (l3 * s34);
  m.alpha4_rad_s2 = dot(k, u3) / (l4 * s34);
}

NominalMotion solve_motion(const Rig& rig, const CrankState& crank) {
  NominalMotion m;
  m.crank = crank;
  m.pose = solve_pose(rig, crank.angle_rad);
  solve_rates(rig, m);
  return m;
}

std::array<double, 2> thesis_cos_theta3_roots(const Rig& rig, double theta2_rad) {
  const double l1 = rig.ground_length_m, l2 = rig.crank.length_m;
  const double l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  const double c2 = std::cos(theta2_rad), s2 = std::sin(theta2_rad);
  const double A = 2.0 * l3 * (l2 * c2 - l1);
  const double B = l4 * l4 - l1 * l1 - l2 * l2 - l3 * l3 + 2.0 * l1 * l2 * c2;
  const double C = 2.0 * l2 * l3 * s2;
  const double D2 = A * A + C * C;
  const double mid = A * B / D2;
  const double disc = std::max(0.0, mid * mid - (B * B - C * C) / D2);
  return {mid + std::sqrt(disc), mid - std::sqrt(disc)};
}

double transmission_angle_rad(const Pose& pose) {
  return std::acos(std::clamp(dot(pose.u3, pose.u4), -1.0, 1.0));
}

}  // namespace fourbar
