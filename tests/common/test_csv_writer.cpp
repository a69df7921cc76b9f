#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
