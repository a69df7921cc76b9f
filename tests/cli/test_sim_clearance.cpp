// `fourbar sim` with model = "clearance": the thesis scenes write series,
// impact and revolution tables and a summary; bad [clearance] values fail
// with one line, exit status 2, and nothing written.

#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::run_fourbar;
using testing::TempDir;

TEST(SimClearanceCommand, ThesisSceneWritesAllTables) {
  TempDir dir;
  const auto r = run_fourbar("sim " FOURBAR_SOURCE_DIR "/data/scenes/thesis_clearance_350rpm_e05.toml --out " +
                             dir.path().string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f : {"series.csv", "impacts.csv", "revolutions.csv", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / f)) << f;
  const std::string series = testing::read_file(dir.path() / "series.csv");
  EXPECT_EQ(series.rfind("crank_deg,time_s,mode,gap_mm,theta3_rad", 0), 0u) << "the header is the first line";
  EXPECT_EQ(testing::count_lines(series), 1 + 3601);  // header, rows
  std::ifstream in(dir.path() / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("provenance").at("inputs").size(), 2u) << "the tables' provenance (scene, rig) is in summary.json";
  const auto& c = j.at("clearance");
  EXPECT_EQ(c.at("settings").at("restitution"), 0.5);
  EXPECT_LT(c.at("energy").at("residual_rel").get<double>(), 1e-8);
  EXPECT_LT(c.at("drift").at("max_contact_circle_error_rel").get<double>(), 1e-9);
  EXPECT_LT(c.at("drift").at("max_penetration_rel").get<double>(), 1e-9);
  // The report's warm-up by default: one turn after 20 (the issue's "0
  // impacts" was the first turn from the start); the count is said, and
  // that one turn is too few for a mean.
  EXPECT_EQ(j.at("scene").at("warmup_revolutions"), 20);
  const auto& out = c.at("output_turns");
  EXPECT_EQ(out.at("first_revolution"), 20);
  EXPECT_GT(out.at("impacts").get<int>(), 0) << "the e = 0.5 scene after the warm-up impacts";
  EXPECT_NE(r.out.find(std::to_string(out.at("impacts").get<int>()) + " impacts in the 1 turn output ("),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("after 20 warm-up turns (not output)"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("transient"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("impacts per turn from 1 turn only: the count varies from turn to turn"), std::string::npos)
      << r.err;
  const std::string revs = testing::read_file(dir.path() / "revolutions.csv");
  EXPECT_EQ(testing::count_lines(revs), 1 + 21) << "the warm-up turns kept, column revolution";
  const std::string first_row = series.substr(series.find('\n') + 1);
  const double t0 = std::stod(first_row.substr(first_row.find(',') + 1));  // crank_deg, time_s, ...
  EXPECT_NEAR(t0, 20 * 60.0 / 350.0, 1e-9) << "series.csv starts after the warm-up";
}

TEST(SimClearanceCommand, WithoutWarmUpTheTransientIsSaid) {
  // --warmup-turns 0: the thesis's first turn from the start (Figs 6.10b-6.18b),
  // its counts the start transient; said.
  TempDir dir;
  const auto r = run_fourbar("sim " FOURBAR_SOURCE_DIR "/data/scenes/thesis_clearance_350rpm_e05.toml --warmup-turns 0 --out " +
                             dir.path().string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("impacts in 1 turn from the start: the transient after the start"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("20 warm-up turns"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("from the start (no warm-up)"), std::string::npos) << r.out;
  std::ifstream in(dir.path() / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("scene").at("warmup_revolutions"), 0);
  EXPECT_EQ(j.at("clearance").at("output_turns").at("first_revolution"), 0);
  const auto bad = run_fourbar("sim " FOURBAR_SOURCE_DIR "/data/scenes/thesis_clearance_350rpm_e05.toml --warmup-turns -1 --out " +
                               (dir.path() / "x").string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--warmup-turns -1 must be between 0 and 100000"), std::string::npos) << bad.err;
}

TEST(SimClearanceCommand, WallFrictionSceneStopsAtItsPeriodicState) {
  TempDir dir;
  const auto r = run_fourbar("sim " FOURBAR_SOURCE_DIR "/data/scenes/wall_friction_steady_350rpm.toml --out " +
                             dir.path().string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("transient"), std::string::npos) << "a steady-state run is no transient: " << r.err;
  std::ifstream in(dir.path() / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& st = j.at("clearance").at("steady_state");
  EXPECT_EQ(st.at("criterion_fired"), "periodic");
  EXPECT_EQ(st.at("period_revolutions"), 1);
  const int first = st.at("first_output_revolution");
  EXPECT_LE(first, 8);
  EXPECT_EQ(st.at("verdict"), "periodic with period 1 after " + std::to_string(first) + " turns");
  EXPECT_EQ(st.at("revolutions_simulated"), first + 1);  // no more turns than needed
  const auto& e = j.at("clearance").at("energy");
  EXPECT_GT(e.at("friction_loss_J").get<double>(), 1e-3);
  EXPECT_LT(e.at("residual_rel").get<double>(), 1e-8);
  const std::string revs = testing::read_file(dir.path() / "revolutions.csv");
  EXPECT_NE(revs.find(",alpha3_deviation_rms_rad_s2\n"), std::string::npos);
  EXPECT_EQ(testing::count_lines(revs), 1 + first + 1);  // header, one row per turn
}

TEST(SimClearanceCommand, BadValuesExitTwoAndWriteNothing) {
  const std::string base = testing::read_file(FOURBAR_SOURCE_DIR "/data/scenes/thesis_clearance_350rpm_e05.toml");
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"restitution = 0.5", "restitution = 2"},
           {"radial_mm = 0.254", "radial_mm = -0.254"},
           {"contact = \"smooth\"", "contact = \"stick-slip\"\nfriction_coefficient = -1"},
           {"tolerance = 1e-10", "tolerance = 0"}}) {
    TempDir dir;
    std::string text = base;
    text.replace(text.find(from), from.size(), to);
    text.replace(text.find("../rigs/"), 8, FOURBAR_SOURCE_DIR "/data/rigs/");
    const auto scene = dir.write("s.toml", text);
    const auto out = dir.path() / "out";
    const auto r = run_fourbar("sim " + scene.string() + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << to;
    EXPECT_EQ(testing::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("s.toml"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out / "series.csv")) << to;
  }
}

}  // namespace
}  // namespace fourbar
