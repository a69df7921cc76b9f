// The report page in a real browser (Debian's headless Chromium): no script
// errors, no blocked requests, every chart drew data; and the page holds no
// reference to anything outside itself.
#include <gtest/gtest.h>

#include <regex>

#include "common/atomic_output.hpp"
#include "common/units.hpp"
#include "compare/matched_theory.hpp"
#include "compare/recording_comparison.hpp"
#include "report/comparison_record.hpp"
#include "report/html_report.hpp"
#include "report/html_text.hpp"
#include "report/session_report.hpp"
#include "report/quantity_names.hpp"
#include "support/headless_browser.hpp"

namespace fourbar {
namespace {

using nlohmann::json;

/// A session of two recordings: the "measurement" is an independent run of
/// the clearance model (another warm-up), so all plots have real content.
json synthetic_session() {
  const Rig rig = thesis_rig();
  json records = json::array();
  int i = 0;
  for (double rpm : {250.0, 350.0}) {
    const CrankGrid grid{360, 0.0, 1.0};
    const double w = units::rpm_to_rad_s(rpm);
    TheorySettings s;
    s.warmup_revolutions = 3, s.averaged_revolutions = 6, s.max_order = 30;
    const MatchedTheory theory = simulate_matched_theory(rig, 0.254e-3, w, grid, s);
    s.warmup_revolutions = 7;
    const MatchedTheory other = simulate_matched_theory(rig, 0.254e-3, w, grid, s);
    MeasuredResponse m;
    m.grid = grid;
    m.crank_speed_rad_s = w;
    for (LinkQuantity q : kLinkQuantities) {
      const TheorySeries& o = other.series[index_of(q)];
      m.series[index_of(q)] = AngleSeries{o.clearance.mean, o.clearance.std, o.clearance_revolutions, 6};
    }
    json r = comparison_record(m, theory, compare_response(m, theory));
    r["name"] = "synthetic_" + std::to_string(static_cast<int>(rpm)) + ".flac";
    r["files"] = json::array({{{"role", "recording"}, {"path", r["name"]}, {"sha256", std::string(64, 'a')}, {"bytes", 1}}});
    r["spectra"] = {{"alpha3_rad_s2", {{"order", {1, 2, 3}}, {"amplitude", {10.0, 5.0, 1.0}}}}};
    records.push_back(r);
    ++i;
  }
  records.push_back({{"name", "broken.wav"}, {"status", "failed"}, {"error_kind", "input"},
                     {"error", "broken.wav: not a recording </script><b>"}, {"files", json::array()}});
  return {{"tool", "fourbar"}, {"version", "test"}, {"command", "fourbar report <test>"}, {"session_dir", "synthetic"},
          {"title", "Synthetic session"}, {"notes", ""}, {"settings", {{"theory", theory_settings_json({})}}},
          {"settings_file", nullptr}, {"recordings", records}, {"recordings_failed", 1},
          {"orphan_manifests", json::array()}, {"severity", severity_record(records)}};
}

TEST(HtmlReport, SelfContainedAndEscaped) {
  const std::string html = render_html_report(synthetic_session());
  // Nothing to fetch: no src/href to another document, no url(), no @import.
  EXPECT_FALSE(std::regex_search(html, std::regex(R"re((src|href)\s*=\s*["']?(https?:|//|file:))re", std::regex::icase)));
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("sourceMappingURL"), std::string::npos);
  // Text from the data cannot close the script or inject markup.
  EXPECT_EQ(html.find("not a recording </script><b>"), std::string::npos);
  EXPECT_NE(html.find("not a recording &lt;/script&gt;&lt;b&gt;"), std::string::npos);
  EXPECT_NE(html.find("Dygraph"), std::string::npos);   // the library is inlined
  EXPECT_NE(html.find("@media print"), std::string::npos);
  // Tables and charts name the quantities as a person reads them, from one table.
  EXPECT_NE(html.find("<td class=\"l\">coupler angular acceleration α3 (rad/s²)</td>"), std::string::npos);
  EXPECT_NE(html.find("<h3>rocker angular velocity ω4 (rad/s): measured, clearance model, nominal</h3>"), std::string::npos);
  EXPECT_EQ(html.find(">alpha3_rad_s2"), std::string::npos);
  EXPECT_NE(html.find("\"names\":{"), std::string::npos);  // the same table for the scripts
}

// The page's data is put together from each recording's part (made by the
// worker that made the recording) and the rest of the session: it must read
// back as the whole session, rounded, and the page must not depend on whether
// the session it is given still holds the recordings' bulk.
TEST(HtmlReport, DataAssembledFromRecordingPartsIsTheWholeSession) {
  const json session = synthetic_session();
  const std::string html = render_html_report(session);
  const std::string open = "<script id=\"report-data\" type=\"application/json\">";
  const std::size_t a = html.find(open);
  ASSERT_NE(a, std::string::npos);
  const std::size_t b = html.find("</script>", a);
  const json data = json::parse(html.substr(a + open.size(), b - a - open.size()));
  json expected = session;
  round_numbers(expected);
  expected["names"] = quantity_names_json();
  EXPECT_EQ(data, expected);
  ASSERT_TRUE(data["recordings"][0].contains("series"));  // the bulk is in the page

  std::vector<RecordingPage> pages;
  for (std::size_t i = 0; i < session["recordings"].size(); ++i)
    pages.push_back(render_recording_page(session["recordings"][i], i));
  const json light = summary_of(session);
  ASSERT_FALSE(light["recordings"][0].contains("series"));
  EXPECT_EQ(render_html_report(light, pages), html);
  pages.pop_back();
  EXPECT_THROW(render_html_report(light, pages), std::logic_error);
}

TEST(HtmlReport, QuantityNames) {
  EXPECT_EQ(quantity_label("alpha3_rad_s2"), "coupler angular acceleration α3 (rad/s²)");
  EXPECT_EQ(quantity_axis_label("omega4_rad_s"), "ω4 (rad/s)");
  EXPECT_EQ(quantity_label("impacts_per_rev"), "impacts per turn n");  // a count: no unit
  EXPECT_EQ(quantity_label("speed_rpm"), "crank speed (rpm)");
  EXPECT_EQ(quantity_label("something_new"), "something_new");         // unknown: shown as it is
  const nlohmann::json j = quantity_names_json();
  EXPECT_EQ(j["alpha4_rad_s2"]["label"], "rocker angular acceleration α4 (rad/s²)");
  EXPECT_EQ(j["alpha4_rad_s2"]["axis"], "α4 (rad/s²)");
  // Every quantity of a comparison record has a name.
  for (const char* k : {"alpha3_rad_s2", "omega3_rad_s", "alpha4_rad_s2", "omega4_rad_s"})
    EXPECT_NE(find_quantity_name(k), nullptr) << k;
}

TEST(HtmlReport, DrawsEveryChartInHeadlessChromium) {
  const auto chromium = testing::chromium_binary();
  if (!chromium) GTEST_SKIP() << "chromium is not installed (Debian package chromium; scripts/install-deps.sh installs it)";
  testing::TempDir dir;
  const auto page = dir.path() / "report.html";
  write_text_file(page, render_html_report(synthetic_session()));
  const testing::BrowserRun run = testing::run_chromium(*chromium, page, "--dump-dom");
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string& dom = run.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(dom, m, std::regex(R"re(<body[^>]*data-js-errors="(\d+)")re"))) << dom.substr(0, 2000);
  EXPECT_EQ(m[1], "0") << dom.substr(dom.find("js-errors"), 600);
  ASSERT_TRUE(std::regex_search(dom, m, std::regex(R"re(<body[^>]*data-charts-drawn="(\d+)")re"))) << "charts never finished";
  const int drawn = std::stoi(m[1]);
  // 2 recordings × (4 overlays + orders + factor + spectrum) + the 2 session
  // charts against crank speed (one clearance: none against clearance).
  EXPECT_EQ(drawn, 2 * 7 + 2);
  EXPECT_NE(dom.find("One clearance in this session"), std::string::npos);
  std::size_t charts = 0, with_data = 0;
  const std::regex chart_div(R"re(<div class="chart[^"]*" id="([^"]+)"([^>]*)>)re");
  for (auto it = std::sregex_iterator(dom.begin(), dom.end(), chart_div); it != std::sregex_iterator(); ++it) {
    ++charts;
    std::smatch d;
    const std::string attrs = (*it)[2];
    if (std::regex_search(attrs, d, std::regex(R"re(data-drawn="(\d+)")re")) && std::stoi(d[1]) > 0) ++with_data;
    else ADD_FAILURE() << "chart " << (*it)[1] << " drew no data";
  }
  EXPECT_EQ(charts, static_cast<std::size_t>(drawn));
  EXPECT_EQ(with_data, charts);
  EXPECT_EQ(run.err.find("Uncaught"), std::string::npos) << run.err;
  EXPECT_NE(dom.find("<canvas"), std::string::npos);
  // Axis titles from the name table; ω drawn as the deviation from nominal.
  EXPECT_NE(dom.find(">α3 (rad/s²)</div>"), std::string::npos);
  EXPECT_NE(dom.find(">ω3 − nominal (rad/s)</div>"), std::string::npos);
  EXPECT_NE(dom.find(">crank angle θ2 (deg)</div>"), std::string::npos);
  EXPECT_NE(dom.find("class=\"dot\""), std::string::npos);  // the polar impact plots have points

  // A screenshot to look at (kept in the test's working folder).
  const auto shot = std::filesystem::absolute("html_report_screenshot.png");
  std::filesystem::remove(shot);
  const testing::BrowserRun pic = testing::run_chromium(*chromium, page, "--screenshot=" + shot.string());
  ASSERT_EQ(pic.status, 0) << pic.err;
  ASSERT_TRUE(std::filesystem::exists(shot));
  EXPECT_GT(std::filesystem::file_size(shot), 20000u);  // a blank page is a few kB
}

}  // namespace
}  // namespace fourbar
