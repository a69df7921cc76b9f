// The Siconos three-clearance four-bar scene (data/scenes/siconos_three_clearance.toml,
// ../shared/benchmarks/three-clearance-four-bar.md): the crank prescribed from
// the benchmark's table, clearance in three joints, contacts per joint.
// The crank table lives in shared/ beside the repository (no licence note:
// not copied); without it the test is skipped, saying so.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "common/error.hpp"
#include "sim/run/linkage_run.hpp"
#include "sim/drive/tabulated_crank.hpp"
#include "sim/scene.hpp"

namespace fourbar {
namespace {

const std::filesystem::path kTable = std::filesystem::path(FOURBAR_SHARED_DIR) / "benchmarks" /
                                     "three-clearance-crank-motion.csv";

TEST(SiconosScene, NamesTheSharedCrankTableRelativeToTheRepository) {
  const Scene scene = load_scene(std::filesystem::path(FOURBAR_SOURCE_DIR) / "data/scenes/siconos_three_clearance.toml");
  EXPECT_EQ(scene.model, Model::linkage);
  const std::filesystem::path expected =
      (std::filesystem::path(FOURBAR_SOURCE_DIR) / "../shared/benchmarks/three-clearance-crank-motion.csv")
          .lexically_normal();
  EXPECT_EQ(scene.linkage.crank_table, expected);
  for (double xi : scene.linkage.spec.clearance_m) EXPECT_DOUBLE_EQ(xi, 5e-3);
  EXPECT_DOUBLE_EQ(scene.rig->gravity_m_s2, 9.81);
}

TEST(SiconosScene, CrankSplineFollowsTheTable) {
  if (!std::filesystem::exists(kTable)) GTEST_SKIP() << "no " << kTable << " (shared/ beside the repository)";
  const auto crank = TabulatedCrank::from_csv(kTable);
  // The spline's speed against the table's own speeds (independent of the angles it interpolates).
  double num = 0, den = 0;
  for (std::size_t i = 0; i < crank->table_speeds().size(); ++i) {
    const double w = crank->at(1e-3 * static_cast<double>(i)).speed_rad_s, ref = crank->table_speeds()[i];
    num += (w - ref) * (w - ref);
    den += ref * ref;
  }
  std::printf("    crank speed: spline vs table relative RMS %.3e\n", std::sqrt(num / den));
  EXPECT_LT(std::sqrt(num / den), 0.02);
  EXPECT_NEAR(crank->at(0.0).angle_rad, 1.570823772, 1e-12);
}

TEST(SiconosScene, ThreeClearancesOverOneSecond) {
  if (!std::filesystem::exists(kTable)) GTEST_SKIP() << "no " << kTable << " (shared/ beside the repository)";
  Scene scene = load_scene(std::filesystem::path(FOURBAR_SOURCE_DIR) / "data/scenes/siconos_three_clearance.toml");
  scene.linkage.crank_table = kTable;
  const LinkageRun run = run_linkage(scene);
  const LinkageDiagnostics& d = run.diagnostics;
  EXPECT_EQ(run.clearance_joints.size(), 3u);
  EXPECT_LT(std::abs(d.energy_residual_J) / d.energy_scale_J, 1e-6);
  for (int j : run.clearance_joints) {
    const LinkageJointBooks& b = d.joint[static_cast<std::size_t>(j)];
    int impacts = 0;
    for (const LinkageContact& c : run.contacts) impacts += c.joint == j && c.impact;
    std::printf("    %-15s impacts %3d, contact losses %3d, free flight %.3f, max penetration %.3e mm\n",
                to_string(static_cast<LinkJoint>(j)), impacts, b.contact_losses,
                b.free_time_s / (b.free_time_s + b.contact_time_s), b.max_penetration_m * 1e3);
    EXPECT_NEAR(b.free_time_s + b.contact_time_s, 1.0, 1e-9);
    EXPECT_GT(impacts, 0);
    EXPECT_GT(b.max_penetration_m, 0.0);
    EXPECT_LT(b.max_penetration_m, 0.1 * 5e-3);
  }
  EXPECT_EQ(run.series.rows(), 1001u);
}

}  // namespace
}  // namespace fourbar
