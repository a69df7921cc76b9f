// The fourbar command: subcommand table, help, version, exit codes, and
// `fourbar: ` one-line errors for bad arguments.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::count_lines;
using testing::run_fourbar;

TEST(Cli, VersionAndHelp) {
  auto r = run_fourbar("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out.rfind("fourbar ", 0), 0u) << r.out;
  r = run_fourbar("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("sim"), std::string::npos);
  EXPECT_NE(r.out.find("exit status"), std::string::npos);
  EXPECT_NE(r.out.find("tap"), std::string::npos);
  for (const char* cmd : {"sim", "rig", "tap"}) {
    r = run_fourbar(std::string(cmd) + " --help");
    EXPECT_EQ(r.status, 0) << cmd;
    EXPECT_NE(r.out.find("usage: fourbar"), std::string::npos) << cmd;
  }
}

TEST(Cli, NoArgumentsOrUnknownCommandIsUsageError) {
  auto r = run_fourbar("");
  EXPECT_EQ(r.status, 2);
  r = run_fourbar("simulate x");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("fourbar: unknown command 'simulate'", 0), 0u) << r.err;
  EXPECT_EQ(count_lines(r.err), 1);
  EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << "nothing close to 'simulate': " << r.err;
  for (const auto& [typed, meant] : std::vector<std::pair<std::string, std::string>>{
           {"reprot", "report"}, {"swep", "sweep"}, {"acquier", "acquire"}, {"analyse", "analyze"}}) {
    r = run_fourbar(typed + " x");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("did you mean '" + meant + "'?"), std::string::npos) << r.err;
  }
}

TEST(Cli, AMissingPositionalArgumentIsNamedAsTheUsageNamesIt) {
  for (const auto& [command, name] : std::vector<std::pair<std::string, std::string>>{
           {"report", "SESSION_DIR"}, {"sweep", "SWEEP.toml"}, {"sim", "SCENE.toml"}}) {
    const auto r = run_fourbar(command);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("fourbar: " + command + ": " + name + " is missing"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("--session"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("'--sweep'"), std::string::npos) << r.err;
  }
}

TEST(Cli, BadOptionsFailCleanly) {
  auto r = run_fourbar("sim --frobnicate");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("fourbar: sim: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("fourbar sim --help"), std::string::npos) << r.err;
  EXPECT_EQ(count_lines(r.err), 1);
  r = run_fourbar("sim");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("SCENE.toml is missing"), std::string::npos) << r.err;
  r = run_fourbar("sim a.toml b.toml");
  EXPECT_EQ(r.status, 2);
}

TEST(Cli, RigReportsClass) {
  auto r = run_fourbar("rig " FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("crank-rocker"), std::string::npos) << r.out;
  r = run_fourbar("rig " FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml --json");
  EXPECT_NE(r.out.find("\"grashof_class\": \"crank-rocker\""), std::string::npos) << r.out;
  r = run_fourbar("rig /nonexistent.toml");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "fourbar: /nonexistent.toml: no such file (check the path)\n");
}

}  // namespace
}  // namespace fourbar
