// `fourbar report` with the compliant contact model as the session's theory
// ([theory] model = "compliant"): a small virtual-rig session is compared
// with it end to end, and its keys are checked at the boundary (exit 2
// naming the key; a recording whose rig has no bearing to compute the
// stiffness from fails naming the key); fit refuses such a session.
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

const std::string kScene = R"(rig = "rig.toml"
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
noise_snr_db = 50.0
seed = 11
[recording.pulse]
angle_deg = 0.0
)" + testing::sensor_toml("coupler_t", "coupler_tangential", 300.0);

class CompliantTheory : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    dir_->write("make/rig.toml", testing::thesis_rig_toml());
    dir_->write("make/rec.toml", kScene);
    std::filesystem::create_directories(dir_->path() / "session");
    const auto r = testing::record_virtual(dir_->path() / "make" / "rec.toml", dir_->path() / "session" / "rec.flac");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { delete dir_; }

  /// `fourbar report` on the session with this session.toml, into out_NAME.
  static testing::CommandResult report(const std::string& session_toml, const std::string& name) {
    dir_->write("session/session.toml", session_toml);
    return testing::run_fourbar("report " + (dir_->path() / "session").string() + " --out " +
                                (dir_->path() / ("out_" + name) / "report.html").string());
  }
  static json summary(const std::string& name) {
    std::ifstream in(dir_->path() / ("out_" + name) / "summary.json");
    return json::parse(in);
  }
  static testing::TempDir* dir_;
};
testing::TempDir* CompliantTheory::dir_ = nullptr;

TEST_F(CompliantTheory, ReportUsesTheCompliantModel) {
  const auto r = report(R"([theory]
model = "compliant"
restitution = 0.5
contact_stiffness_N_per_m_n = 1e9
damping = "hunt-crossley"
warmup_revolutions = 2
averaged_revolutions = 3
)",
                        "ok");
  ASSERT_EQ(r.status, 0) << r.err;
  const json s = summary("ok");
  ASSERT_EQ(s["recordings"].size(), 1u);
  const json& rec = s["recordings"][0];
  ASSERT_EQ(rec["status"], "ok") << rec.dump();
  const json& th = rec["theory"];
  EXPECT_EQ(th["settings"]["model"], "compliant");
  EXPECT_EQ(th["settings"]["damping"], "hunt-crossley");
  EXPECT_EQ(th["settings"]["contact_stiffness_N_per_m_n"], 1e9);
  // The pin went into the wall (K = 1e9 at 350 rpm: a few per cent of ξ); the energy balance holds.
  EXPECT_GT(th["max_penetration_rel"].get<double>(), 1e-3);
  EXPECT_LT(th["energy_residual_rel"].get<double>(), 1e-6);
  EXPECT_EQ(th["severity"]["impacts_by_rev"].size(), 3u);

  // The same session with the three-mode theory: other settings, no penetration.
  ASSERT_EQ(report("[theory]\nrestitution = 0.5\nwarmup_revolutions = 2\naveraged_revolutions = 3\n", "three").status, 0);
  const json three = summary("three");
  const json& th3 = three["recordings"][0]["theory"];
  EXPECT_FALSE(th3["settings"].contains("model"));
  EXPECT_LT(th3["max_penetration_rel"].get<double>(), 1e-6);
}

TEST_F(CompliantTheory, BadKeysExit2NamingTheKey) {
  struct Case {
    const char* toml;
    const char* key;
  };
  const Case cases[] = {
      {"[theory]\nmodel = \"compliant\"\ncontact_stiffness_N_per_m_n = -1\n", "contact_stiffness_N_per_m_n"},
      {"[theory]\nmodel = \"compliant\"\ncontact_stiffness_N_per_m_n = 1e9\ncontact = \"rough\"\n", "contact"},
      {"[theory]\ndamping = \"flores\"\n", "damping"},
      {"[theory]\nmodel = \"rigid\"\n", "model"},
      {"[theory]\nmodel = \"compliant\"\ncontact_exponent = 5\n", "contact_exponent"},
      {"[theory]\nmodel = \"compliant\"\nrestitution = 0.001\n", "restitution"},
      {"[theory]\nmodel = \"compliant\"\n[[recording]]\nfile = \"rec.flac\"\nfriction_slip_speed_mm_s = 0.01\n",
       "friction_slip_speed_mm_s"},
  };
  int i = 0;
  for (const Case& c : cases) {
    const auto r = report(c.toml, "bad" + std::to_string(i++));
    EXPECT_EQ(r.status, 2) << c.toml << r.err;
    EXPECT_EQ(r.err.rfind("fourbar: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("session.toml"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(std::string(c.key) + "'"), std::string::npos) << c.toml << r.err;
  }
}

TEST_F(CompliantTheory, NoStiffnessAndNoBearingFailsTheRecordingNamingTheKey) {
  // The thesis rig file has no bearing length or moduli to compute K from.
  const auto r = report("[theory]\nmodel = \"compliant\"\nwarmup_revolutions = 0\naveraged_revolutions = 1\n", "nok");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("contact_stiffness_N_per_m_n"), std::string::npos) << r.err;
  const json s = summary("nok");
  EXPECT_EQ(s["recordings"][0]["error_kind"], "input");
  EXPECT_NE(s["recordings"][0]["error"].get<std::string>().find("session.toml [theory]"), std::string::npos);
}

TEST_F(CompliantTheory, FitRefusesACompliantTheory) {
  // fit varies the three-mode model's e and μ: it must not fit a session whose theory is another model.
  dir_->write("session/session.toml", "[theory]\nmodel = \"compliant\"\ncontact_stiffness_N_per_m_n = 1e9\n");
  const auto r = testing::run_fourbar("fit " + (dir_->path() / "session").string() + " --out " +
                                      (dir_->path() / "fit_out").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("model = \"compliant\""), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_->path() / "fit_out" / "fit.json"));
}

}  // namespace
}  // namespace fourbar
