// The three-mode fit's model-family check on a rig whose file gives the
// links' modes (fit/family_judgement.hpp family_check_at): the measurement
// placed between the linkage model with rigid and with elastic links
// (compare/link_vibration.hpp), as the report's verdict does. A recording of
// the linkage model with ringing links rejects the family ("link vibration");
// a recording of rigid links on the same rig does not; without a contact
// stiffness for the reference, fit.json notes that the links' vibration
// was not checked and which key to give.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_rig_scene.hpp"

namespace fourbar {
namespace {

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// 12 turns at 350 rpm, 0.254 mm, 12.8 kHz, 30 dB, mid-span tangential
/// sensors on data/rigs/thesis_elastic.toml: MOTION is the scene's model
/// line and its clearance table.
void write_vibration_session(testing::TempDir& dir, const std::string& motion, const std::string& session_toml) {
  dir.write("make/rec.toml", std::string("rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml\"\n") +
                                 R"(crank_speed_rpm = 350
outputs = ["alpha3_rad_s2"]
)" + motion + R"([recording]
sample_rate_hz = 12800
revolutions = 12
noise_snr_db = 30.0
seed = 11
[recording.pulse]
angle_deg = 0.0
)" + testing::tangential_sensors_toml(154.5, 150.0));
  const auto made = testing::record_virtual(dir.path() / "make" / "rec.toml", dir.path() / "session" / "rec.flac");
  ASSERT_EQ(made.status, 0) << made.err;
  dir.write("session/session.toml", session_toml);
}

const std::string kRinging = R"(model = "linkage"
[linkage]
coupler_rocker_radial_mm = 0.254
elastic_links = ["coupler", "rocker"]
elastic_modes = 1
restitution = 0.5
contact_stiffness_N_per_m_n = 1e10
tolerance = 1e-7
)";
const std::string kRigid = R"(model = "clearance"
[clearance]
radial_mm = 0.254
restitution = 0.5
contact = "smooth"
)";
const std::string kPrior = "[theory]\nrestitution = 0.9\ncontact = \"smooth\"\n";
const std::string kStiffness = "[model_family]\ncontact_stiffness_N_per_m_n = 1e10\n";

nlohmann::json fit_json_of(const testing::TempDir& dir) {
  const auto out = dir.path() / "fit";
  const auto r = testing::run_fourbar("fit " + (dir.path() / "session").string() + " --smooth --jobs 1 -q --out " + out.string());
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  std::ifstream in(out / "fit.json");
  return nlohmann::json::parse(in);
}

std::string reasons(const nlohmann::json& j) { return j["model_family"]["reasons"].dump(); }

TEST(FitLinkVibration, RingingLinksRejectTheThreeModeFamily) {
  testing::TempDir dir;
  write_vibration_session(dir, kRinging, kPrior + kStiffness);
  const nlohmann::json j = fit_json_of(dir);
  EXPECT_EQ(j["model_family"]["verdict"], "rejected") << j["model_family"].dump(1);
  EXPECT_TRUE(mentions(reasons(j), "link vibration")) << reasons(j);
  EXPECT_FALSE(j["parameters"]["restitution"]["identifiable"].get<bool>());
}

TEST(FitLinkVibration, RigidLinksOnTheSameRigAreNotCalledVibrating) {
  testing::TempDir dir;
  write_vibration_session(dir, kRigid, kPrior + kStiffness);
  const nlohmann::json j = fit_json_of(dir);
  EXPECT_FALSE(mentions(reasons(j), "link vibration")) << reasons(j);
  for (const auto& n : j["notes"]) EXPECT_FALSE(mentions(n.get<std::string>(), "vibration was not checked")) << n;
}

TEST(FitLinkVibration, WithoutAStiffnessTheFitSaysTheVibrationWasNotChecked) {
  testing::TempDir dir;
  write_vibration_session(dir, kRinging, kPrior);
  const nlohmann::json j = fit_json_of(dir);
  bool noted = false;
  for (const auto& n : j["notes"])
    noted = noted || (mentions(n.get<std::string>(), "vibration was not checked") &&
                      mentions(n.get<std::string>(), "[model_family] contact_stiffness_N_per_m_n"));
  EXPECT_TRUE(noted) << j["notes"].dump(1);
}

}  // namespace
}  // namespace fourbar
