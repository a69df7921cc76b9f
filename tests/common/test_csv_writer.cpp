#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

TEST(CsvWriter, WritesCommentsHeaderAndRoundTripNumbers) {
  testing::TempDir dir;
  const auto p = dir.path() / "a.csv";
  {
    CsvWriter w(p, {"made by test"}, {"crank_deg", "x_m"});
    const double row[] = {0.1, 1.0 / 3.0};
    w.row(row);
    w.commit();
  }
  const std::string text = testing::read_file(p);
  EXPECT_EQ(text, "# made by test\ncrank_deg,x_m\n0.1,0.3333333333333333\n");
  EXPECT_EQ(std::stod("0.3333333333333333"), 1.0 / 3.0);
}

TEST(CsvWriter, WithoutCommentsTheHeaderIsTheFirstLine) {
  testing::TempDir dir;
  const auto p = dir.path() / "a.csv";
  CsvWriter w(p, {}, {"speed_rpm", "clearance_mm", "status"});
  const double row[] = {350.0, 0.0254};
  w.row(row, "ok");
  w.row(row, "check set-up, \"axis\"");
  const std::string cells[] = {"", "1e-07", "a\nb"};
  w.text_row(cells);
  w.commit();
  EXPECT_EQ(testing::read_file(p),
            "speed_rpm,clearance_mm,status\n350,0.0254,ok\n350,0.0254,\"check set-up, \"\"axis\"\"\"\n,1e-07,\"a\nb\"\n");
  EXPECT_FALSE(std::filesystem::exists(csv_sidecar_path(p))) << "no sidecar unless asked for";
}

TEST(CsvWriter, SidecarHoldsProvenanceColumnsAndRowsAndAppearsOnCommit) {
  testing::TempDir dir;
  const auto p = dir.path() / "t.csv";
  EXPECT_EQ(csv_sidecar_path(p), dir.path() / "t.csv.json");
  {
    CsvWriter w(p, {}, {"a_m", "b_s"});
    const double row[] = {1.5, 2.0};
    w.row(row);
    w.row(row);
    w.describe_in_sidecar({{"tool", "fourbar"}, {"command", "fourbar test"}});
    EXPECT_FALSE(std::filesystem::exists(csv_sidecar_path(p)));
    w.commit();
  }
  const auto j = nlohmann::json::parse(testing::read_file(csv_sidecar_path(p)));
  EXPECT_EQ(j["file"], "t.csv");
  EXPECT_EQ(j["columns"], nlohmann::json({"a_m", "b_s"}));
  EXPECT_EQ(j["rows"], 2);
  EXPECT_EQ(j["provenance"]["command"], "fourbar test");
}

TEST(CsvWriter, RefusesNonFiniteAndLeavesNoFile) {
  testing::TempDir dir;
  const auto p = dir.path() / "a.csv";
  try {
    CsvWriter w(p, {}, {"crank_deg", "x_m"});
    const double row[] = {0.0, std::numeric_limits<double>::quiet_NaN()};
    w.row(row);
    w.commit();
    FAIL();
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("'x_m' row 1"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(p));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << "temporary file left behind";
}

TEST(CsvWriter, ExistingFileKeptUntilCommit) {
  testing::TempDir dir;
  const auto p = dir.write("a.csv", "old\n");
  {
    CsvWriter w(p, {}, {"a"});
    const double row[] = {1.0};
    w.row(row);
    EXPECT_EQ(testing::read_file(p), "old\n");
  }  // abandoned without commit
  EXPECT_EQ(testing::read_file(p), "old\n");
}

}  // namespace
}  // namespace fourbar
