// `fourbar report` with a `fourbar fit` result: a virtual-rig session made
// with known contact parameters and a wrong prior in session.toml (e = 1,
// smooth, the thesis's setting). The fit.json is written here with the
// virtual rig's truth as the fitted values (what a perfect fit gives: this
// tests the report's use of a fit, bench/fit_recovery.sh tests the fit), so
// that the report's fitted theory is the model that made the recording: its
// magnification factor a must be closer to 1 than the prior's, and the
// section must show the numbers of fit.json. Found in SESSION_DIR/fit/ without
// --fit; left out with --no-fit; a broken fit.json is bad input naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "support/headless_browser.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_rig_scene.hpp"

namespace fourbar {
namespace {

using nlohmann::json;

constexpr double kTrueRestitution = 0.0;

std::string scene(double rpm, int seed) {
  return "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nmodel = \"clearance\"\ncrank_speed_rpm = " +
         std::to_string(rpm) + R"(
outputs = ["alpha3_rad_s2"]
[clearance]
radial_mm = 0.254
restitution = 0.0
contact = "smooth"
tolerance = 1e-8
[recording]
sample_rate_hz = 6400
revolutions = 16
warmup_revolutions = 20
noise_snr_db = 40.0
seed = )" + std::to_string(seed) + R"(
[recording.pulse]
angle_deg = 0.0
)" + testing::sensor_toml("coupler_t", "coupler_tangential", 289.0);
}

/// A fit.json as `fourbar fit` writes it (the keys the report reads, and more).
json fit_json(const std::vector<std::string>& files) {
  json recs = json::array();
  for (const auto& f : files)
    recs.push_back({{"file", f}, {"chi2", 2.0}, {"terms", 2}, {"chi2_per_term", 1.0}, {"chi2_prior", 90.0},
                    {"magnification_fitted", 1.05}, {"magnification_fitted_standard_error", 0.21},
                    {"magnification_prior", 3.5}, {"magnification_prior_standard_error", 0.7}});
  return {{"parameters",
           {{"restitution", {{"value", kTrueRestitution}, {"low", 0.0}, {"high", 0.137}, {"identifiable", true},
                             {"profile", {{0.0, 2.1}, {0.25, 9.0}, {0.5, 30.0}, {1.0, 180.0}}}}},
            {"contact", {{"value", "smooth"}}}}},
          {"fitted", {{"restitution", kTrueRestitution}, {"contact", "smooth"}}},
          {"prior", {{"restitution", 1.0}, {"contact", "smooth"}}},
          {"chi2", 2.0 * static_cast<double>(files.size())},
          {"chi2_prior", 90.0 * static_cast<double>(files.size())},
          {"terms", 2 * static_cast<int>(files.size())},
          {"chi2_per_term", 1.0},
          {"recordings", recs},
          {"interval_delta_chi2", 2.83},
          {"evaluations", 12},
          {"simulations", 24},
          {"turns_per_simulation", 52},
          {"seconds", 7.5},
          {"notes", json::array({"a note of the fit"})},
          {"command_line", "fourbar fit session --smooth"}};
}

class ReportFit : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    const auto& d = dir_->path();
    dir_->write("make/a.toml", scene(350, 11));
    const auto r = testing::record_virtual(d / "make" / "a.toml", d / "session" / "a.flac");
    ASSERT_EQ(r.status, 0) << r.err;
    dir_->write("session/session.toml", "[theory]\nrestitution = 1.0\ncontact = \"smooth\"\naveraged_revolutions = 16\n");
    dir_->write("fit_elsewhere/fit.json", fit_json({"a.flac"}).dump(2));
    run_ = new testing::CommandResult(testing::run_fourbar("report " + (d / "session").string() + " -q --fit " +
                                                           (d / "fit_elsewhere" / "fit.json").string() + " --out " +
                                                           (d / "out" / "report.html").string()));
    std::ifstream in(d / "out" / "summary.json");
    summary_ = new json(json::parse(in));
    html_ = new std::string(testing::read_file(d / "out" / "report.html"));
  }
  static void TearDownTestSuite() {
    delete html_;
    delete summary_;
    delete run_;
    delete dir_;
  }
  static testing::TempDir* dir_;
  static testing::CommandResult* run_;
  static json* summary_;
  static std::string* html_;
};
testing::TempDir* ReportFit::dir_ = nullptr;
testing::CommandResult* ReportFit::run_ = nullptr;
json* ReportFit::summary_ = nullptr;
std::string* ReportFit::html_ = nullptr;

TEST_F(ReportFit, SectionShowsTheNumbersOfFitJson) {
  ASSERT_EQ(run_->status, 0) << run_->err;
  EXPECT_NE(run_->out.find("fitted theory from"), std::string::npos) << run_->out;
  const json& fit = (*summary_)["fit"];
  const json& p = fit["session_fit"]["parameters"]["restitution"];
  EXPECT_EQ(p["value"].get<double>(), kTrueRestitution);
  EXPECT_EQ(p["low"].get<double>(), 0.0);
  EXPECT_EQ(p["high"].get<double>(), 0.137);
  EXPECT_EQ(fit["session_fit"]["notes"][0], "a note of the fit");
  EXPECT_NE(html_->find("<section id=\"fit\"><h2>Fitted bearing parameters</h2>"), std::string::npos);
  EXPECT_NE(html_->find("<td class=\"l\">restitution</td><td>0</td><td>[0, 0.137]</td><td class=\"l\">yes</td><td>1</td>"),
            std::string::npos);
  EXPECT_NE(html_->find("a note of the fit"), std::string::npos);
  EXPECT_NE(html_->find("id=\"fit-profile-restitution\""), std::string::npos);
  EXPECT_NE(html_->find("id=\"fit-r0\""), std::string::npos);
  // The fit's a with its standard error, prior → fitted.
  EXPECT_NE(html_->find("3.5 ± 0.7 → <b>1.05 ± 0.21</b>"), std::string::npos);
  // The theory at the prior is the session's; the fitted one the fit's.
  const json& rec = (*summary_)["recordings"][0];
  EXPECT_EQ(rec["theory"]["settings"]["restitution"].get<double>(), 1.0);
  EXPECT_EQ(rec["fitted_theory"]["settings"]["restitution"].get<double>(), kTrueRestitution);
  EXPECT_EQ(rec["fitted_theory"]["settings"]["averaged_revolutions"], rec["theory"]["settings"]["averaged_revolutions"]);
}

