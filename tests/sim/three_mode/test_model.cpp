// Following-mode mechanics in the minimal coordinate η against two other
// formulations at random states: the thesis's corrected 6×6 system
// (eq. 3.3-7/3.3-8) and the unified constrained form M·q̈ = f + Jᵀλ on
// q = (θ3, θ4) with φ = ½(|e|² − ξ²) = 0.

#include <gtest/gtest.h>

#include <array>
#include <random>

#include <Eigen/Dense>

#include "sim/three_mode/model.hpp"
#include "sim/three_mode/thesis_reference.hpp"

namespace fourbar {
namespace {

struct RandomState {
  CrankState crank;
  double eta, eta_rate;
};

RandomState random_state(std::mt19937& rng, double alpha2_max = 0.0) {
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), speed(-60, 60), rate(-400, 400), acc(-1, 1);
  return {{angle(rng), speed(rng), alpha2_max * acc(rng)}, angle(rng), rate(rng)};
}

double rel(double a, double b, double scale) { return std::abs(a - b) / scale; }

/// Link motion a time dt later along the trajectory with the model's η̈ (and the crank's α2).
LinkMotion along(const ClearanceModel& model, const RandomState& s, const FollowingMotion& f, double dt,
                 CrankState* crank_out = nullptr) {
  CrankState c = s.crank;
  c.angle_rad += c.speed_rad_s * dt + 0.5 * c.accel_rad_s2 * dt * dt;
  c.speed_rad_s += c.accel_rad_s2 * dt;
  if (crank_out) *crank_out = c;
  const double eta = s.eta + s.eta_rate * dt + 0.5 * f.eta_accel_rad_s2 * dt * dt;
  return model.following_links(c, eta, s.eta_rate + f.eta_accel_rad_s2 * dt);
}

TEST(ClearanceModel, FollowingPoseLiesOnTheContactCircle) {
  const Rig rig = thesis_rig();
  const ClearanceModel model(rig, 0.254e-3);
  std::mt19937 rng(11);
  for (int i = 0; i < 2000; ++i) {
    const RandomState s = random_state(rng);
    const LinkMotion m = model.following_links(s.crank, s.eta, s.eta_rate);
    const BearingState b = model.bearing(s.crank, m);
    EXPECT_LT(std::abs(b.gap_m), 1e-12 * 0.254e-3 * 1e3) << i;  // |e| = ξ to round-off
    EXPECT_NEAR(std::atan2(b.normal.y, b.normal.x), std::remainder(s.eta, 2 * M_PI), 1e-9);
    EXPECT_LT(std::abs(b.normal_speed_m_s), 1e-12);  // no normal relative velocity
    // The rocker's contact point and the bushing centre differ by ξ·ω4 tangentially only.
    EXPECT_NEAR(b.tangential_speed_m_s, 0.254e-3 * (s.eta_rate - m.omega4_rad_s), 1e-12);
  }
}

TEST(ClearanceModel, FollowingRatesAreDerivativesOfPositions) {
  const Rig rig = thesis_rig();
  const ClearanceModel model(rig, 0.254e-3);
  std::mt19937 rng(12);
  for (int i = 0; i < 200; ++i) {
    const RandomState s = random_state(rng, 50.0);
    const FollowingMotion f = model.following(s.crank, s.eta, s.eta_rate);
    // Move along a trajectory with η̈ from the model; difference the link angles.
    const double h = 1e-5;
    auto at = [&](double dt) { return along(model, s, f, dt); };
    const LinkMotion p = at(h), m = at(-h), p2 = at(2 * h), m2 = at(-2 * h);
    auto ang = [&](Vec2 a, Vec2 b) { return std::atan2(cross(a, b), dot(a, b)); };
    const double w3 = (8 * ang(m.u3, p.u3) - ang(m2.u3, p2.u3)) / (12 * h);
    const double w4 = (8 * ang(m.u4, p.u4) - ang(m2.u4, p2.u4)) / (12 * h);
    EXPECT_LT(rel(w3, f.links.omega3_rad_s, 1 + std::abs(f.links.omega3_rad_s)), 1e-6) << i;
    EXPECT_LT(rel(w4, f.links.omega4_rad_s, 1 + std::abs(f.links.omega4_rad_s)), 1e-6) << i;
    const double a3 = (8 * (p.omega3_rad_s - m.omega3_rad_s) - (p2.omega3_rad_s - m2.omega3_rad_s)) / (12 * h);
    const double a4 = (8 * (p.omega4_rad_s - m.omega4_rad_s) - (p2.omega4_rad_s - m2.omega4_rad_s)) / (12 * h);
    EXPECT_LT(rel(a3, f.alpha3_rad_s2, 1 + std::abs(f.alpha3_rad_s2)), 1e-5) << i;
    EXPECT_LT(rel(a4, f.alpha4_rad_s2, 1 + std::abs(f.alpha4_rad_s2)), 1e-5) << i;
  }
}

TEST(ClearanceModel, AgreesWithThesisSixBySixSystem) {
  const Rig rig = thesis_rig();
  const double xi = 0.254e-3;
  const ClearanceModel model(rig, xi);
  std::mt19937 rng(13);
  for (int i = 0; i < 2000; ++i) {
    const RandomState s = random_state(rng);  // α2 = 0 as in the thesis
    const FollowingMotion f = model.following(s.crank, s.eta, s.eta_rate);
    const double t3 = std::atan2(f.links.u3.y, f.links.u3.x), t4 = std::atan2(f.links.u4.y, f.links.u4.x);
    // The clearance link points from the pin to the bushing centre: θc = η + π.
    const ThesisFollowingSolution x = thesis_following_system(
        rig, xi, s.crank.angle_rad, s.crank.speed_rad_s, t3, t4, s.eta + M_PI, f.links.omega3_rad_s,
        f.links.omega4_rad_s, s.eta_rate);
    const Vec2 pin = -f.normal_force_N * f.normal;
    const double fs = 1 + std::abs(f.normal_force_N);
    EXPECT_LT(rel(x.alpha3_rad_s2, f.alpha3_rad_s2, 1 + std::abs(f.alpha3_rad_s2)), 1e-9) << i;
    EXPECT_LT(rel(x.alpha4_rad_s2, f.alpha4_rad_s2, 1 + std::abs(f.alpha4_rad_s2)), 1e-9) << i;
    EXPECT_LT(rel(x.alpha_c_rad_s2, f.eta_accel_rad_s2, 1 + std::abs(f.eta_accel_rad_s2)), 1e-9) << i;
    EXPECT_LT(rel(x.force_x_N, pin.x, fs), 1e-9) << i;
    EXPECT_LT(rel(x.force_y_N, pin.y, fs), 1e-9) << i;
    EXPECT_LT(rel(x.crank_torque_Nm, f.crank_torque_Nm, 1 + std::abs(f.crank_torque_Nm)), 1e-9) << i;
  }
}

/// Generalised forces of a pin force P (−P on the rocker at B), from the
/// eccentricity vector, independent of the model's own formulas.
std::array<double, 2> generalised(const Rig& rig, const LinkMotion& m, Vec2 e, Vec2 P) {
  return {dot(P, rig.coupler.length_m * m.u3.perp()), -dot(P, (rig.rocker.length_m * m.u4 + e).perp())};
}

/// (α3, α4, λ) of the unified form M·q̈ = f + Jᵀλ + f_t·D, J·q̈ = −γ on
/// q = (θ3, θ4) with φ = ½(|e|² − ξ²), solved as a dense 3×3 system, at the
/// link motion the model found. The pin force is λ·e + f_t·t, so N = −λ·ξ;
/// Coulomb sliding f_t = −σ·μ·N = σ·μ·ξ·λ enters the λ column (μ = 0: none).
Eigen::Vector3d unified_solution(const ClearanceModel& model, const CrankState& crank, const LinkMotion& m,
                                 double sigma_mu) {
  const Rig& rig = model.rig();
  const double l2 = rig.crank.length_m, l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  const Vec2 u2 = unit(crank.angle_rad);
  const Vec2 e = model.bearing(crank, m).eccentricity_m;
  const Vec2 t = (e * (1.0 / std::sqrt(dot(e, e)))).perp();
  const double w2 = crank.speed_rad_s, a2 = crank.accel_rad_s2, w3 = m.omega3_rad_s, w4 = m.omega4_rad_s;
  const Vec2 e_dot = l2 * w2 * u2.perp() + l3 * w3 * m.u3.perp() - l4 * w4 * m.u4.perp();
  const Vec2 e_known = l2 * (a2 * u2.perp() - w2 * w2 * u2) - l3 * w3 * w3 * m.u3 + l4 * w4 * w4 * m.u4;
  double fa3, fa4;
  model.free_accelerations(crank, m, fa3, fa4);
  const double I3 = model.inertia_coupler_about_A(), I4 = model.inertia_rocker_about_O4();
  const double J3 = dot(e, l3 * m.u3.perp()), J4 = -dot(e, l4 * m.u4.perp());
  const auto D = generalised(rig, m, e, t);
  const double k = sigma_mu * model.clearance_m();
  Eigen::Matrix3d A;
  A << I3, 0, -(J3 + k * D[0]), 0, I4, -(J4 + k * D[1]), J3, J4, 0;
  const Eigen::Vector3d b(I3 * fa3, I4 * fa4, -(dot(e_dot, e_dot) + dot(e, e_known)));
  return A.fullPivLu().solve(b);
}

TEST(ClearanceModel, AgreesWithUnifiedConstrainedForm) {
  const Rig rig = thesis_rig();
  const double xi = 0.1e-3;
  const ClearanceModel model(rig, xi);
  std::mt19937 rng(14);
  for (int i = 0; i < 2000; ++i) {
    const RandomState s = random_state(rng, 80.0);
    const FollowingMotion f = model.following(s.crank, s.eta, s.eta_rate);
    const Eigen::Vector3d x = unified_solution(model, s.crank, f.links, 0.0);
    EXPECT_LT(rel(x(0), f.alpha3_rad_s2, 1 + std::abs(f.alpha3_rad_s2)), 1e-9) << i;
    EXPECT_LT(rel(x(1), f.alpha4_rad_s2, 1 + std::abs(f.alpha4_rad_s2)), 1e-9) << i;
    // λ·e is the force on the pin: −N·n = λ·e, so N = −λ·ξ.
    EXPECT_LT(rel(-x(2) * xi, f.normal_force_N, 1 + std::abs(f.normal_force_N)), 1e-9) << i;
  }
}

TEST(ClearanceModel, CrankTorqueBalancesPowerInFollowingMode) {
  // d(T+V)/dt = τ·ω2 + f_t·v_t, checked by differences: without friction the
  // bearing force does no work; with sliding friction (μ = 0.25) it
  // dissipates (f_t·v_t ≤ 0).
  const Rig rig = thesis_rig();
  const ClearanceModel model(rig, 0.254e-3);
  std::mt19937 rng(15);
  for (double mu : {0.0, 0.25}) {
    for (int i = 0; i < 100; ++i) {
      const RandomState s = random_state(rng, 40.0);
      const double v_t = model.following(s.crank, s.eta, s.eta_rate).slip_speed_m_s;
      const FollowingMotion f = model.following(s.crank, s.eta, s.eta_rate, {mu, v_t > 0 ? 1 : -1});
      if (f.normal_force_N > 0) EXPECT_LE(f.tangential_force_N * f.slip_speed_m_s, 0.0) << i;
      auto energy = [&](double dt) {
        CrankState c;
        const LinkMotion m = along(model, s, f, dt, &c);
        return model.kinetic_energy_J(c, m) + model.potential_energy_J(c, m);
      };
      const double h = 1e-6;
      const double power = (8 * (energy(h) - energy(-h)) - (energy(2 * h) - energy(-2 * h))) / (12 * h);
      const double expected = f.crank_torque_Nm * s.crank.speed_rad_s + f.tangential_force_N * f.slip_speed_m_s;
      const double scale = 1 + std::abs(f.crank_torque_Nm * s.crank.speed_rad_s);
      EXPECT_LT(std::abs(power - expected) / scale, 1e-6) << "mu " << mu << " " << i;
    }
  }
}

TEST(ClearanceModel, SlidingFrictionAgreesWithUnifiedForm) {
  const Rig rig = thesis_rig();
  const double xi = 0.1e-3;
  const ClearanceModel model(rig, xi);
  std::mt19937 rng(24);
  std::uniform_int_distribution<int> coin(0, 1);
  for (int i = 0; i < 2000; ++i) {
    const RandomState s = random_state(rng, 80.0);
    const int sigma = coin(rng) ? 1 : -1;
    const double mu = 0.3;
    const FollowingMotion f = model.following(s.crank, s.eta, s.eta_rate, {mu, sigma});
    const Eigen::Vector3d x = unified_solution(model, s.crank, f.links, sigma * mu);
    EXPECT_LT(rel(x(0), f.alpha3_rad_s2, 1 + std::abs(f.alpha3_rad_s2)), 1e-9) << i;
    EXPECT_LT(rel(x(1), f.alpha4_rad_s2, 1 + std::abs(f.alpha4_rad_s2)), 1e-9) << i;
    EXPECT_LT(rel(-x(2) * xi, f.normal_force_N, 1 + std::abs(f.normal_force_N)), 1e-9) << i;
    EXPECT_NEAR(f.tangential_force_N, -sigma * mu * f.normal_force_N, 1e-12 * (1 + std::abs(f.normal_force_N)));
    EXPECT_NEAR(f.slip_speed_m_s, model.bearing(s.crank, f.links).tangential_speed_m_s, 1e-12);
  }
}

TEST(ClearanceModel, StuckPinKeepsZeroSlipAndBalancesForces) {
  const Rig rig = thesis_rig();
  const double xi = 0.254e-3;
  const ClearanceModel model(rig, xi);
  std::mt19937 rng(25);
  for (int i = 0; i < 300; ++i) {
    RandomState s = random_state(rng, 40.0);
    // The rate that makes the slip zero: η̇ = ω4, ω4 affine in η̇.
    const double h4 = model.following_links(s.crank, s.eta, 0.0).omega4_rad_s;
    const double G4 = model.following_links(s.crank, s.eta, 1.0).omega4_rad_s - h4;
    s.eta_rate = h4 / (1 - G4);
    const FollowingMotion f = model.following(s.crank, s.eta, s.eta_rate, {0.3, 0});
    EXPECT_LT(std::abs(f.slip_speed_m_s), 1e-15) << i;
    // Slip stays zero along the trajectory (its rate by central differences).
    const double h = 1e-6;
    auto slip = [&](double dt) {
      CrankState c;
      const LinkMotion m = along(model, s, f, dt, &c);
      return model.bearing(c, m).tangential_speed_m_s;
    };
    const double slip_rate = (8 * (slip(h) - slip(-h)) - (slip(2 * h) - slip(-2 * h))) / (12 * h);
    EXPECT_LT(std::abs(slip_rate), 1e-6 * (1 + std::abs(xi * f.alpha4_rad_s2))) << i;
    // M·α − f_applied = generalised force of the pin force −N·n + f_t·t.
    double fa3, fa4;
    model.free_accelerations(s.crank, f.links, fa3, fa4);
    const Vec2 e = model.bearing(s.crank, f.links).eccentricity_m;
    const auto Q = generalised(rig, f.links, e, f.pin_force());
    const double I3 = model.inertia_coupler_about_A(), I4 = model.inertia_rocker_about_O4();
    const double scale = 1e-3 + std::abs(I3 * f.alpha3_rad_s2) + std::abs(I4 * f.alpha4_rad_s2);
    EXPECT_LT(std::abs(I3 * (f.alpha3_rad_s2 - fa3) - Q[0]) / scale, 1e-10) << i;
    EXPECT_LT(std::abs(I4 * (f.alpha4_rad_s2 - fa4) - Q[1]) / scale, 1e-10) << i;
  }
}

}  // namespace
}  // namespace fourbar
