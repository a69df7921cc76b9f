// `fourbar fit` as a user runs it: a backwards box is bad input naming the
// option (exit 2, nothing written); a session of nominal recordings has no
// clearance effect above its noise and is not fitted (exit 1, said plainly).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

std::string nominal_scene(double rpm, int seed) {
  return "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nmodel = \"nominal\"\ncrank_speed_rpm = " +
         std::to_string(rpm) + R"(
outputs = ["alpha3_rad_s2"]
[recording]
sample_rate_hz = 12800
revolutions = 20
noise_snr_db = 30.0
seed = )" + std::to_string(seed) + R"(
[recording.pulse]
angle_deg = 0.0
[[recording.sensor]]
name = "coupler_t"
role = "coupler_tangential"
position_mm = 289.0
volts_per_unit = 0.002
[[recording.sensor]]
name = "rocker_t"
role = "rocker_tangential"
position_mm = 292.0
volts_per_unit = 0.002
)";
}

class FitCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    int seed = 1;
    for (double rpm : {250.0, 350.0}) {
      const std::string name = "nominal_" + std::to_string(static_cast<int>(rpm));
      dir_->write("make/" + name + ".toml", nominal_scene(rpm, seed++));
      // The manifest needs a clearance for the fit to get as far as the noise check.
      const auto r = testing::run_fourbar("virtual-rig " + (dir_->path() / "make" / (name + ".toml")).string() +
                                          " --no-truth --out " + (dir_->path() / "session" / (name + ".flac")).string());
      ASSERT_EQ(r.status, 0) << r.err;
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static testing::TempDir* dir_;
};
testing::TempDir* FitCommand::dir_ = nullptr;

TEST_F(FitCommand, BackwardsBoxIsBadInputNamingIt) {
  const auto out = dir_->path() / "out_box";
  const auto r = testing::run_fourbar("fit " + (dir_->path() / "session").string() + " --restitution 0.9:0.1 --out " +
                                      out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("fourbar: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--restitution"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "fit.json"));
  const auto m = testing::run_fourbar("fit " + (dir_->path() / "session").string() + " --friction 0.3");
  EXPECT_EQ(m.status, 2) << m.err;
  EXPECT_NE(m.err.find("LOW:HIGH"), std::string::npos) << m.err;
}

TEST_F(FitCommand, NominalRecordingsAreNotFitted) {
  const auto out = dir_->path() / "out_nominal";
  // The nominal scenes' manifests carry the rig's clearance (the model did not use it).
  const auto r = testing::run_fourbar("fit " + (dir_->path() / "session").string() + " -q --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("no clearance effect measurable above the noise floor"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "fit.json"));
}

// A small recovery (the full table is bench/fit_recovery.sh): one recording
// at the large clearance made with e = 0.2 (smooth), a wrong prior e = 0.95
// in session.toml; the e-only fit must find e well away from the prior, with
// the truth inside its interval, and a χ² far below the prior's.
TEST(FitRecovery, SmallSessionFindsRestitutionAwayFromWrongPrior) {
  testing::TempDir dir;
  dir.write("make/rec.toml", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nmodel = \"clearance\"\n"
            R"(crank_speed_rpm = 350
outputs = ["alpha3_rad_s2"]
[clearance]
radial_mm = 0.254
restitution = 0.2
contact = "smooth"
tolerance = 1e-8
[recording]
sample_rate_hz = 12800
revolutions = 16
noise_snr_db = 30.0
seed = 5
[recording.pulse]
angle_deg = 0.0
[[recording.sensor]]
name = "coupler_t"
role = "coupler_tangential"
position_mm = 289.0
volts_per_unit = 0.002
[[recording.sensor]]
name = "rocker_t"
role = "rocker_tangential"
position_mm = 292.0
volts_per_unit = 0.002
)");
  const auto made = testing::run_fourbar("virtual-rig " + (dir.path() / "make" / "rec.toml").string() +
                                         " --no-truth --out " + (dir.path() / "session" / "rec.flac").string());
  ASSERT_EQ(made.status, 0) << made.err;
  dir.write("session/session.toml", "[theory]\nrestitution = 0.95\ncontact = \"smooth\"\n");
  const auto out = dir.path() / "fit";
  const auto r = testing::run_fourbar("fit " + (dir.path() / "session").string() + " --smooth --turns 24 -q --out " +
                                      out.string());
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  std::ifstream in(out / "fit.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& e = j["parameters"]["restitution"];
  EXPECT_LE(e["low"].get<double>(), 0.2) << j.dump(1);
  EXPECT_GE(e["high"].get<double>(), 0.2) << j.dump(1);
  EXPECT_LT(e["high"].get<double>(), 0.8) << "the wrong prior 0.95 is not excluded: " << j.dump(1);
  EXPECT_LT(j["chi2"].get<double>(), 0.25 * j["chi2_prior"].get<double>()) << j.dump(1);
  EXPECT_EQ(j["recordings"].size(), 1u);
  EXPECT_GT(j["evaluations"].get<int>(), 10);
}

}  // namespace
}  // namespace fourbar
