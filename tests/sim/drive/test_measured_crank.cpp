// The measured crank motion: a constant table is the constant speed; θ2' = ω2
// and ω2' = α2 everywhere (also across knots and outside the table); angles
// invert; bad tables are refused; the clearance model's energy balance
// closes with a varying crank speed, its crank work counted.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/error.hpp"
#include "common/units.hpp"
#include "sim/drive/measured_crank.hpp"
#include "sim/three_mode/simulator.hpp"

namespace fourbar {
namespace {

/// A speed table fluctuating around `rpm` (two harmonics per turn plus a slow drift).
MeasuredSpeedCrank fluctuating_crank(double rpm, double amplitude, int turns, int per_turn) {
  const double w0 = units::rpm_to_rad_s(rpm), period = units::kTwoPi / std::abs(w0);
  std::vector<double> t, w;
  for (int i = -2; i <= turns * per_turn + 2; ++i) {
    const double x = static_cast<double>(i) / per_turn;
    t.push_back(x * period);
    w.push_back(w0 * (1 + amplitude * (std::sin(units::kTwoPi * x) + 0.5 * std::cos(2 * units::kTwoPi * x + 0.3)) +
                      0.01 * x));
  }
  return MeasuredSpeedCrank(0.3, t, w);
}

TEST(MeasuredSpeedCrank, ConstantTableIsConstantSpeed) {
  for (double w : {36.65, -20.0}) {
    const MeasuredSpeedCrank m(0.4, {-1.0, 0.0, 0.25, 0.6, 2.0}, {w, w, w, w, w});
    const ConstantSpeedCrank c(0.4, w);
    for (double t : {-3.0, -0.5, 0.0, 0.1, 0.3, 0.59, 1.7, 2.5}) {
      const CrankState a = m.at(t), b = c.at(t);
      EXPECT_NEAR(a.angle_rad, b.angle_rad, 1e-13 * (1 + std::abs(b.angle_rad))) << t;
      EXPECT_NEAR(a.speed_rad_s, b.speed_rad_s, 1e-13 * std::abs(w)) << t;
      EXPECT_NEAR(a.accel_rad_s2, 0.0, 1e-12 * std::abs(w)) << t;
      EXPECT_NEAR(m.time_at_angle(b.angle_rad), t, 1e-13 * (1 + std::abs(t))) << t;
    }
  }
  const MeasuredSpeedCrank r = MeasuredSpeedCrank::from_revolution_speeds(0.0, {30.0, 30.0, 30.0});
  EXPECT_NEAR(r.time_at_angle(3 * units::kTwoPi), 3 * units::kTwoPi / 30.0, 1e-13);
}

TEST(MeasuredSpeedCrank, DerivativesAreConsistent) {
  const MeasuredSpeedCrank m = fluctuating_crank(300, 0.05, 3, 7);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> time(-0.1, 0.8);
  const double h = 1e-5;
  for (int i = 0; i < 400; ++i) {
    const double t = time(rng);
    const CrankState c = m.at(t);
    // 4th-order central differences of θ2 and ω2.
    auto d = [&](auto get) {
      return (get(m.at(t - 2 * h)) - 8 * get(m.at(t - h)) + 8 * get(m.at(t + h)) - get(m.at(t + 2 * h))) / (12 * h);
    };
    const double w_fd = d([](const CrankState& s) { return s.angle_rad; });
    const double a_fd = d([](const CrankState& s) { return s.speed_rad_s; });
    EXPECT_NEAR(w_fd, c.speed_rad_s, 1e-7 * std::abs(c.speed_rad_s)) << t;
    // ω2 is C¹ only: away from the knots (every period/7) the difference is exact.
    const double period = units::kTwoPi / units::rpm_to_rad_s(300), x = t / (period / 7);
    if (std::abs(x - std::round(x)) * period / 7 > 3 * h) EXPECT_NEAR(a_fd, c.accel_rad_s2, 1e-4) << t;
    EXPECT_NEAR(m.time_at_angle(c.angle_rad), t, 1e-12) << t;
  }
  // Speeds stay between neighbouring samples (no overshoot): the crank keeps turning.
  for (double t = -0.1; t < 0.8; t += 1e-3) EXPECT_GT(m.at(t).speed_rad_s, 0.8 * units::rpm_to_rad_s(300));
}

TEST(MeasuredSpeedCrank, RevolutionSpeedsGiveTheirPeriods) {
  // A speed rising linearly in time, ω = w0 + b·t: revolution k ends at the
  // root of w0·t + b·t²/2 = 2πk, and its mean speed equals the speed at its
  // middle time, where from_revolution_speeds puts it; PCHIP reproduces
  // linear data, so the interior revolutions are reproduced exactly.
  const double w0 = 30.0, b = 4.0;
  auto t_of = [&](double angle) { return (-w0 + std::sqrt(w0 * w0 + 2 * b * angle)) / b; };
  std::vector<double> w;
  for (int k = 0; k < 12; ++k) w.push_back(units::kTwoPi / (t_of(units::kTwoPi * (k + 1)) - t_of(units::kTwoPi * k)));
  const MeasuredSpeedCrank m = MeasuredSpeedCrank::from_revolution_speeds(0.0, w);
  for (int k = 2; k <= 9; ++k) {
    const double a = units::kTwoPi * k;
    // Over each true revolution the interpolant turns by exactly 2π (its
    // angle origin is off by the flat start, before the first middle time).
    EXPECT_NEAR(m.at(t_of(a + units::kTwoPi)).angle_rad - m.at(t_of(a)).angle_rad, units::kTwoPi, 1e-11) << k;
    const double tm = 0.5 * (t_of(a) + t_of(a + units::kTwoPi));
    EXPECT_NEAR(m.at(tm).speed_rad_s, w0 + b * tm, 1e-11) << k;
    EXPECT_NEAR(m.at(tm).accel_rad_s2, b, 1e-9) << k;
  }
}

TEST(MeasuredSpeedCrank, BadTablesAreRefused) {
  EXPECT_THROW(MeasuredSpeedCrank(0, {0, 1, 1, 2}, {3, 3, 3, 3}), InputError);        // repeated time
  EXPECT_THROW(MeasuredSpeedCrank(0, {0, 1, 2, 3}, {3, 3, -3, 3}), InputError);       // reverses
  EXPECT_THROW(MeasuredSpeedCrank(0, {0, 1, 2, 3}, {3, 0, 3, 3}), InputError);        // stops
  EXPECT_THROW(MeasuredSpeedCrank(0, {0, 1, 2}, {3, 3, 3, 3}), InputError);           // sizes
  EXPECT_THROW(MeasuredSpeedCrank(0, {0, NAN, 2, 3}, {3, 3, 3, 3}), InputError);      // NaN
  EXPECT_THROW(MeasuredSpeedCrank(0, {0}, {3}), InputError);                          // one sample
  EXPECT_NO_THROW(MeasuredSpeedCrank(0, {0, 1}, {3, 4}));                             // two: densified
}

TEST(MeasuredSpeedCrank, ClearanceEnergyBalanceWithVaryingSpeed) {
  // ±7 % speed fluctuation: the crank's own kinetic energy swings, the motor
  // torque carries α2; the books must still close to 1e-8 of the energy scale.
  // α2 is only continuous at the knots (PCHIP is C¹), which the integrators'
  // error estimates see poorly: at tolerance 1e-10 the residual is ~1e-8
  // (measured 8.6e-9 Odeint, 1.2e-8 CVODE), at 1e-11 ~1e-9, so this runs at 1e-11.
  const Rig rig = thesis_rig();
  const ClearanceModel model(rig, 0.254e-3);
  const MeasuredSpeedCrank crank = fluctuating_crank(350, 0.07, 6, 24);
  for (IntegratorKind k : {IntegratorKind::odeint, IntegratorKind::cvode}) {
    ClearanceSettings s;
    s.restitution = 0.5;
    s.integrator = k;
    s.tolerance = 1e-11;
    ClearanceSimulator sim(model, crank, s);
    sim.start_nominal(0.0);
    const double t_end = crank.time_at_angle(0.3 + 5 * units::kTwoPi);
    sim.advance_to(t_end);
    const ClearanceDiagnostics d = sim.diagnostics();
    SCOPED_TRACE(to_string(k));
    EXPECT_GT(d.impacts, 20u);
    EXPECT_LT(std::abs(d.energy_residual_J), 1e-8 * d.energy_scale_J);
    EXPECT_LT(d.max_energy_residual_J, 1e-8 * d.energy_scale_J);
    // The crank's kinetic energy changes by far more than the residual: the
    // α2 terms of the crank work are really counted.
    const double I2 = rig.crank.inertia_about_joint();
    const double w_a = crank.at(0).speed_rad_s, w_b = crank.at(t_end).speed_rad_s;
    EXPECT_GT(std::abs(0.5 * I2 * (w_b * w_b - w_a * w_a)), 1e4 * std::abs(d.energy_residual_J));
    EXPECT_GT(std::abs(d.crank_work_J), 1e-3);
    EXPECT_LT(d.max_penetration, 1e-9);
  }
}

}  // namespace
}  // namespace fourbar
