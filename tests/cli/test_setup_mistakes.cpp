// Set-up mistakes that used to mislead the technician (issue 26), each run
// through `fourbar` on a recording of the sample session with its manifest
// changed the way a technician gets it wrong, checking what they are told:
// a wrong rig file, a forgotten clearance_mm, a calibration sheet in mV/g,
// and TOML slips (a bare word, yes, a unit after a number).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

namespace fs = std::filesystem;

const fs::path kSample = FOURBAR_SOURCE_DIR "/data/session";
const std::string kStem = "thesis_350rpm_0254mm";

/// The sample manifest with `edit` applied (regex → replacement, first match),
/// the rig named by its absolute path.
struct Trial {
  testing::TempDir dir;
  fs::path recording, manifest;

  explicit Trial(const std::string& rig = "thesis.toml") {
    recording = dir.path() / (kStem + ".flac");
    manifest = dir.path() / (kStem + ".toml");
    fs::copy_file(kSample / (kStem + ".flac"), recording);
    text = testing::read_file(kSample / (kStem + ".toml"));
    edit(R"(rig = "[^"]*")", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/" + rig + "\"");
  }
  void edit(const std::string& pattern, const std::string& replacement) {
    const std::string before = text;
    text = std::regex_replace(text, std::regex(pattern), replacement, std::regex_constants::format_first_only);
    ASSERT_NE(text, before) << "no match for " << pattern;
  }
  testing::CommandResult run(const std::string& command) {
    std::ofstream(manifest, std::ios::trunc) << text;
    return testing::run_fourbar(command + " " + recording.string() + (command == "analyze" ? " --out " + (dir.path() / "out").string() : ""));
  }
  std::string text;
};

// The other example rig named in the manifest: the sensor positions no longer
// fit its links, and once they do, the channels disagree with each other the
// way a wrong geometry makes them. The rig file is named as the cause, first.
TEST(SetupMistakes, WrongRigFileIsNamed) {
  Trial t("bench.toml");
  testing::CommandResult r = t.run("analyze");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("lies outside the link"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("names the wrong rig file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("small bench rig"), std::string::npos) << "the rig the manifest names: " << r.err;
  // "Fixed" by moving the sensors onto the bench rig's links.
  t.edit("position_mm = 289", "position_mm = 150");
  t.edit("position_mm = 289", "position_mm = 150");
  t.edit("position_mm = 292", "position_mm = 150");
  r = t.run("analyze");
  EXPECT_EQ(r.status, 0) << r.err;
  const auto first = r.err.find("check set-up");
  ASSERT_NE(first, std::string::npos) << r.err;
  const std::string line = r.err.substr(first, r.err.find('\n', first) - first);
  EXPECT_NE(line.find("rig_file"), std::string::npos) << "the first finding names the rig file:\n" << r.err;
  EXPECT_NE(line.find("bench.toml"), std::string::npos) << line;
  EXPECT_NE(line.find("different factors"), std::string::npos) << line;
}

// No clearance_mm: refused (exit 2) naming the file, the key, what to type
// and that the rig file's clearance is not taken silently; nothing written.
// clearance_mm = "rig" asks for the rig file's, and the report says so
// beside the clearance; the template asks for it.
TEST(SetupMistakes, MissingClearanceIsRefusedAndTheTemplateAsksForIt) {
  Trial t;
  t.edit(R"(clearance_mm = [0-9.]+\n)", "");
  testing::CommandResult r = t.run("analyze");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(testing::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("fourbar: " + t.manifest.string() + ": key 'clearance_mm' is missing: add the line clearance_mm = "),
            std::string::npos) << r.err;
  EXPECT_NE(r.err.find("radial clearance of the coupler-rocker bearing in mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(0.254 mm) is not taken without being asked: clearance_mm = \"rig\" takes it"), std::string::npos)
      << r.err;
  const fs::path page = t.dir.path() / "report" / "report.html";
  r = testing::run_fourbar("report " + t.dir.path().string() + " --out " + page.string() + " -q --no-cache");
  EXPECT_EQ(r.status, 1) << "the report is written, the recording failed: " << r.err;
  EXPECT_NE(r.err.find("key 'clearance_mm' is missing"), std::string::npos) << r.err;
  EXPECT_NE(testing::read_file(page).find("is missing: add the line clearance_mm = "), std::string::npos);
  // Asked for on purpose: taken, said in the warnings and in the report.
  t.edit("(crank_direction = )", "clearance_mm = \"rig\"\n$1");
  r = t.run("analyze");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("clearance_mm = \"rig\": the rig file's 0.254 mm is used"), std::string::npos) << r.err;
  r = testing::run_fourbar("report " + t.dir.path().string() + " --out " + page.string() + " -q --no-cache");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(testing::read_file(page).find("rig file (clearance_mm = &quot;rig&quot;)"), std::string::npos);
  // Any other text is refused with what to type.
  t.edit("clearance_mm = \"rig\"", "clearance_mm = \"0.254 mm\"");
  r = t.run("analyze");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("key 'clearance_mm' = \"0.254 mm\": give the radial clearance in mm as a number"), std::string::npos)
      << r.err;
  r = testing::run_fourbar("inspect " + t.recording.string() + " --manifest-template");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nclearance_mm = \"FILL IN\""), std::string::npos) << r.out;
}