TEST_F(ReportFit, FittedTheoryIsCloserToTheMeasurementThanThePrior) {
  ASSERT_EQ(run_->status, 0) << run_->err;
  const json& row = (*summary_)["fit"]["recordings"][0];
  const double a_prior = row["prior"]["a"].get<double>(), a_fit = row["fitted"]["a"].get<double>();
  // The model that made the recording: a near 1; e = 1 is more violent.
  EXPECT_LT(std::abs(std::log(a_fit)), std::abs(std::log(a_prior))) << "a fitted " << a_fit << ", prior " << a_prior;
  EXPECT_LT(row["fitted"]["rms_difference"].get<double>(), row["prior"]["rms_difference"].get<double>());
  // The numbers of the table are those of the records they come from.
  const json& rec = (*summary_)["recordings"][0];
  EXPECT_EQ(row["fitted"]["a"], rec["fitted_theory"]["metrics"]["alpha3_rad_s2"]["magnification"]["time_domain"]);
  EXPECT_EQ(row["prior"]["a"], rec["metrics"]["alpha3_rad_s2"]["magnification"]["time_domain"]);
}

TEST_F(ReportFit, PageWithTheFitDrawsInHeadlessChromium) {
  const auto chromium = testing::chromium_binary();
  if (!chromium) GTEST_SKIP() << "chromium is not installed (Debian package chromium; scripts/install-deps.sh installs it)";
  const auto run = testing::run_chromium(*chromium, dir_->path() / "out" / "report.html", "--dump-dom");
  ASSERT_EQ(run.status, 0) << run.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(run.out, m, std::regex(R"re(<body[^>]*data-js-errors="(\d+)")re")));
  EXPECT_EQ(m[1], "0");
  ASSERT_TRUE(std::regex_search(run.out, m, std::regex(R"re(<body[^>]*data-charts-drawn="(\d+)")re")));
  // One recording with the coupler only (α3, ω3, orders, factor, spectrum) + 4
  // session charts + the profile along e + the fit overlay.
  EXPECT_EQ(std::stoi(m[1]), 5 + 4 + 2);
  EXPECT_NE(run.out.find("id=\"fit-r0\" data-drawn"), std::string::npos);
  EXPECT_NE(run.out.find("id=\"fit-profile-restitution\" data-drawn"), std::string::npos);
}

TEST_F(ReportFit, FoundInTheSessionFolderAndLeftOutWithNoFit) {
  const auto& d = dir_->path();
  testing::TempDir copy;
  std::filesystem::copy(d / "session", copy.path() / "session");
  copy.write("session/fit/fit.json", fit_json({"a.flac"}).dump());
  const auto found = testing::run_fourbar("report " + (copy.path() / "session").string() + " -q --out " +
                                          (copy.path() / "out" / "report.html").string());
  ASSERT_EQ(found.status, 0) << found.err;
  EXPECT_NE(testing::read_file(copy.path() / "out" / "report.html").find("<section id=\"fit\">"), std::string::npos);
  const auto left = testing::run_fourbar("report " + (copy.path() / "session").string() + " -q --no-fit --out " +
                                         (copy.path() / "out2" / "report.html").string());
  ASSERT_EQ(left.status, 0) << left.err;
  EXPECT_EQ(testing::read_file(copy.path() / "out2" / "report.html").find("<section id=\"fit\">"), std::string::npos);
}

TEST_F(ReportFit, AnotherSessionsFitIsNamedInAWarning) {
  const auto& d = dir_->path();
  dir_->write("other/fit.json", fit_json({"b.flac"}).dump());
  const auto r = testing::run_fourbar("report " + (d / "session").string() + " -q --fit " + (d / "other" / "fit.json").string() +
                                      " --out " + (d / "out_other" / "report.html").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("b.flac, which is not a recording of this session"), std::string::npos) << r.err;
  EXPECT_NE(testing::read_file(d / "out_other" / "report.html").find("which is not a recording of this session"),
            std::string::npos);
}

TEST_F(ReportFit, BrokenFitJsonIsBadInputNamingTheKey) {
  const auto& d = dir_->path();
  json broken = fit_json({"a.flac"});
  broken["fitted"].erase("restitution");
  dir_->write("broken/fit.json", broken.dump());
  const auto r = testing::run_fourbar("report " + (d / "session").string() + " -q --fit " + (d / "broken" / "fit.json").string() +
                                      " --out " + (d / "out_broken" / "report.html").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("fourbar: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("fitted.restitution"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(d / "out_broken" / "report.html"));
}

}  // namespace
}  // namespace fourbar
