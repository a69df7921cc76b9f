// A recording whose file name is not UTF-8 (Latin-1, as copied from a DAQ
// PC) is reported like any other: JSON outputs write the byte as U+FFFD
// instead of ending the whole report with an internal error.

#include <gtest/gtest.h>

#include <fstream>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

TEST(ReportFileNames, Latin1NameIsReportedNotFatal) {
  testing::TempDir d;
  const std::filesystem::path session = d.path() / "session", src = FOURBAR_SOURCE_DIR "/data/session";
  std::filesystem::create_directories(session);
  const std::string stem = "Messung_\xE4";  // "Messung_ä" in Latin-1
  std::filesystem::copy_file(src / "thesis_350rpm_00254mm.flac", session / (stem + ".flac"));
  std::string manifest = testing::read_file(src / "thesis_350rpm_00254mm.toml");
  const auto rig = manifest.find("rig = ");
  ASSERT_NE(rig, std::string::npos);
  manifest.replace(rig, manifest.find('\n', rig) - rig, "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"");
  std::ofstream(session / (stem + ".toml")) << manifest;

  const auto r = testing::run_fourbar("report " + session.string() + " --out " + (d.path() / "out" / "report.html").string());
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string summary = testing::read_file(d.path() / "out" / "summary.json");
  EXPECT_NE(summary.find("Messung_\xEF\xBF\xBD.flac"), std::string::npos) << summary.substr(0, 2000);
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary.substr(0, 2000);
  EXPECT_NE(summary.find("\"recordings_failed\": 0"), std::string::npos) << summary.substr(0, 2000);
  EXPECT_TRUE(std::filesystem::exists(d.path() / "out" / "report.html"));
}

}  // namespace
}  // namespace fourbar
