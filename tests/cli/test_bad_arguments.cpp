// Bad arguments to every subcommand (issue 7): each fails cleanly with exit
// status 2 and exactly one line on stderr starting `fourbar: `, writes
// nothing, and never crashes.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/clean_failure.hpp"
#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::count_lines;
using testing::run_fourbar;
using testing::TempDir;

const std::string kData = FOURBAR_SOURCE_DIR "/data";

struct BadCase {
  std::string args;
  std::string must_mention;  ///< a word the message names (option, file, value)
};

void expect_clean_failure(const BadCase& c, const std::filesystem::path& out_dir) {
  SCOPED_TRACE("fourbar " + c.args);
  testing::expect_clean_failure(run_fourbar(c.args), c.must_mention, out_dir);
}

class BadArguments : public ::testing::Test {
 protected:
  TempDir dir;
  std::string out() const { return (dir.path() / "out").string(); }
  std::filesystem::path file(const std::string& name, const std::string& text) const { return dir.write(name, text); }
};

TEST_F(BadArguments, Tap) {
  const std::string rec = file("tap.csv", "time_s,a\n0,0\n0.001,1\n0.002,0\n").string();
  for (const BadCase& c : std::vector<BadCase>{
           {"tap", "REC"},
           {"tap /nonexistent/tap.wav", "/nonexistent/tap.wav"},
           {"tap " + rec + " --link crank", "crank"},
           {"tap " + rec + " --modes 0", "modes"},
           {"tap " + rec + " --channel 7", "7"},
           {"tap " + rec, "tap.csv"},
       })
    expect_clean_failure(c, out());
}

TEST_F(BadArguments, Sim) {
  const std::string scene = kData + "/scenes/thesis_nominal_350rpm.toml";
  const std::string empty = file("empty.toml", "").string();
  const std::string plain = file("plain_file", "x").string();
  for (const BadCase& c : std::vector<BadCase>{
           {"sim", "SCENE.toml"},
           {"sim --frobnicate " + scene, "frobnicate"},
           {"sim " + scene + " " + scene + " --out " + out(), "sim"},
           {"sim /nonexistent/scene.toml --out " + out(), "/nonexistent/scene.toml"},
           {"sim " + dir.path().string() + " --out " + out(), dir.path().string()},
           {"sim " + empty + " --out " + out(), "empty.toml"},
           {"sim " + scene + " --out", "out"},
           {"sim " + scene + " --out " + plain, "plain_file"},
       })
    expect_clean_failure(c, out());
}

TEST_F(BadArguments, Rig) {
  const std::string rig = kData + "/rigs/thesis.toml";
  const std::string garbage = file("garbage.toml", "[ground\nlength_mm = ").string();
  for (const BadCase& c : std::vector<BadCase>{
           {"rig", "rig"},
           {"rig " + rig + " --json=maybe", "json"},
           {"rig " + rig + " " + rig, "rig"},
           {"rig --nope " + rig, "nope"},
           {"rig /nonexistent.toml", "/nonexistent.toml"},
           {"rig " + garbage, "garbage.toml"},
       })
    expect_clean_failure(c, out());
}

TEST_F(BadArguments, Sweep) {
  const std::string sweep = kData + "/scenes/experiment_grid_sweep.toml";
  const std::string out_csv = out() + "/table.csv";
  for (const BadCase& c : std::vector<BadCase>{
           {"sweep", "sweep"},
           {"sweep " + sweep + " --jobs 0 --out " + out_csv, "jobs"},
           {"sweep " + sweep + " --jobs -1 --out " + out_csv, "jobs"},
           {"sweep " + sweep + " --jobs many --out " + out_csv, "jobs"},
           {"sweep " + sweep + " --jobs 99999999999 --out " + out_csv, "jobs"},
           {"sweep " + sweep + " --out " + out_csv + " --bogus", "bogus"},
           {"sweep /nonexistent.toml --out " + out_csv, "/nonexistent.toml"},
           {"sweep " + kData + "/scenes/thesis_nominal_350rpm.toml --out " + out_csv, "scene"},
       })
    expect_clean_failure(c, out());
}

TEST_F(BadArguments, Acquire) {
  const std::string rec = file("rec.csv", "time_s,a\n0,1\n0.001,2\n").string();
  for (const BadCase& c : std::vector<BadCase>{
           {"acquire", "REC is missing"},
           {"acquire " + rec, "rec.toml"},  // checks only, but needs the manifest
           {"acquire " + rec + " --out " + out() + " -n 0", "samples-per-rev"},
           {"acquire " + rec + " --out " + out() + " -n -5", "samples-per-rev"},
           {"acquire " + rec + " --out " + out() + " -n lots", "samples-per-rev"},
           {"acquire " + rec + " --out " + out() + " --binary=yes", "binary"},
           {"acquire " + rec + " --out " + out() + " --manifest /nonexistent.toml", "/nonexistent.toml"},
           {"acquire " + rec + " --out " + out(), "rec.toml"},  // no manifest beside it
           {"acquire /nonexistent.wav --out " + out(), "/nonexistent.wav"},
           {"acquire " + dir.path().string() + " --out " + out(), dir.path().string()},
       })
    expect_clean_failure(c, out());
}

TEST_F(BadArguments, VirtualRig) {
  const std::string scene = kData + "/scenes/thesis_virtual_rig_350rpm.toml";
  for (const BadCase& c : std::vector<BadCase>{
           {"virtual-rig", "required"},
           {"virtual-rig " + scene, "out"},
           {"virtual-rig " + scene + " --out " + out() + "/rec.mp3", "mp3"},
           {"virtual-rig " + scene + " --out " + out() + "/rec", "rec"},
           {"virtual-rig " + scene + " --out " + out() + "/rec.wav --no-truth=1", "no-truth"},
           {"virtual-rig " + kData + "/scenes/thesis_nominal_350rpm.toml --out " + out() + "/rec.wav", "recording"},
           {"virtual-rig /nonexistent.toml --out " + out() + "/rec.wav", "/nonexistent.toml"},
       })
    expect_clean_failure(c, out());
}

TEST_F(BadArguments, VirtualRigNeverWritesOverItsScene) {
  // `--out S.flac` beside the scene S.toml: the recording's manifest would be
  // S.toml. Refused before anything is written; the scene is left as it was.
  std::string text = testing::read_file(kData + "/scenes/thesis_virtual_rig_350rpm.toml");
  text.replace(text.find("../rigs/"), 8, kData + "/rigs/");
  const auto scene = file("S.toml", text);
  const std::string before = testing::read_file(scene);
  const auto r = run_fourbar("virtual-rig " + scene.string() + " --out " + (dir.path() / "S.flac").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("would overwrite the input " + scene.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("S_rec.flac"), std::string::npos) << r.err;
  EXPECT_EQ(testing::count_lines(r.err), 1) << r.err;
  EXPECT_EQ(testing::read_file(scene), before);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "S.flac"));
}

}  // namespace
}  // namespace fourbar
