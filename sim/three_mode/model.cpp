#include "sim/three_mode/model.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <string>

#include "common/error.hpp"
#include "mechanism/kinetostatics.hpp"

namespace fourbar {

namespace {

/// |v| without std::hypot's overflow care (mechanism lengths are far from
/// overflow; hypot cost 12 % of a run, bench_clearance --profile).
double length(Vec2 v) { return std::sqrt(dot(v, v)); }

}  // namespace

ClearanceModel::ClearanceModel(const Rig& rig, double clearance_m)
    : rig_(rig),
      xi_(clearance_m),
      l1_(rig.ground_length_m),
      l2_(rig.crank.length_m),
      l3_(rig.coupler.length_m),
      l4_(rig.rocker.length_m),
      I2_(rig.crank.inertia_about_joint()),
      I3_(rig.coupler.inertia_about_joint()),
      I4_(rig.rocker.inertia_about_joint()),
      m3_l2_S3_(rig.coupler.mass_kg * rig.crank.length_m * rig.coupler.mass_centre_m),
      m3_S3_g_(rig.coupler.mass_kg * rig.coupler.mass_centre_m * rig.gravity_m_s2),
      m4_S4_g_(rig.rocker.mass_kg * rig.rocker.mass_centre_m * rig.gravity_m_s2),
      crank_gravity_((rig.crank.mass_kg * rig.crank.mass_centre_m + rig.coupler.mass_kg * rig.crank.length_m) *
                     rig.gravity_m_s2),
      branch_(rig.assembly_sign()) {}

BearingState ClearanceModel::bearing(const CrankState& crank, const LinkMotion& m) const {
  return bearing(crank, unit(crank.angle_rad), m);
}

BearingState ClearanceModel::bearing(const CrankState& crank, Vec2 u2, const LinkMotion& m) const {
  // e = A + l3·u3 − O4 − l4·u4, summed so that the large terms cancel first.
  const Vec2 e{(l2_ * u2.x - l1_) + (l3_ * m.u3.x - l4_ * m.u4.x), l2_ * u2.y + (l3_ * m.u3.y - l4_ * m.u4.y)};
  BearingState b;
  b.eccentricity_m = e;
  const double r = length(e);
  b.gap_m = xi_ - r;
  b.normal = r > 0 ? e * (1.0 / r) : Vec2{1.0, 0.0};
  // Relative velocity of the pin (coupler point B) and the rocker's material
  // point at B: v_B3 − v_B4 = l2ω2·u2⊥ + l3ω3·u3⊥ − ω4·(B − O4)⊥.
  const Vec2 b_o4 = l4_ * m.u4 + e;
  const Vec2 v = l2_ * crank.speed_rad_s * u2.perp() + l3_ * m.omega3_rad_s * m.u3.perp() -
                 m.omega4_rad_s * b_o4.perp();
  b.normal_speed_m_s = dot(v, b.normal);
  b.tangential_speed_m_s = dot(v, b.normal.perp());
  return b;
}

void ClearanceModel::free_accelerations(const CrankState& crank, const LinkMotion& m, double& alpha3,
                                        double& alpha4) const {
  free_accelerations(crank, unit(crank.angle_rad), m, alpha3, alpha4);
}

void ClearanceModel::free_accelerations(const CrankState& crank, Vec2 u2, const LinkMotion& m, double& alpha3,
                                        double& alpha4) const {
  const double sin_b = cross(m.u3, u2), cos_b = dot(m.u3, u2);  // β = θ2 − θ3
  const double w2 = crank.speed_rad_s;
  // thesis eq. 4.1-20 (with I_A3, errata) extended by α2; eq. 4.2-1.
  alpha3 = (m3_l2_S3_ * (w2 * w2 * sin_b - crank.accel_rad_s2 * cos_b) - m3_S3_g_ * m.u3.x) / I3_;
  alpha4 = -m4_S4_g_ * m.u4.x / I4_;
}

void ClearanceModel::forced_accelerations(const CrankState& crank, Vec2 u2, const LinkMotion& m, Vec2 p,
                                          double& alpha3, double& alpha4) const {
  free_accelerations(crank, u2, m, alpha3, alpha4);
  const Vec2 e{(l2_ * u2.x - l1_) + (l3_ * m.u3.x - l4_ * m.u4.x), l2_ * u2.y + (l3_ * m.u3.y - l4_ * m.u4.y)};
  alpha3 += dot(p, l3_ * m.u3.perp()) / I3_;
  alpha4 -= dot(p, (l4_ * m.u4 + e).perp()) / I4_;
}

double ClearanceModel::crank_torque_Nm(const CrankState& crank, const LinkMotion& m, double alpha3,
                                       Vec2 pin_force_N) const {
  return crank_torque_Nm(crank, unit(crank.angle_rad), m, alpha3, pin_force_N);
}

double ClearanceModel::crank_torque_Nm(const CrankState& crank, Vec2 u2, const LinkMotion& m, double alpha3,
                                       Vec2 pin_force_N) const {
  const double sin_b = cross(m.u3, u2), cos_b = dot(m.u3, u2);
  const double w3 = m.omega3_rad_s;
  // Lagrange's equation for θ2 (thesis eq. 3.3-1 with α2, corrected):
  // (I_O2 + m3·l2²)·α2 + m3·l2·S3·(α3·cos β + ω3²·sin β) = τ − (m2·S2 + m3·l2)·g·cos θ2 + P·(l2·u2⊥)
  const double m3_l2_l2 = rig_.coupler.mass_kg * l2_ * l2_;
  return (I2_ + m3_l2_l2) * crank.accel_rad_s2 + m3_l2_S3_ * (alpha3 * cos_b + w3 * w3 * sin_b) +
         crank_gravity_ * u2.x - dot(pin_force_N, l2_ * u2.perp());
}

namespace {

/// Sensitivities of (ω3, ω4) or (α3, α4) to a relative velocity r of B
/// against C: l3·x3·u3⊥ − l4·x4·u4⊥ = r solved by two cross products.
struct LoopSolve {
  double l3, l4, s;  // s = sin(θ4 − θ3) = u3 × u4
  Vec2 p3, p4;       // u3⊥, u4⊥
  void solve(Vec2 r, double& x3, double& x4) const {
    x3 = cross(r, p4) / (l3 * s);
    x4 = cross(r, p3) / (l4 * s);
  }
};

}  // namespace

LinkMotion ClearanceModel::following_links(const CrankState& crank, double eta, double eta_rate) const {
  return following_links(crank, unit(crank.angle_rad), unit(eta), eta_rate);
}

LinkMotion ClearanceModel::following_links(const CrankState& crank, Vec2 u2, Vec2 n, double eta_rate) const {
  // Loop A + l3·u3 = O4' + l4·u4 with the shifted pivot O4' = O4 + ξ·n:
  // B on the circles of radius l3 about A and l4 about O4'.
  const Vec2 v{(l1_ - l2_ * u2.x) + xi_ * n.x, -l2_ * u2.y + xi_ * n.y};  // O4' − A
  const double r = length(v);
  assert(r > 0);
  const double cos_phi = std::clamp((l3_ * l3_ + r * r - l4_ * l4_) / (2.0 * l3_ * r), -1.0, 1.0);
  const double sin_phi = branch_ * std::sqrt(std::max(0.0, 1.0 - cos_phi * cos_phi));
  const Vec2 vh = v * (1.0 / r);
  LinkMotion m;
  m.u3 = {cos_phi * vh.x - sin_phi * vh.y, sin_phi * vh.x + cos_phi * vh.y};
  m.u4 = (l3_ * m.u3 - v) * (1.0 / l4_);
  // Velocity loop: l3·ω3·u3⊥ − l4·ω4·u4⊥ = ξ·η̇·n⊥ − v_A.
  const LoopSolve ls{l3_, l4_, cross(m.u3, m.u4), m.u3.perp(), m.u4.perp()};
  ls.solve(xi_ * eta_rate * n.perp() - l2_ * crank.speed_rad_s * u2.perp(), m.omega3_rad_s, m.omega4_rad_s);
  return m;
}

FollowingMotion ClearanceModel::following(const CrankState& crank, double eta, double eta_rate,
                                          const WallFriction& friction) const {
  FollowingMotion f;
  const Vec2 u2 = unit(crank.angle_rad);
  const Vec2 n = unit(eta);
  f.links = following_links(crank, u2, n, eta_rate);
  const LinkMotion& m = f.links;
  f.normal = n;
  const LoopSolve ls{l3_, l4_, cross(m.u3, m.u4), m.u3.perp(), m.u4.perp()};
  // Rates are affine in η̇ and accelerations affine in η̈:
  //   (ω3, ω4) = G·η̇ + h,   (α3, α4) = G·η̈ + k.
  double G3, G4;
  ls.solve(xi_ * n.perp(), G3, G4);
  const double w2 = crank.speed_rad_s, w3 = m.omega3_rad_s, w4 = m.omega4_rad_s;
  const Vec2 a_A = l2_ * (crank.accel_rad_s2 * u2.perp() - w2 * w2 * u2);
  // Acceleration loop: l3·α3·u3⊥ − l4·α4·u4⊥ = ξ·η̈·n⊥ + r2.
  const Vec2 r2 = -xi_ * eta_rate * eta_rate * n - l4_ * w4 * w4 * m.u4 - a_A + l3_ * w3 * w3 * m.u3;
  double k3, k4;
  ls.solve(r2, k3, k4);
  // Applied generalised forces (gravity, crank-driven inertia), thesis 3.3-2/3.3-4.
  double fa3, fa4;
  free_accelerations(crank, u2, m, fa3, fa4);
  const double f3 = I3_ * fa3, f4 = I4_ * fa4;
  // Generalised force of a unit normal force: c = (−l3·u3⊥·n, l4·u4⊥·n) (pin force −N·n).
  const double c3 = -l3_ * dot(m.u3.perp(), n), c4 = l4_ * dot(m.u4.perp(), n);
  f.slip_speed_m_s = xi_ * (eta_rate - w4);
  if (friction.mu > 0) {
    following_with_friction(friction, m, n, G3, G4, k3, k4, f3, f4, c3, c4, f);
    f.crank_torque_Nm = crank_torque_Nm(crank, u2, m, f.alpha3_rad_s2, f.pin_force());
    return f;
  }
  // Lagrange on the manifold: Gᵀ·(M·(G·η̈ + k) − f) = 0 (the normal force does no virtual work).
  f.eta_accel_rad_s2 = (G3 * (f3 - I3_ * k3) + G4 * (f4 - I4_ * k4)) / (I3_ * G3 * G3 + I4_ * G4 * G4);
  f.alpha3_rad_s2 = G3 * f.eta_accel_rad_s2 + k3;
  f.alpha4_rad_s2 = G4 * f.eta_accel_rad_s2 + k4;
  // Constraint forces Q = M·α − f = N·c.
  const double q3 = I3_ * f.alpha3_rad_s2 - f3, q4 = I4_ * f.alpha4_rad_s2 - f4;
  f.normal_force_N = (q3 * c3 + q4 * c4) / (c3 * c3 + c4 * c4);
  f.crank_torque_Nm = crank_torque_Nm(crank, u2, m, f.alpha3_rad_s2, -f.normal_force_N * n);
  return f;
}

void ClearanceModel::following_with_friction(const WallFriction& fr, const LinkMotion& m, Vec2 n, double G3,
                                             double G4, double k3, double k4, double f3, double f4, double c3,
                                             double c4, FollowingMotion& f) const {
  // Generalised force of a unit tangential force on the pin along t (−t on
  // the rocker at B, arm (B − O4) = l4·u4 + ξ·n): d = (l3·u3⊥·t, −(l4·u4⊥·t + ξ)).
  const Vec2 t = n.perp();
  const double d3 = l3_ * dot(m.u3.perp(), t), d4 = -(l4_ * dot(m.u4.perp(), t) + xi_);
  // Link equations M·(G·η̈ + k) − f_applied = N·c + f_t·d, with r = M·k − f_applied.
  const double r3 = I3_ * k3 - f3, r4 = I4_ * k4 - f4;
  if (fr.slip != 0) {
    // Sliding: f_t = −s·N with s = slip·μ; unknowns η̈ and N (Cramer).
    const double s = fr.slip * fr.mu;
    const double e3 = c3 - s * d3, e4 = c4 - s * d4;
    const double det = e3 * I4_ * G4 - I3_ * G3 * e4;
    const double det0 = c3 * I4_ * G4 - I3_ * G3 * c4;  // the frictionless one
    if (!(det / det0 > 1e-3))
      throw RunError("following-mode friction: mu = " + std::to_string(fr.mu) +
                     " makes the sliding pin's equations singular (Painleve's paradox); lower "
                     "[clearance] friction_coefficient or set following_friction = false");
    f.eta_accel_rad_s2 = (r3 * e4 - e3 * r4) / det;
    f.normal_force_N = (r3 * I4_ * G4 - I3_ * G3 * r4) / det;
    f.tangential_force_N = -s * f.normal_force_N;
  } else {
    // Stuck: d/dt(η̇ − ω4) = 0 gives η̈ = α4 = G4·η̈ + k4; then (N, f_t) from c, d.
    f.eta_accel_rad_s2 = k4 / (1.0 - G4);
    const double q3 = I3_ * (G3 * f.eta_accel_rad_s2) + r3, q4 = I4_ * (G4 * f.eta_accel_rad_s2) + r4;
    const double det = c3 * d4 - c4 * d3;
    f.normal_force_N = (q3 * d4 - q4 * d3) / det;
    f.tangential_force_N = (c3 * q4 - c4 * q3) / det;
  }
  f.alpha3_rad_s2 = G3 * f.eta_accel_rad_s2 + k3;
  f.alpha4_rad_s2 = G4 * f.eta_accel_rad_s2 + k4;
}

double ClearanceModel::kinetic_energy_J(const CrankState& crank, const LinkMotion& m) const {
  NominalMotion nm;
  nm.crank = crank;
  nm.pose = {unit(crank.angle_rad), m.u3, m.u4};
  nm.omega3_rad_s = m.omega3_rad_s;
  nm.omega4_rad_s = m.omega4_rad_s;
  return fourbar::kinetic_energy_J(rig_, nm);
}

double ClearanceModel::potential_energy_J(const CrankState& crank, const LinkMotion& m) const {
  return fourbar::potential_energy_J(rig_, Pose{unit(crank.angle_rad), m.u3, m.u4});
}

double ClearanceModel::force_scale_N(double w2) const {
  const double g = rig_.gravity_m_s2;
  return rig_.coupler.mass_kg * (g + l2_ * w2 * w2) + rig_.rocker.mass_kg * g + 1e-300;
}

double ClearanceModel::energy_scale_J(double w2) const {
  // Crank and coupler-end motion at ω2 plus the potential energy range.
  const double m3 = rig_.coupler.mass_kg;
  return 0.5 * (I2_ + m3 * l2_ * l2_) * w2 * w2 +
         rig_.gravity_m_s2 * (rig_.crank.mass_kg * rig_.crank.mass_centre_m +
                              m3 * (l2_ + rig_.coupler.mass_centre_m) + rig_.rocker.mass_kg * rig_.rocker.mass_centre_m);
}

}  // namespace fourbar
