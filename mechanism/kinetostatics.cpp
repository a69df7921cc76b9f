#include "mechanism/kinetostatics.hpp"

#include <Eigen/Dense>

namespace fourbar {

JointLoads solve_loads(const Rig& rig, const NominalMotion& m) {
  const Link &cr = rig.crank, &co = rig.coupler, &ro = rig.rocker;
  const double l2 = cr.length_m, l3 = co.length_m, l4 = ro.length_m;
  const Vec2 u2 = m.pose.u2, u3 = m.pose.u3, u4 = m.pose.u4;
  const double w2 = m.crank.speed_rad_s, a2 = m.crank.accel_rad_s2;
  const double w3 = m.omega3_rad_s, a3 = m.alpha3_rad_s2, w4 = m.omega4_rad_s, a4 = m.alpha4_rad_s2;
  const double g = rig.gravity_m_s2;
  const Vec2 gv{0.0, -g};

  // Accelerations of the crank pin and of the mass centres.
  const Vec2 acc_u2 = a2 * u2.perp() - w2 * w2 * u2;
  const Vec2 a_A = l2 * acc_u2;
  const Vec2 a_G2 = cr.mass_centre_m * acc_u2;
  const Vec2 a_G3 = a_A + co.mass_centre_m * (a3 * u3.perp() - w3 * w3 * u3);
  const Vec2 a_G4 = ro.mass_centre_m * (a4 * u4.perp() - w4 * w4 * u4);

  // Bearing force F on the coupler at B from two moment balances:
  //  rocker about O4:  l4·u4 × F = −I_O4·α4 − m4·g·S4·cos θ4
  //  coupler about A:  l3·u3 × F = I_A3·α3 + m3·S3·(u3 × a_A) + m3·g·S3·cos θ3
  const double r1 = -ro.inertia_about_joint() * a4 - ro.mass_kg * g * ro.mass_centre_m * u4.x;
  const double r2 = co.inertia_about_joint() * a3 + co.mass_kg * co.mass_centre_m * cross(u3, a_A) +
                    co.mass_kg * g * co.mass_centre_m * u3.x;
  const double det = l3 * l4 * cross(u4, u3);  // l3·l4·sin(θ3 − θ4)
  JointLoads out;
  out.bearing_N = {(r1 * l3 * u3.x - r2 * l4 * u4.x) / det, (r1 * l3 * u3.y - r2 * l4 * u4.y) / det};

  // Force balances, coupler → rocker → crank, then the crank's moment about O2.
  const Vec2 F = out.bearing_N;
  out.crank_pin_N = co.mass_kg * a_G3 - co.mass_kg * gv - F;
  out.rocker_pivot_N = ro.mass_kg * a_G4 - ro.mass_kg * gv + F;
  out.crank_pivot_N = cr.mass_kg * a_G2 - cr.mass_kg * gv + out.crank_pin_N;
  out.crank_torque_Nm = cr.inertia_about_joint() * a2 + l2 * cross(u2, out.crank_pin_N) +
                        cr.mass_kg * g * cr.mass_centre_m * u2.x;
  return out;
}

LagrangeSolution solve_loads_lagrange(const Rig& rig, const NominalMotion& m) {
  const Link &cr = rig.crank, &co = rig.coupler, &ro = rig.rocker;
  const double l2 = cr.length_m, l3 = co.length_m, l4 = ro.length_m;
  const double m3 = co.mass_kg, S3 = co.mass_centre_m, g = rig.gravity_m_s2;
  const double c2 = m.pose.u2.x, s2 = m.pose.u2.y, c3 = m.pose.u3.x, s3 = m.pose.u3.y;
  const double c4 = m.pose.u4.x, s4 = m.pose.u4.y;
  const double w2 = m.crank.speed_rad_s, a2 = m.crank.accel_rad_s2;
  const double w3 = m.omega3_rad_s, w4 = m.omega4_rad_s;
  const double c23 = c2 * c3 + s2 * s3, s23 = s2 * c3 - c2 * s3;  // cos, sin of (θ2 − θ3)

  // Mass matrix in q = (θ2, θ3, θ4) from T (errata: cross term +2·l2·S3·ω2·ω3·cos(θ2−θ3)).
  const double M11 = cr.inertia_about_joint() + m3 * l2 * l2, M12 = m3 * l2 * S3 * c23;
  const double M22 = co.inertia_about_joint(), M33 = ro.inertia_about_joint();
  // Velocity-product terms and gravity, Q = −∂V/∂q (eq. 3.3-1/3.3-2).
  const double h2 = m3 * l2 * S3 * s23 * w3 * w3, h3 = -m3 * l2 * S3 * s23 * w2 * w2;
  const double Q2 = -(cr.mass_kg * cr.mass_centre_m + m3 * l2) * g * c2;
  const double Q3 = -m3 * g * S3 * c3, Q4 = -ro.mass_kg * g * ro.mass_centre_m * c4;

  // Unknowns x = (α3, α4, τ, λx, λy). Constraint Jacobian rows (loop x, y):
  //   Φx_q = (−l2·s2, −l3·s3,  l4·s4),  Φy_q = (l2·c2, l3·c3, −l4·c4);
  // τ is the multiplier of θ2 − θ2(t), (λx, λy) the force on the coupler at B.
  Eigen::Matrix<double, 5, 5> A = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> b;
  A.row(0) << M12, 0, -1, l2 * s2, -l2 * c2;
  b(0) = Q2 - M11 * a2 - h2;
  A.row(1) << M22, 0, 0, l3 * s3, -l3 * c3;
  b(1) = Q3 - M12 * a2 - h3;
  A.row(2) << 0, M33, 0, -l4 * s4, l4 * c4;
  b(2) = Q4;
  // Acceleration-level loop closure: Φ_q·q̈ + (Φ_q)˙·q̇ = 0.
  A.row(3) << -l3 * s3, l4 * s4, 0, 0, 0;
  b(3) = l2 * s2 * a2 + l2 * c2 * w2 * w2 + l3 * c3 * w3 * w3 - l4 * c4 * w4 * w4;
  A.row(4) << l3 * c3, -l4 * c4, 0, 0, 0;
  b(4) = -l2 * c2 * a2 + l2 * s2 * w2 * w2 + l3 * s3 * w3 * w3 - l4 * s4 * w4 * w4;

  const Eigen::Matrix<double, 5, 1> x = A.fullPivLu().solve(b);
  return {x(0), x(1), x(2), Vec2{x(3), x(4)}};
}

double kinetic_energy_J(const Rig& rig, const NominalMotion& m) {
  const Link &cr = rig.crank, &co = rig.coupler, &ro = rig.rocker;
  const double w2 = m.crank.speed_rad_s, w3 = m.omega3_rad_s, w4 = m.omega4_rad_s;
  const Vec2 v_G3 = cr.length_m * w2 * m.pose.u2.perp() + co.mass_centre_m * w3 * m.pose.u3.perp();
  return 0.5 * (cr.inertia_about_joint() * w2 * w2 + co.mass_kg * dot(v_G3, v_G3) +
                co.inertia_cg_kg_m2 * w3 * w3 + ro.inertia_about_joint() * w4 * w4);
}

double potential_energy_J(const Rig& rig, const Pose& p) {
  const Link &cr = rig.crank, &co = rig.coupler, &ro = rig.rocker;
  const double y2 = cr.mass_centre_m * p.u2.y;
  const double y3 = cr.length_m * p.u2.y + co.mass_centre_m * p.u3.y;
  const double y4 = ro.mass_centre_m * p.u4.y;
  return rig.gravity_m_s2 * (cr.mass_kg * y2 + co.mass_kg * y3 + ro.mass_kg * y4);
}

}  // namespace fourbar
