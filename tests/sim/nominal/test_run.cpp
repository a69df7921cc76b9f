// The nominal run computes only what the scene asks for, on the right grid.

#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"
#include "sim/nominal/run.hpp"

namespace fourbar {
namespace {

Scene scene_with(std::vector<std::string> outputs) {
  Scene s;
  s.rig = std::make_shared<const Rig>(thesis_rig());
  s.crank_speed_rad_s = units::rpm_to_rad_s(350);
  s.revolutions = 2;
  s.samples_per_revolution = 100;
  s.outputs = std::move(outputs);
  return s;
}

TEST(NominalRun, ComputesOnlyWhatIsRequested) {
  NominalRunStats stats;
  SeriesTable t = run_nominal(scene_with({"time_s"}), &stats);
  EXPECT_EQ(stats.kinematics_evaluations, 0u);
  EXPECT_EQ(stats.load_evaluations, 0u);
  t = run_nominal(scene_with({"alpha3_rad_s2"}), &stats);
  EXPECT_EQ(stats.kinematics_evaluations, 201u);
  EXPECT_EQ(stats.load_evaluations, 0u);
  EXPECT_EQ(stats.energy_evaluations, 0u);
  t = run_nominal(scene_with({"bearing_fx_N"}), &stats);
  EXPECT_EQ(stats.load_evaluations, 201u);
}

TEST(NominalRun, GridColumnsAndContinuity) {
  Scene s = scene_with({"time_s", "theta3_rad", "theta4_rad", "crank_torque_Nm"});
  s.start_angle_rad = units::deg_to_rad(170);
  const SeriesTable t = run_nominal(s);
  ASSERT_EQ(t.rows(), 201u);
  ASSERT_EQ(t.names.front(), "crank_deg");
  EXPECT_DOUBLE_EQ(t.columns[0][0], 170.0);
  EXPECT_NEAR(t.columns[0][200], 170.0 + 720.0, 1e-9);
  EXPECT_NEAR(t.columns[1][200], 2 * 60.0 / 350.0, 1e-12);
  // Angles continuous (no ±2π jumps) and periodic over a turn.
  for (std::size_t i = 1; i < t.rows(); ++i) {
    EXPECT_LT(std::abs(t.columns[2][i] - t.columns[2][i - 1]), 0.5);
    EXPECT_LT(std::abs(t.columns[3][i] - t.columns[3][i - 1]), 0.5);
  }
  EXPECT_NEAR(t.columns[2][0], t.columns[2][100], 1e-12);
  EXPECT_NEAR(t.columns[4][0], t.columns[4][200], 1e-9);
}

TEST(NominalRun, ClockwiseCrank) {
  Scene s = scene_with({"omega3_rad_s"});
  s.crank_speed_rad_s = -s.crank_speed_rad_s;
  const SeriesTable t = run_nominal(s);
  EXPECT_NEAR(t.columns[0][100], -360.0, 1e-9);
  // Reversing the crank reverses every angular velocity at the same angle.
  const NominalMotion m = solve_motion(*s.rig, {units::deg_to_rad(-36), s.crank_speed_rad_s, 0});
  EXPECT_NEAR(t.columns[1][10], m.omega3_rad_s, 1e-12);
}

}  // namespace
}  // namespace fourbar
