#include "report/html_summary.hpp"

#include <string>

#include "report/html_blocks.hpp"
#include "report/html_text.hpp"
#include "report/html_verdict.hpp"
#include "report/setup_check_record.hpp"
#include "report/verdict_table.hpp"

namespace fourbar {

using nlohmann::json;

void summary_section(std::ostringstream& h, const json& data) {
  const json& recs = data["recordings"];
  const int failed = data["recordings_failed"];
  h << "<section id=\"summary\"><h2>Summary</h2>";
  verdict_summary_table(h, recs);
  for (const json& r : recs)
    if (is_analysed(r)) h << setup_check_html(r.value("setup_check", json::object()), r["name"]);
  h << "<p>" << recs.size() << (recs.size() == 1 ? " recording, " : " recordings, ")
    << (failed ? "<span class=\"failed\">" + std::to_string(failed) + " failed</span>" : std::string("all analysed"))
    << ". Theory: clearance model and nominal mechanism at each recording's measured mean crank speed and clearance. "
       "a = RMS(model − nominal) / RMS(measured − nominal) on α3 (thesis sec. 8.1): how many times more violent the model is "
       "than the measurement. The verdict judges by one a (its kind: scatter, spectral or time, docs/verdict.md); the "
       "other factors are diagnostics.</p><table class=\"summary\"><tr><th colspan=\"6\"></th><th colspan=\"6\" "
       "class=\"group\">diagnostics</th></tr><tr><th class=\"l\">recording</th><th class=\"l\">status</th>"
       "<th class=\"l\">a (verdict)</th><th>speed (rpm)</th><th>clearance (mm)</th><th>revolutions</th><th>a time</th>"
       "<th>a spectral</th><th>corr. α3 meas/model</th><th>n per turn</th><th>ΣF per turn (N·s)</th><th>I_n (N·s)</th></tr>";
  for (std::size_t i = 0; i < recs.size(); ++i) {
    const json& r = recs[i];
    h << "<tr><td class=\"l\"><span class=\"swatch\" data-rec=\"" << i << "\"></span><a href=\"#rec" << i << "\">"
      << html_escape(r["name"]) << "</a></td>";
    if (!is_analysed(r)) {
      h << "<td class=\"l failed\" colspan=\"11\">failed: " << html_escape(r["error"]) << "</td></tr>";
      continue;
    }
    const json m = r["metrics"].contains("alpha3_rad_s2") ? r["metrics"]["alpha3_rad_s2"] : json::object();
    auto mm = [&](const char* a, const char* b, const char* f) {
      return m.empty() ? std::string("–") : fmt(b ? m[a][b] : m[a], f);
    };
    const json& sv = r["theory"]["severity"];
    h << (r["status"] == "ok" ? "<td class=\"l ok\">ok" : "<td class=\"l failed\">check set-up") << "</td><td class=\"l num\">"
      << html_escape(verdict_a_text(r.value("verdict", json()))) << "</td><td>"
      << fmt(r["operating_point"]["speed_rpm"], "%.2f") << "</td><td>"
      << fmt(r["operating_point"]["clearance_mm"], "%.4g") << "</td><td>" << fmt(r["operating_point"]["revolutions_averaged"], "%.0f")
      << "</td><td>" << mm("magnification", "time_domain", "%.3g") << "</td><td>" << mm("magnification", "spectral", "%.3g")
      << "</td><td>" << mm("correlation_simulated", nullptr, "%.3f") << "</td><td>" << fmt(sv["impacts_per_rev"], "%.1f")
      << "</td><td>" << fmt(sv["sum_normal_impulse_per_rev_Ns"], "%.3g") << "</td><td>" << fmt(sv["impact_index_Ns"], "%.3g")
      << "</td></tr>";
  }
  h << "</table>";
  if (!data["orphan_manifests"].empty()) {
    h << "<p class=\"warn\">Manifests without a recording beside them (ignored):";
    for (const json& o : data["orphan_manifests"]) h << " " << html_escape(o);
    h << "</p>";
  }
  if (data.contains("other_files") && !data["other_files"].empty()) {
    h << "<p class=\"warn\">Files in the session folder that are neither a recording nor a manifest (ignored):";
    for (const json& o : data["other_files"]) h << " " << html_escape(o);
    h << "</p>";
  }
  h << "</section>";
}

void severity_section(std::ostringstream& h, const json& /*data*/) {
  h << "<section id=\"session\"><h2>Severity against clearance and crank speed</h2><p class=\"note\">Measured: RMS of the "
       "averaged α3 about the nominal response (thesis Figs 7.9–7.17). Clearance model: the same, and the impacts per turn n, "
       "the sum of normal impulses per turn ΣF and I_n = ΣF/n (thesis Figs 7.10/7.11). Line colour: measured or model; "
       "line style: the crank speed or clearance of the line; point colour: the recording (as in the summary table).</p>"
       "<div id=\"sev-table\"></div><div class=\"grid2\" id=\"sev-charts\">";
  chart_box(h, "sev-clearance", "Fluctuation against clearance", true, true);
  chart_box(h, "sev-clearance-sim", "Simulated impacts against clearance", true, true);
  chart_box(h, "sev-speed", "Fluctuation against crank speed", true, true);
  chart_box(h, "sev-speed-sim", "Simulated impacts against crank speed", true, true);
  h << "</div></section>";
}

}  // namespace fourbar
