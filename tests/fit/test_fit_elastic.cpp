// `fourbar fit --model elastic` (the linkage model with the rig's elastic
// coupler and rocker as the fitted theory) and the fit's bad input of issue
// 28: a band limit above a recording's Nyquist frequency, and an elastic fit
// on a rig without modal data or a contact stiffness — exit 2 naming the
// option or the rig file, the value and the fix, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_rig_scene.hpp"

namespace fourbar {
namespace {

/// One recording of the three-mode model (e = 0.5, smooth) on RIG at 350 rpm,
/// 0.254 mm, 12.8 kHz, 12 turns at 30 dB: something with impacts to fit.
void write_session(testing::TempDir& dir, const std::string& rig) {
  dir.write("make/rec.toml", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/" + rig + "\"\nmodel = \"clearance\"\n" +
                                 R"(crank_speed_rpm = 350
outputs = ["alpha3_rad_s2"]
[clearance]
radial_mm = 0.254
restitution = 0.5
contact = "smooth"
[recording]
sample_rate_hz = 12800
revolutions = 12
noise_snr_db = 30.0
seed = 11
[recording.pulse]
angle_deg = 0.0
)" + testing::tangential_sensors_toml(289.0, 292.0));
  const auto made = testing::record_virtual(dir.path() / "make" / "rec.toml", dir.path() / "session" / "rec.flac");
  ASSERT_EQ(made.status, 0) << made.err;
  dir.write("session/session.toml", "[theory]\nrestitution = 0.9\ncontact = \"smooth\"\n");
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class FitBadInput : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    rigid_ = new testing::TempDir;
    write_session(*rigid_, "thesis.toml");
  }
  static void TearDownTestSuite() { delete rigid_; }
  static testing::TempDir* rigid_;
};
testing::TempDir* FitBadInput::rigid_ = nullptr;

TEST_F(FitBadInput, BandTopAboveNyquistNamesOptionValueRateAndFix) {
  const auto out = rigid_->path() / "out_band";
  const auto r = testing::run_fourbar("fit " + (rigid_->path() / "session").string() + " --band-top-hz 7000 --out " +
                                      out.string());
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_TRUE(has(r.err, "fourbar: ")) << r.err;
  EXPECT_TRUE(has(r.err, "--band-top-hz 7000")) << r.err;
  EXPECT_TRUE(has(r.err, "rec.flac")) << r.err;
  EXPECT_TRUE(has(r.err, "sample rate 12800 Hz")) << r.err;
  EXPECT_TRUE(has(r.err, "at most 6400")) << r.err;  // the fix
  EXPECT_FALSE(std::filesystem::exists(out / "fit.json"));
}

TEST_F(FitBadInput, ElasticModelOnARigWithoutModalDataNamesTheRigKeysAndFix) {
  const auto out = rigid_->path() / "out_elastic";
  const auto r = testing::run_fourbar("fit " + (rigid_->path() / "session").string() +
                                      " --model elastic --contact-stiffness 1e10 --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_TRUE(has(r.err, "fourbar: ")) << r.err;
  EXPECT_TRUE(has(r.err, "data/rigs/thesis.toml")) << r.err;  // the rig file
  EXPECT_TRUE(has(r.err, "[coupler.elastic]")) << r.err;       // the missing keys
  EXPECT_TRUE(has(r.err, "[rocker.elastic]")) << r.err;
  EXPECT_TRUE(has(r.err, "thesis_elastic.toml")) << r.err;     // the fix: an example
  EXPECT_TRUE(has(r.err, "leave out --model elastic")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "fit.json"));
  const auto m = testing::run_fourbar("fit " + (rigid_->path() / "session").string() + " --model flexible");
  EXPECT_EQ(m.status, 2) << m.err;
  EXPECT_TRUE(has(m.err, "--model 'flexible'")) << m.err;
  const auto k = testing::run_fourbar("fit " + (rigid_->path() / "session").string() + " --elastic-modes 2");
  EXPECT_EQ(k.status, 2) << k.err;
  EXPECT_TRUE(has(k.err, "add --model elastic")) << k.err;
  // The orbit scan searches the three-mode model's turn map: refused with the elastic model, by name.
  const auto s = testing::run_fourbar("fit " + (rigid_->path() / "session").string() + " --model elastic --orbit-scan");
  EXPECT_EQ(s.status, 2) << s.err;
  EXPECT_TRUE(has(s.err, "--orbit-scan")) << s.err;
}

// The elastic fit itself, kept small (1 mode per link, 2 + 8 turns per
// simulation, e only): it runs, writes the model it fitted with its
// settings, and the statistics it compared are the three-mode fit's
// (spread and band energy of α3 and α4 at the sensors).
TEST(FitElastic, RunsAndWritesTheModelItFitted) {
  testing::TempDir dir;
  write_session(dir, "thesis_elastic.toml");
  // Without a stiffness: the rig's bearing has no keys for one.
  const auto k = testing::run_fourbar("fit " + (dir.path() / "session").string() + " --model elastic -q");
  EXPECT_EQ(k.status, 2) << k.out << k.err;
  EXPECT_TRUE(has(k.err, "thesis_elastic.toml")) << k.err;
  EXPECT_TRUE(has(k.err, "--contact-stiffness")) << k.err;
  const auto big = testing::run_fourbar("fit " + (dir.path() / "session").string() +
                                        " --model elastic --contact-stiffness 1e10 --elastic-modes 5");
  EXPECT_EQ(big.status, 2) << big.err;

  const auto out = dir.path() / "fit";
  const auto r = testing::run_fourbar("fit " + (dir.path() / "session").string() +
                                      " --model elastic --elastic-modes 1 --contact-stiffness 1e10 --smooth --turns 8 "
                                      "--warmup 2 -q --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  std::ifstream in(out / "fit.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["model"], "elastic") << j.dump(1);
  EXPECT_EQ(j["elastic_modes"], 1);
  EXPECT_DOUBLE_EQ(j["contact_stiffness_N_per_m_1_5"].get<double>(), 1e10);
  EXPECT_EQ(j["turns_per_simulation"], 10);
  const auto& e = j["parameters"]["restitution"];
  EXPECT_GE(e["value"].get<double>(), 0.05);  // the elastic model's box starts at 0.05 (e = 0: infinite damping)
  EXPECT_LE(e["value"].get<double>(), 1.0);
  EXPECT_LE(e["low"].get<double>(), e["value"].get<double>());
  EXPECT_GE(e["high"].get<double>(), e["value"].get<double>());
  ASSERT_EQ(j["recordings"].size(), 1u);
  // Both links' spread and band energy compared, as in the three-mode fit.
  EXPECT_EQ(j["terms"], 4) << j.dump(1);
  EXPECT_GT(j["chi2"].get<double>(), 0.0);
  EXPECT_LT(j["chi2"].get<double>(), 1e11) << "a simulation failed: " << j.dump(1);
  EXPECT_GT(j["simulations"].get<int>(), 20);
  // The spectral model-family check ran against the elastic model itself
  // (fit/family_judgement.hpp elastic_family_check_at), not the three-mode one.
  ASSERT_TRUE(j["model_family"].contains("spectral_check")) << j["model_family"].dump(1);
  EXPECT_EQ(j["model_family"]["spectral_check"]["model"], "elastic");
  EXPECT_EQ(j["model_family"]["spectral_check"]["recordings"], 1);
  for (const auto& n : j["notes"]) EXPECT_FALSE(has(n.get<std::string>(), "not run with --model elastic")) << n;

  // The three-mode fit of the same session checks against the three-mode
  // model; the rig gives no stiffness for the elastic-link reference, so it
  // says that the links' vibration was not checked.
  const auto out3 = dir.path() / "fit3";
  const auto r3 = testing::run_fourbar("fit " + (dir.path() / "session").string() + " --smooth --turns 8 --warmup 2 -q --out " +
                                       out3.string());
  ASSERT_EQ(r3.status, 0) << r3.out << r3.err;
  std::ifstream in3(out3 / "fit.json");
  const nlohmann::json j3 = nlohmann::json::parse(in3);
  EXPECT_EQ(j3["model_family"]["spectral_check"]["model"], "three-mode") << j3["model_family"].dump(1);
  bool noted = false;
  for (const auto& n : j3["notes"]) noted = noted || has(n.get<std::string>(), "vibration was not checked");
  EXPECT_TRUE(noted) << j3["notes"].dump(1);
}

}  // namespace
}  // namespace fourbar
