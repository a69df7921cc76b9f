// Local time (issue: long runs lost precision in absolute time and crank
// angle): the crank motions' at_local() and the simulator late in a run.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/units.hpp"
#include "sim/drive/measured_crank.hpp"
#include "sim/three_mode/simulator.hpp"
#include "support/thesis_values.hpp"

namespace fourbar {
namespace {

using testing::kXi;

/// a − b modulo 2π, in (−π, π].
double angle_difference(double a, double b) { return std::remainder(a - b, units::kTwoPi); }

TEST(LocalTime, ConstantSpeedCrankAtLocalIsAtModuloTwoPi) {
  const double w = units::rpm_to_rad_s(350);
  const ConstantSpeedCrank crank(0.3, w);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> origin(3, 2000), tau(0, 0.2);  // reduced beyond 16 turns
  for (int i = 0; i < 1000; ++i) {
    const double o = origin(rng), t = tau(rng);
    const CrankState a = crank.at(o + t), b = crank.at_local(o, t);
    // at() itself carries ~ulp(6e4 rad) = 7e-12 rad here.
    EXPECT_NEAR(angle_difference(a.angle_rad, b.angle_rad), 0.0, 3e-11);
    EXPECT_LE(std::abs(b.angle_rad), units::kTwoPi + w * t);
    EXPECT_EQ(a.speed_rad_s, b.speed_rad_s);
  }
  // Exactly on the late origin: the reduced angle of ω·t0 with 2π as double-double.
  const double t0 = 1700.0;
  EXPECT_NEAR(crank.at_local(t0, 0.0).angle_rad, 0.3 + std::remainder(w * t0, units::kTwoPi), 2e-11);
}

TEST(LocalTime, MeasuredCrankAtLocalIsAtModuloTwoPi) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.5, 0.5);
  std::vector<double> speeds;
  for (int k = 0; k < 3000; ++k) speeds.push_back(units::rpm_to_rad_s(350 + jitter(rng)));
  const auto crank = MeasuredSpeedCrank::from_revolution_speeds(0.2, speeds);
  std::uniform_real_distribution<double> origin(0, 500), tau(0, 0.2);
  for (int i = 0; i < 1000; ++i) {
    const double o = origin(rng), t = tau(rng);
    const CrankState a = crank.at(o + t), b = crank.at_local(o, t);
    EXPECT_NEAR(angle_difference(a.angle_rad, b.angle_rad), 0.0, 1e-10) << o << " " << t;
    EXPECT_NEAR(a.speed_rad_s, b.speed_rad_s, 1e-9);
    EXPECT_NEAR(a.accel_rad_s2, b.accel_rad_s2, 1e-6);
  }
}

struct Books {
  double penetration = 0, residual = 0, circle = 0;
  std::size_t impacts = 0;
};

/// `turns` turns of the thesis rig at 350 rpm (ξ = 0.254 mm, e = 0.5) from t0.
Books run_from(double t0, int turns) {
  const ClearanceModel model(thesis_rig(), kXi);
  const double w = units::rpm_to_rad_s(350), period = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  ClearanceSettings s;
  s.restitution = 0.5;
  ClearanceSimulator sim(model, crank, s);
  sim.start_nominal(t0);
  sim.advance_to(t0 + turns * period);
  const ClearanceDiagnostics d = sim.diagnostics();
  EXPECT_NEAR(sim.time(), t0 + turns * period, 1e-12 * (1 + t0));
  return {d.max_penetration, d.max_energy_residual_J / d.energy_scale_J, d.max_contact_circle_error, d.impacts};
}

TEST(LocalTime, LateStartKeepsPenetrationAndEnergyBooks) {
  // t0 = 1700 s is turn ~9900 at 350 rpm: one ulp of t0 is 2.3e-13 s and of
  // the crank angle 7e-12 rad. Before local time the same turns from there
  // reached 9.3e-10·ξ (300 turns) against 1.8e-11·ξ from t0 = 0.
  const Books early = run_from(0.0, 20), late = run_from(1700.0, 20);
  ASSERT_GT(early.impacts, 100u);
  ASSERT_GT(late.impacts, 100u);
  for (const Books& b : {early, late}) {
    EXPECT_LT(b.penetration, 1e-9);
    EXPECT_LT(b.residual, 1e-8);
    EXPECT_LT(b.circle, 1e-9);
  }
  EXPECT_LT(late.penetration, 10 * early.penetration + 1e-11);
  EXPECT_LT(late.residual, 10 * early.residual + 1e-10);
}

}  // namespace
}  // namespace fourbar
