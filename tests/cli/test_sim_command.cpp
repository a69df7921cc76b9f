// `fourbar sim` end to end: the thesis scene against its golden CSV, and bad
// rig/scene input failing with one line and exit status 2, writing nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "support/csv_file.hpp"
#include "support/clean_failure.hpp"
#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::count_lines;
using testing::replace;
using testing::run_fourbar;
using testing::TempDir;

using testing::Csv;
using testing::read_csv;

// Golden: the thesis rig at 350 rpm. Tolerance: 1e-9 relative to each
// column's peak, far below physical meaning, far above libm differences.
TEST(SimCommand, ThesisNominalMatchesGoldenCsv) {
  TempDir dir;
  const auto r = run_fourbar("sim " FOURBAR_SOURCE_DIR "/data/scenes/thesis_nominal_350rpm.toml --out " +
                             dir.path().string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Csv got = read_csv(dir.path() / "series.csv");
  const Csv want = read_csv(FOURBAR_SOURCE_DIR "/tests/golden/thesis_nominal_350rpm.csv");
  ASSERT_EQ(got.header, want.header);
  ASSERT_EQ(got.rows.size(), want.rows.size());
  ASSERT_EQ(got.header.front(), "crank_deg");
  for (std::size_t c = 0; c < want.header.size(); ++c) {
    double peak = 0;
    for (const auto& row : want.rows) peak = std::max(peak, std::abs(row[c]));
    for (std::size_t i = 0; i < want.rows.size(); ++i)
      ASSERT_NEAR(got.rows[i][c], want.rows[i][c], 1e-9 * peak) << want.header[c] << " row " << i;
  }
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "summary.json"));
  const std::string summary = testing::read_file(dir.path() / "summary.json");
  EXPECT_NE(summary.find("\"grashof_class\": \"crank-rocker\""), std::string::npos);
  EXPECT_NE(summary.find("\"version\""), std::string::npos);
}

class BadSceneInput : public ::testing::Test {
 protected:
  TempDir dir;
  std::string scene = R"(rig = "r.toml"
crank_speed_rpm = 350
outputs = ["alpha3_rad_s2"]
)";
  testing::CommandResult run(const std::string& scene_text, const std::string& rig_text) {
    dir.write("r.toml", rig_text);
    const auto s = dir.write("s.toml", scene_text);
    return run_fourbar("sim " + s.string() + " --out " + (dir.path() / "out").string());
  }
  void expect_clean_failure(const testing::CommandResult& r, const std::string& needle) {
    testing::expect_clean_failure(r, needle, dir.path() / "out");
  }
};

TEST_F(BadSceneInput, MissingKey) {
  expect_clean_failure(run(replace(scene, "crank_speed_rpm = 350\n", ""), testing::thesis_rig_toml()),
                       "missing key 'crank_speed_rpm'");
}
TEST_F(BadSceneInput, NegativeMass) {
  expect_clean_failure(run(scene, replace(testing::thesis_rig_toml(), "mass_kg = 0.2439", "mass_kg = -0.2439")),
                       "coupler.mass_kg");
}
TEST_F(BadSceneInput, LinksCannotClose) {
  expect_clean_failure(run(scene, replace(testing::thesis_rig_toml(), "length_mm = 387.0", "length_mm = 800.0")),
                       "cannot close");
}
TEST_F(BadSceneInput, UnknownOutput) {
  expect_clean_failure(run(replace(scene, "alpha3_rad_s2", "alpha5_rad_s2"), testing::thesis_rig_toml()),
                       "unknown output 'alpha5_rad_s2'");
}

}  // namespace
}  // namespace fourbar
