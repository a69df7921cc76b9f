// `fourbar sweep`: a small grid over the experiment base scene writes one row
// per point with consistent statistics; bad sweep files fail with exit 2.

#include <gtest/gtest.h>

#include <sstream>

#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::run_fourbar;
using testing::TempDir;

std::vector<std::vector<double>> rows_of(const std::string& csv, std::vector<std::string>& header) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(csv);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string cell;
    std::vector<double> row;
    if (header.empty()) {
      while (std::getline(ls, cell, ',')) header.push_back(cell);
      continue;
    }
    while (std::getline(ls, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(SweepCommand, GridTable) {
  TempDir dir;
  dir.write("g.toml", "scene = \"" FOURBAR_SOURCE_DIR "/data/scenes/experiment_clearance_base.toml\"\n"
                      "radial_mm = [0.1016, 0.254]\ncrank_speed_rpm = [300, 350]\nrestitution = [0.5, 0.8]\n"
                      "revolutions = 2\nskip_revolutions = 1\n");
  const auto out = dir.path() / "t.csv";
  const auto r = run_fourbar("sweep " + (dir.path() / "g.toml").string() + " --jobs 2 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> header;
  const auto rows = rows_of(testing::read_file(out), header);
  ASSERT_EQ(rows.size(), 8u);
  ASSERT_EQ(header.front(), "radial_mm");
  EXPECT_DOUBLE_EQ(rows[0][0], 0.1016);
  EXPECT_DOUBLE_EQ(rows[7][2], 0.8);
  double total_impacts = 0;
  for (const auto& row : rows) {
    // I_n = ΣF/n, shares in [0, 1], invariants small.
    if (row[4] > 0) EXPECT_NEAR(row[6], row[5] / row[4], 1e-12 * row[6]);
    EXPECT_GE(row[8], 0.0);
    EXPECT_LE(row[8], 1.0);
    EXPECT_LT(row[9], 1e-6);
    total_impacts += row[4];
  }
  EXPECT_GT(total_impacts, 10);
}

TEST(SweepCommand, BadSweepFileExitTwo) {
  for (const std::string body : {"radial_mm = [-1]\n", "crank_speed_rpm = [0]\n", "restitution = [1.5]\n",
                                  "friction_coefficient = [0.1]\n", "revolutionz = 3\n"}) {
    TempDir dir;
    dir.write("g.toml", "scene = \"" FOURBAR_SOURCE_DIR "/data/scenes/experiment_clearance_base.toml\"\n" + body);
    const auto r = run_fourbar("sweep " + (dir.path() / "g.toml").string() + " --out " + (dir.path() / "t.csv").string());
    EXPECT_EQ(r.status, 2) << body << r.err;
    EXPECT_NE(r.err.find("g.toml"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "t.csv"));
  }
}

}  // namespace
}  // namespace fourbar
