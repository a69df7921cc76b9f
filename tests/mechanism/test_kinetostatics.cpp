// Nominal kinetostatics: Newton–Euler (closed form) against the Lagrange
// multiplier system, and both against energy: τ·ω2 = d(T + V)/dt.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"

namespace fourbar {
namespace {

double rel(double a, double b, double scale) { return std::abs(a - b) / scale; }

TEST(NominalKinetostatics, NewtonEulerAgreesWithLagrangeMultipliers) {
  const Rig rig = thesis_rig();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> angle(0, units::kTwoPi), speed(-80.0, 80.0), accel(-500.0, 500.0);
  double worst_torque = 0, worst_force = 0, worst_alpha = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const NominalMotion m = solve_motion(rig, {angle(rng), speed(rng), accel(rng)});
    const JointLoads ne = solve_loads(rig, m);
    const LagrangeSolution lg = solve_loads_lagrange(rig, m);
    const double f_scale = std::max(1.0, ne.bearing_N.norm());
    const double t_scale = std::max(1e-3, std::abs(ne.crank_torque_Nm));
    worst_torque = std::max(worst_torque, rel(ne.crank_torque_Nm, lg.crank_torque_Nm, t_scale));
    worst_force = std::max(worst_force, (ne.bearing_N - lg.bearing_N).norm() / f_scale);
    const double a_scale = std::max(1.0, std::abs(m.alpha3_rad_s2) + std::abs(m.alpha4_rad_s2));
    worst_alpha = std::max({worst_alpha, rel(m.alpha3_rad_s2, lg.alpha3_rad_s2, a_scale),
                            rel(m.alpha4_rad_s2, lg.alpha4_rad_s2, a_scale)});
  }
  EXPECT_LT(worst_torque, 1e-10);
  EXPECT_LT(worst_force, 1e-10);
  EXPECT_LT(worst_alpha, 1e-10);
}

// Power balance from the link motions: τ·ω2 = Σ (m·v_G·a_G + I_G·ω·α + m·g·v_Gy).
TEST(NominalKinetostatics, PowerBalanceFromLinkMotions) {
  const Rig rig = thesis_rig();
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> angle(0, units::kTwoPi), speed(5.0, 80.0), accel(-300.0, 300.0);
  const double g = rig.gravity_m_s2;
  for (int trial = 0; trial < 500; ++trial) {
    const NominalMotion m = solve_motion(rig, {angle(rng), speed(rng), accel(rng)});
    const JointLoads loads = solve_loads(rig, m);
    const Vec2 u2 = m.pose.u2, u3 = m.pose.u3, u4 = m.pose.u4;
    const double w2 = m.crank.speed_rad_s, a2 = m.crank.accel_rad_s2;
    const double w3 = m.omega3_rad_s, a3 = m.alpha3_rad_s2, w4 = m.omega4_rad_s, a4 = m.alpha4_rad_s2;
    auto pt = [](double r, Vec2 u, double w, double a) {
      return std::pair{r * w * u.perp(), r * (a * u.perp() - w * w * u)};
    };
    const auto [v2, acc2] = pt(rig.crank.mass_centre_m, u2, w2, a2);
    const auto [vA, accA] = pt(rig.crank.length_m, u2, w2, a2);
    const auto [v3r, acc3r] = pt(rig.coupler.mass_centre_m, u3, w3, a3);
    const auto [v4, acc4] = pt(rig.rocker.mass_centre_m, u4, w4, a4);
    const Vec2 v3 = vA + v3r, acc3 = accA + acc3r;
    const double power = rig.crank.mass_kg * (dot(v2, acc2) + g * v2.y) + rig.crank.inertia_cg_kg_m2 * w2 * a2 +
                         rig.coupler.mass_kg * (dot(v3, acc3) + g * v3.y) + rig.coupler.inertia_cg_kg_m2 * w3 * a3 +
                         rig.rocker.mass_kg * (dot(v4, acc4) + g * v4.y) + rig.rocker.inertia_cg_kg_m2 * w4 * a4;
    const double scale = std::max(std::abs(power), 1e-3 * w2 * w2 * w2);
    EXPECT_LT(std::abs(loads.crank_torque_Nm * w2 - power) / scale, 1e-12) << "trial " << trial;
  }
}

// Power balance against a finite difference of the energy along one turn at
// constant speed: τ·ω2 = ω2·d(T + V)/dθ2, sixth-order central differences.
TEST(NominalKinetostatics, PowerBalanceMatchesEnergyDerivative) {
  const Rig rig = thesis_rig();
  const double w2 = units::rpm_to_rad_s(350.0);
  auto energy = [&](double t2) {
    const NominalMotion m = solve_motion(rig, {t2, w2, 0.0});
    return kinetic_energy_J(rig, m) + potential_energy_J(rig, m.pose);
  };
  const double h = 1e-3;  // rad of crank angle
  double peak = 0;
  std::vector<double> power(3600), fd(3600);
  for (int i = 0; i < 3600; ++i) {
    const double t2 = units::deg_to_rad(0.1 * i);
    const NominalMotion m = solve_motion(rig, {t2, w2, 0.0});
    power[i] = solve_loads(rig, m).crank_torque_Nm * w2;
    const double dE = (45 * (energy(t2 + h) - energy(t2 - h)) - 9 * (energy(t2 + 2 * h) - energy(t2 - 2 * h)) +
                       (energy(t2 + 3 * h) - energy(t2 - 3 * h))) /
                      (60 * h);
    fd[i] = w2 * dE;
    peak = std::max(peak, std::abs(power[i]));
  }
  double worst = 0;
  for (int i = 0; i < 3600; ++i) worst = std::max(worst, std::abs(power[i] - fd[i]) / peak);
  EXPECT_LT(worst, 1e-9);
}

// Standing still, the torque is the gravity moment: τ = dV/dθ2.
TEST(NominalKinetostatics, StaticTorqueIsPotentialGradient) {
  const Rig rig = thesis_rig();
  const double h = 1e-4;
  for (int i = 0; i < 360; i += 5) {
    const double t2 = units::deg_to_rad(i + 0.25);
    const JointLoads loads = solve_loads(rig, solve_motion(rig, {t2, 0.0, 0.0}));
    const double dV = (potential_energy_J(rig, solve_pose(rig, t2 - 2 * h)) -
                       potential_energy_J(rig, solve_pose(rig, t2 + 2 * h)) +
                       8 * (potential_energy_J(rig, solve_pose(rig, t2 + h)) -
                            potential_energy_J(rig, solve_pose(rig, t2 - h)))) /
                      (12 * h);
    EXPECT_NEAR(loads.crank_torque_Nm, dV, 1e-10) << "crank " << i + 0.25 << " deg";
  }
}

// Without gravity and at rest nothing is loaded; the whole mechanism's force
// balance holds: F_O2 + F_O4 + Σ m·g = Σ m·a_G.
TEST(NominalKinetostatics, WholeMechanismForceBalance) {
  Rig rig = thesis_rig();
  const NominalMotion m = solve_motion(rig, {1.0, 30.0, 10.0});
  const JointLoads l = solve_loads(rig, m);
  const double g = rig.gravity_m_s2;
  const Vec2 aG2 = rig.crank.mass_centre_m * (m.crank.accel_rad_s2 * m.pose.u2.perp() -
                                              m.crank.speed_rad_s * m.crank.speed_rad_s * m.pose.u2);
  const Vec2 aA = rig.crank.length_m / rig.crank.mass_centre_m * aG2;
  const Vec2 aG3 = aA + rig.coupler.mass_centre_m * (m.alpha3_rad_s2 * m.pose.u3.perp() -
                                                     m.omega3_rad_s * m.omega3_rad_s * m.pose.u3);
  const Vec2 aG4 = rig.rocker.mass_centre_m * (m.alpha4_rad_s2 * m.pose.u4.perp() -
                                               m.omega4_rad_s * m.omega4_rad_s * m.pose.u4);
  const double mt = rig.crank.mass_kg + rig.coupler.mass_kg + rig.rocker.mass_kg;
  const Vec2 lhs = l.crank_pivot_N + l.rocker_pivot_N + Vec2{0, -mt * g};
  const Vec2 rhs = rig.crank.mass_kg * aG2 + rig.coupler.mass_kg * aG3 + rig.rocker.mass_kg * aG4;
  EXPECT_NEAR(lhs.x, rhs.x, 1e-11);
  EXPECT_NEAR(lhs.y, rhs.y, 1e-11);

  rig.gravity_m_s2 = 0;
  const JointLoads rest = solve_loads(rig, solve_motion(rig, {1.0, 0.0, 0.0}));
  EXPECT_EQ(rest.crank_torque_Nm, 0.0);
  EXPECT_EQ(rest.bearing_N.norm(), 0.0);
}

}  // namespace
}  // namespace fourbar