// A calibration sheet in mV/g: accepted as sensitivity_mV_per_g; the same
// number under the m/s² key is named as the unit mix-up it is, with the key
// the manifest has; so are the mix-ups by 1000 (mV for V, V for mV).
TEST(SetupMistakes, MillivoltsPerG) {
  Trial t;
  // 0.002 V per m/s² = 19.6133 mV/g, on every accelerometer.
  const std::string vpu = "volts_per_unit = 0.002";
  for (int i = 0; i < 3; ++i) t.edit(vpu + "\n", "sensitivity_mV_per_g = 19.6133\n");
  testing::CommandResult r = t.run("analyze");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("check set-up"), std::string::npos) << "mV/g read as mV/g: " << r.err;
  Trial m;
  m.edit(vpu + "\n", "sensitivity_mV_per_m_s2 = 19.6\n");  // the coupler's tangential sensor only
  r = m.run("analyze");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("sensitivity_mV_per_m_s2"), std::string::npos) << "the key the manifest has: " << r.err;
  EXPECT_NE(r.err.find("unit mix-up or gain step: the factor is 1/g"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("give it as sensitivity_mV_per_g"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("change [[channel]] name=\"coupler_t\" volts_per_unit"), std::string::npos) << r.err;
  // … and the finding is called by that key, not by the internal volts_per_unit.
  EXPECT_NE(r.err.find("channel 'coupler_t': sensitivity_mV_per_m_s2: the manifest says"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("'coupler_t': volts_per_unit:"), std::string::npos) << r.err;
  // The factor 1000 both ways: mV per m/s² written as V (volts_per_unit = 2
  // for 2 mV), and V/g written under the mV/g key (0.0196 for 19.6 mV/g).
  struct Thousand {
    const char* key_and_value;
    const char* key;
    const char* told;
  };
  for (const Thousand& k : {Thousand{"volts_per_unit = 2", "volts_per_unit", "the factor is 1/1000: a value in mV written where V are meant"},
                            Thousand{"sensitivity_mV_per_g = 0.0196133", "sensitivity_mV_per_g",
                                     "the factor is 1000: a value in V written where mV are meant"}}) {
    Trial x;
    x.edit(vpu + "\n", std::string(k.key_and_value) + "\n");
    r = x.run("analyze");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("change [[channel]] name=\"coupler_t\" " + std::string(k.key)), std::string::npos)
        << "the key the manifest has: " << k.key_and_value << ": " << r.err;
    EXPECT_NE(r.err.find(k.told), std::string::npos) << k.key_and_value << ": " << r.err;
  }
}

// TOML slips: the error says what to type, not only the parser's words.
TEST(SetupMistakes, TomlSlipsAreTranslatedIntoWhatToType) {
  struct Slip {
    const char* pattern;
    const char* slip;
    const char* told;
  };
  for (const Slip& s : {Slip{R"(crank_direction = "ccw")", "crank_direction = ccw", "write crank_direction = \"ccw\""},
                        Slip{"ac_coupled = true", "ac_coupled = yes", "write ac_coupled = true"},
                        Slip{"full_scale_V = 10", "full_scale_V = 10 V", "write full_scale_V = 10 (a number alone"}}) {
    Trial t;
    t.edit(s.pattern, s.slip);
    const testing::CommandResult r = t.run("acquire");
    EXPECT_EQ(r.status, 2) << s.slip;
    EXPECT_NE(r.err.find(s.told), std::string::npos) << s.slip << ": " << r.err;
    EXPECT_NE(r.err.find(t.manifest.string() + ":"), std::string::npos) << "names the file and line: " << r.err;
  }
}

}  // namespace
}  // namespace fourbar
