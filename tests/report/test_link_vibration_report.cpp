// `fourbar report` on a rig file with the links' modal data: the
// link-vibration check (compare/link_vibration.hpp) runs the elastic-link
// reference (report/elastic_reference.hpp). On a recording made by another
// model (the three-mode model's rigid links) it must not name a link
// vibration; without a contact stiffness it says what to give; a bad
// stiffness exits 2 naming the key.
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

using nlohmann::json;

/// A `[LINK.elastic]` table: the 25 × 4 mm steel bar of data/rigs/thesis_elastic.toml, two modes.
std::string elastic_table(const std::string& link) {
  return "\n[" + link + ".elastic]\nmodes = 2\nE_GPa = 210\ndensity_kg_m3 = 7850\nwidth_mm = 25.0\nthickness_mm = 4.0\n"
         "damping_ratios = [0.02, 0.015]\n";
}

const std::string kElasticLinks = elastic_table("coupler") + elastic_table("rocker");

const std::string kRigidLinkScene = R"(rig = "rig.toml"
model = "clearance"
crank_speed_rpm = 350
outputs = ["alpha3_rad_s2"]
[clearance]
radial_mm = 0.254
restitution = 0.5
tolerance = 1e-8
[recording]
sample_rate_hz = 8000
duration_s = 2.5
sample_format = "pcm24"
noise_snr_db = 40.0
seed = 12
[recording.pulse]
angle_deg = 0.0
)" + testing::sensor_toml("coupler_t", "coupler_tangential", 154.5);

const std::string kShortTheory = "[theory]\nrestitution = 0.5\nwarmup_revolutions = 4\naveraged_revolutions = 8\n";

class LinkVibrationReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    dir_->write("make/rig.toml", testing::thesis_rig_toml() + kElasticLinks);
    dir_->write("make/rec.toml", kRigidLinkScene);
    std::filesystem::create_directories(dir_->path() / "session");
    const auto r = testing::record_virtual(dir_->path() / "make" / "rec.toml", dir_->path() / "session" / "rec.flac");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { delete dir_; }

  static testing::CommandResult report(const std::string& session_toml, const std::string& name) {
    dir_->write("session/session.toml", session_toml);
    return testing::run_fourbar("report " + (dir_->path() / "session").string() + " --out " +
                                (dir_->path() / ("out_" + name) / "report.html").string() + " --no-cache");
  }
  static json family(const std::string& name) {
    std::ifstream in(dir_->path() / ("out_" + name) / "summary.json");
    const json s = json::parse(in);
    return s["recordings"][0]["model_family"];
  }
  static testing::TempDir* dir_;
};
testing::TempDir* LinkVibrationReport::dir_ = nullptr;

TEST_F(LinkVibrationReport, WithoutAStiffnessTheCheckSaysWhatToGive) {
  const auto r = report(kShortTheory, "no_stiffness");
  ASSERT_EQ(r.status, 0) << r.err;
  const json f = family("no_stiffness");
  ASSERT_TRUE(f.contains("link_vibration")) << f.dump();
  EXPECT_FALSE(f["link_vibration"]["checked"].get<bool>());
  const std::string why = f["link_vibration"]["not_checked"];
  EXPECT_NE(why.find("[model_family] contact_stiffness_N_per_m_n"), std::string::npos) << why;
  // … and the verdict says so, not only summary.json's record.
  std::ifstream in(dir_->path() / "out_no_stiffness" / "summary.json");
  const json s = json::parse(in);
  const std::string verdict = s["recordings"][0].dump();
  EXPECT_NE(verdict.find("their vibration was not checked"), std::string::npos) << verdict;
  // … and does not call the family good: the resonance test alone misses a ringing link.
  EXPECT_EQ(verdict.find("\"holds\""), std::string::npos) << verdict;
  EXPECT_NE(verdict.find("not confirmed: link vibration not checked"), std::string::npos) << verdict;
}

TEST_F(LinkVibrationReport, RigidLinkRecordingIsNotCalledVibrating) {
  const auto r = report(kShortTheory + "[model_family]\ncontact_stiffness_N_per_m_n = 1e10\n", "stiffness");
  ASSERT_EQ(r.status, 0) << r.err;
  const json f = family("stiffness");
  ASSERT_TRUE(f.contains("link_vibration")) << f.dump();
  const json& v = f["link_vibration"];
  // The reference ran: its per-band energies are written either way.
  ASSERT_TRUE(v.contains("elastic_band_ms")) << v.dump();
  EXPECT_EQ(v["elastic_band_ms"].size(), f["bands"].size());
  if (v["checked"].get<bool>()) {
    EXPECT_FALSE(v["present"].get<bool>()) << v.dump();
    EXPECT_LT(v["position"].get<double>(), 0.5);
    // Of the rig's two modes per link, the one the check can see (614 Hz;
    // the second, 2456 Hz, lies above twice the checked range's top).
    EXPECT_NE(v["reference"].get<std::string>().find("coupler 1 mode (61"), std::string::npos) << v["reference"];
  }
  for (const json& u : f["unmodelled"]) EXPECT_NE(u["kind"], "link vibration") << u.dump();
}

TEST_F(LinkVibrationReport, BadStiffnessExitsTwoNamingTheKey) {
  const auto r = report(kShortTheory + "[model_family]\ncontact_stiffness_N_per_m_n = -1\n", "bad");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("contact_stiffness_N_per_m_n"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fourbar
