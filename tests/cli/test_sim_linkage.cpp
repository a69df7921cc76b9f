// `fourbar sim` with model = "linkage": series with per-joint columns,
// impacts.csv with a joint column, per-joint summary; the Siconos scene with
// its crank table read from shared/ beside the repository; bad [linkage]
// values fail with exit status 2 naming the key.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::run_fourbar;
using testing::TempDir;

TEST(SimLinkageCommand, ThreeClearanceThesisSceneWritesPerJointTables) {
  TempDir dir;
  const auto r = run_fourbar("sim " FOURBAR_SOURCE_DIR "/data/scenes/thesis_linkage_three_clearances_350rpm.toml --out " +
                             dir.path().string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string series = testing::read_file(dir.path() / "series.csv");
  EXPECT_EQ(series.rfind("crank_deg,time_s,mode,alpha3_rad_s2", 0), 0u);
  for (const char* c : {"crank_coupler_gap_mm", "coupler_rocker_contact_force_N", "rocker_ground_fy_N"})
    EXPECT_NE(series.find(c), std::string::npos) << c;
  EXPECT_EQ(testing::count_lines(series), 1 + 361);
  const std::string impacts = testing::read_file(dir.path() / "impacts.csv");
  EXPECT_EQ(impacts.rfind("joint,time_s,approach_speed_m_s,", 0), 0u);
  for (const char* j : {"\ncrank_coupler,", "\ncoupler_rocker,", "\nrocker_ground,"})
    EXPECT_NE(impacts.find(j), std::string::npos) << j;
  std::ifstream in(dir.path() / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& l = j.at("linkage");
  EXPECT_LT(l.at("energy").at("residual_rel").get<double>(), 1e-8);
  for (const char* name : {"crank_coupler", "coupler_rocker", "rocker_ground"}) {
    const auto& jt = l.at("joints").at(name);
    EXPECT_GT(jt.at("impacts").get<int>(), 0) << name;
    const double free = jt.at("free_flight_share"), contact = jt.at("contact_share");
    EXPECT_NEAR(free + contact, 1.0, 1e-9) << name;
    EXPECT_GT(jt.at("contact_damping_loss_J").get<double>(), 0.0) << name;
  }
}

TEST(SimLinkageCommand, SiconosSceneReadsTheSharedCrankTable) {
  const std::filesystem::path table = std::filesystem::path(FOURBAR_SHARED_DIR) / "benchmarks/three-clearance-crank-motion.csv";
  if (!std::filesystem::exists(table)) GTEST_SKIP() << "no " << table << " (shared/ beside the repository)";
  // A checkout layout in a temporary folder: repo/data/{scenes,rigs} and shared/ beside repo.
  TempDir dir;
  const auto repo = dir.path() / "repo";
  for (const char* f : {"data/scenes/siconos_three_clearance.toml", "data/rigs/siconos_three_clearance.toml"})
    dir.write(std::string("repo/") + f, testing::read_file(std::filesystem::path(FOURBAR_SOURCE_DIR) / f));
  std::filesystem::create_directory_symlink(std::filesystem::absolute(FOURBAR_SHARED_DIR), dir.path() / "shared");
  const auto r = run_fourbar("sim " + (repo / "data/scenes/siconos_three_clearance.toml").string() + " --out " +
                             (dir.path() / "out").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string impacts = testing::read_file(dir.path() / "out/impacts.csv");
  EXPECT_EQ(impacts.rfind("joint,time_s,approach_speed_m_s,", 0), 0u);
  std::ifstream in(dir.path() / "out/summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("provenance").at("inputs").size(), 3u) << "scene, rig and crank table";
  for (const char* name : {"crank_coupler", "coupler_rocker", "rocker_ground"})
    EXPECT_GT(j.at("linkage").at("joints").at(name).at("impacts").get<int>(), 0) << name;
}

TEST(SimLinkageCommand, ElasticCouplerSceneWritesSensorAndModalColumns) {
  TempDir dir;
  const auto r = run_fourbar("sim " FOURBAR_SOURCE_DIR "/data/scenes/thesis_linkage_elastic_coupler_350rpm.toml --out " +
                             dir.path().string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string series = testing::read_file(dir.path() / "series.csv");
  for (const char* c : {"coupler_acc_154.5mm_0mm_m_s2", "coupler_acc_309mm_0mm_m_s2", "coupler_eta1_um",
                        "coupler_eta2_um", "coupler_midspan_deflection_um"})
    EXPECT_NE(series.find(c), std::string::npos) << c;
  std::ifstream in(dir.path() / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& e = j.at("linkage").at("energy");
  EXPECT_GT(e.at("modal_damping_J").get<double>(), 0.0);
  EXPECT_LT(e.at("residual_rel").get<double>(), 1e-8);
}

/// The data rows of a CSV file as numbers (the first line is the header; a
/// cell that is not a number reads as NaN).
std::vector<std::vector<double>> numeric_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      try {
        row.push_back(std::stod(cell));
      } catch (...) {
        row.push_back(std::nan(""));
      }
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(SimLinkageCommand, WarmupTurnsStartTheSeriesAfterThemAndKeepTheRun) {
  // Three turns output from the start against one turn after two warm-up
  // turns: the same run, so the second's rows are the first's last turn and
  // both have the same contacts.
  TempDir dir;
  dir.write("rig.toml", testing::read_file(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml"));
  const std::string scene = R"(rig = "rig.toml"
model = "linkage"
crank_speed_rpm = 350.0
revolutions = REVS
samples_per_revolution = 90
outputs = ["time_s", "alpha3_rad_s2", "contact_force_N"]
[linkage]
coupler_rocker_radial_mm = 0.254
elastic_links = ["coupler"]
elastic_modes = 1
restitution = 0.5
contact_stiffness_N_per_m_n = 1e10
tolerance = 1e-9
)";
  const auto three = dir.write("three.toml", testing::replace(scene, "REVS", "3"));
  const auto one = dir.write("one.toml", testing::replace(scene, "REVS", "1"));
  const auto a = run_fourbar("sim " + three.string() + " --out " + (dir.path() / "a").string());
  ASSERT_EQ(a.status, 0) << a.err;
  const auto b = run_fourbar("sim " + one.string() + " --warmup-turns 2 --out " + (dir.path() / "b").string());
  ASSERT_EQ(b.status, 0) << b.err;
  const auto ra = numeric_rows(testing::read_file(dir.path() / "a/series.csv"));
  const auto rb = numeric_rows(testing::read_file(dir.path() / "b/series.csv"));
  ASSERT_EQ(ra.size(), 3U * 90U + 1U);
  ASSERT_EQ(rb.size(), 91U);
  EXPECT_NEAR(rb.front()[0], 720.0, 1e-9);  // crank_deg goes on from the warm-up
  EXPECT_NEAR(rb.back()[0], 1080.0, 1e-9);
  std::size_t compared = 0;
  for (std::size_t i = 0; i < rb.size(); ++i) {
    const std::vector<double>& x = rb[i];
    const std::vector<double>& y = ra[2 * 90 + i];
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
      if (std::isnan(y[k])) continue;
      EXPECT_NEAR(x[k], y[k], 1e-7 * (1 + std::abs(y[k]))) << "row " << i << " column " << k;
      ++compared;
    }
  }
  EXPECT_GT(compared, 91U * 5U);
  EXPECT_EQ(testing::read_file(dir.path() / "b/impacts.csv"), testing::read_file(dir.path() / "a/impacts.csv"));
  std::ifstream in(dir.path() / "b/summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("scene").at("warmup_revolutions").get<int>(), 2);
  EXPECT_NEAR(j.at("scene").at("output_start_s").get<double>(), 2 * 60.0 / 350.0, 1e-12);
  EXPECT_NEAR(j.at("scene").at("duration_s").get<double>(), 60.0 / 350.0, 1e-12);
  // Without the option a linkage scene's output starts at the start.
  std::ifstream ina(dir.path() / "a/summary.json");
  EXPECT_EQ(nlohmann::json::parse(ina).at("scene").at("warmup_revolutions").get<int>(), 0);
}

TEST(SimLinkageCommand, WarmupOnACrankTableCountsItsTurnsAndRefusesTooMany) {
  TempDir dir;
  dir.write("rig.toml", testing::thesis_rig_toml());
  // 0.4 s at 350 rpm: 2.33 turns.
  std::string table = "time_s,crank_rad,crank_rad_s\n";
  const double w = 350.0 * 2 * M_PI / 60;
  for (int i = 0; i <= 400; ++i) {
    const double t = 0.001 * i;
    table += std::to_string(t) + "," + std::to_string(w * t) + "," + std::to_string(w) + "\n";
  }
  dir.write("crank.csv", table);
  const auto scene = dir.write("scene.toml", R"(rig = "rig.toml"
model = "linkage"
outputs = ["time_s"]
[linkage]
crank_motion = "crank.csv"
coupler_rocker_radial_mm = 0.254
restitution = 0.5
contact_stiffness_N_per_m_n = 1e10
)");
  const auto r = run_fourbar("sim " + scene.string() + " --warmup-turns 3 --out " + (dir.path() / "out").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("fourbar: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("--warmup-turns 3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("crank.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out/series.csv"));
  // Two warm-up turns fit: the output runs from the second turn's end to the table's end.
  const auto ok = run_fourbar("sim " + scene.string() + " --warmup-turns 2 --out " + (dir.path() / "ok").string());
  ASSERT_EQ(ok.status, 0) << ok.err;
  std::ifstream in(dir.path() / "ok/summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_NEAR(j.at("scene").at("output_start_s").get<double>(), 2 * 60.0 / 350.0, 1e-5);
  EXPECT_NEAR(j.at("scene").at("duration_s").get<double>(), 0.4 - 2 * 60.0 / 350.0, 1e-5);
  const auto rows = numeric_rows(testing::read_file(dir.path() / "ok/series.csv"));
  ASSERT_FALSE(rows.empty());
  EXPECT_NEAR(rows.front()[0], 720.0, 1e-2);  // crank_deg
}

TEST(SimLinkageCommand, BadLinkageValuesExitTwoNamingTheKey) {
  TempDir dir;
  dir.write("rig.toml", testing::thesis_rig_toml());
  const std::string base = R"(rig = "rig.toml"
model = "linkage"
crank_speed_rpm = 350.0
outputs = ["time_s"]
[linkage]
restitution = 0.5
contact_stiffness_N_per_m_n = 1e10
)";
  struct Case {
    std::string extra, key;
  };
  for (const Case& c : {Case{"rocker_ground_radial_mm = -0.1\n", "rocker_ground_radial_mm"},
                        Case{"coupler_rocker_radial_mm = 0.0\n", "coupler_rocker_radial_mm"},
                        Case{"crank_coupler_radial_mm = 300.0\n", "crank_coupler_radial_mm"},
                        Case{"contact = \"rough\"\n", "contact"},
                        Case{"crank_motion = \"missing.csv\"\n", "crank_speed_rpm"},
                        Case{"elastic_links = [\"coupler\"]\n", "elastic_links"},  // the rig has no [coupler.elastic]
                        Case{"elastic_links = [\"crank\"]\n", "elastic_links"},
                        Case{"coupler_sensors_mm = [400.0, 0.0]\n", "coupler_sensors_mm"},
                        Case{"rocker_sensors_mm = [100.0]\n", "rocker_sensors_mm"}}) {
    const auto scene = dir.write("scene.toml", base + c.extra);
    const auto r = run_fourbar("sim " + scene.string() + " --out " + (dir.path() / "out").string());
    EXPECT_EQ(r.status, 2) << c.extra;
    EXPECT_EQ(r.err.rfind("fourbar: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << c.extra << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out/series.csv"));
  }
  const auto no_k = dir.write("scene.toml", testing::replace(base, "contact_stiffness_N_per_m_n = 1e10\n", ""));
  const auto r = run_fourbar("sim " + no_k.string() + " --out " + (dir.path() / "out").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("contact_stiffness_N_per_m_n"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fourbar
