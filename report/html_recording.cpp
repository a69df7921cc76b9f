#include "report/html_recording.hpp"

#include <string>

#include "report/html_blocks.hpp"
#include "report/html_text.hpp"
#include "report/html_verdict.hpp"
#include "report/quantity_names.hpp"
#include "report/html_views.hpp"
#include "report/setup_check_record.hpp"

namespace fourbar {

using nlohmann::json;

namespace {

/// One crank pulse per turn: what the recording cannot see, in numbers.
std::string one_pulse_note(const json& u, const json& speed_rpm) {
  if (u.is_null()) return {};
  const bool coupler = u["quantities"][0] == "alpha3_rad_s2";
  const std::string a = coupler ? "α3" : "α4", w = coupler ? "ω3" : "ω4";
  return "<p class=\"note one-pulse\"><b>One crank pulse per turn:</b> a crank-speed change that repeats every turn is "
         "invisible in this recording, whatever its size (the pulse times are the same with or without it). At " +
         fmt(speed_rpm, "%.0f") + " rpm with this " + (coupler ? "coupler" : "rocker") + " sensor, each " +
         fmt(u["speed_change_pct"], "%.1f") + " % of once-per-turn speed change would put up to " +
         fmt(u["once_per_turn_pct"]["alpha"], "%.2f") + " % into the averaged " + a + " and " +
         fmt(u["once_per_turn_pct"]["omega"], "%.2f") + " % into " + w + " (twice per turn: " +
         fmt(u["twice_per_turn_pct"]["alpha"], "%.2f") + " % and " + fmt(u["twice_per_turn_pct"]["omega"], "%.2f") +
         " %). A loaded crank usually changes speed within the turn: to measure it, fit a tooth wheel "
         "(<code>pulses_per_rev</code>) or an encoder (<code>encoder_a</code>, <code>encoder_b</code>).</p>";
}

}  // namespace

void recording_section(std::ostringstream& h, const json& r, std::size_t ri) {
  const std::string name = r["name"];
  const bool ok = is_analysed(r);
  h << "<section class=\"recording\" id=\"rec" << ri << "\"><h2><span class=\"swatch\" data-rec=\"" << ri << "\"></span>" << html_escape(name) << " <span class=\""
    << (!ok ? "failed\">failed" : r["status"] == "ok" ? "ok\">analysed" : "failed\">analysed: check set-up") << "</span>"
    << (r.value("from_cache", false) ? " <span class=\"note\">(from cache)</span>" : "") << "</h2>";
  if (ok) h << verdict_box(r) << setup_check_html(r.value("setup_check", json::object()), name);
  if (!ok) {
    h << "<p class=\"err\"><b>" << (r["error_kind"] == "input" ? "Bad input" : "Run failed") << ":</b> " << html_escape(r["error"])
      << "</p><h3>Input files</h3>";
    files_table(h, r["files"]);
    h << "</section>";
    return;
  }
  const json& op = r["operating_point"];
  const json& th = r["theory"];
  const json& sv = th["severity"];
  h << "<table><tr><th class=\"l\">crank speed</th><th class=\"l\">clearance</th><th class=\"l\">revolutions averaged</th>"
       "<th class=\"l\">theory</th><th class=\"l\">simulated n / ΣF / I_n per turn</th></tr><tr><td class=\"l\">"
    << fmt(op["speed_rpm"], "%.2f") << " rpm (" << fmt(op["direction"]) << ", std " << fmt(at(r, {"acquisition", "speed_rpm", "std"}), "%.2f")
    << ")</td><td class=\"l\">" << fmt(op["clearance_mm"], "%.4g") << " mm ("
    << html_escape(op.value("clearance_source", std::string("manifest"))) << ")</td><td class=\"l\">" << fmt(op["revolutions_averaged"], "%.0f")
    << "</td><td class=\"l\">e = " << fmt(th["settings"]["restitution"]) << ", " << fmt(th["settings"]["contact"])
    << ", μ = " << fmt(th["settings"]["friction_coefficient"]) << "; " << fmt(th["settings"]["warmup_revolutions"], "%.0f")
    << " warm-up + " << fmt(th["settings"]["averaged_revolutions"], "%.0f") << " averaged turns</td><td class=\"l\">"
    << fmt(sv["impacts_per_rev"], "%.1f") << " / " << fmt(sv["sum_normal_impulse_per_rev_Ns"], "%.3g") << " N·s / "
    << fmt(sv["impact_index_Ns"], "%.3g") << " N·s</td></tr></table>";
  h << one_pulse_note(at(r, {"acquisition", "one_pulse_per_turn"}), op["speed_rpm"]);
  if (!at(r, {"warnings"}).empty()) {
    h << "<div class=\"warn\"><b>Warnings</b><ul>";
    for (const json& w : r["warnings"]) h << "<li>" << html_escape(w) << "</li>";
    h << "</ul></div>";
  }
  views_section(h, r, ri);
  // Metrics.
  h << "<h3>Theory over measurement</h3><table><tr><th class=\"l\">quantity</th><th>RMS measured</th><th>RMS clearance model</th>"
       "<th>RMS nominal</th><th>RMS(meas − model)</th><th>corr. model</th><th>corr. nominal</th><th>peak ratio meas/model</th>"
       "<th>a (time)</th><th>a (spectral)</th><th class=\"l\">largest deviations from nominal, θ2 (deg): measured | model</th></tr>";
  for (const auto& [q, m] : r["metrics"].items()) {
    auto angles = [](const json& a) {
      std::string s;
      for (const json& v : a) s += (s.empty() ? "" : ", ") + fmt(v, "%.1f");
      return s;
    };
    h << "<tr><td class=\"l\">" << html_escape(quantity_label(q)) << "</td><td>" << fmt(m["measured_rms"]) << "</td><td>" << fmt(m["simulated_rms"])
      << "</td><td>" << fmt(m["nominal_rms"]) << "</td><td>" << fmt(m["rms_difference_simulated"]) << "</td><td>"
      << fmt(m["correlation_simulated"], "%.3f") << "</td><td>" << fmt(m["correlation_nominal"], "%.3f") << "</td><td>"
      << fmt(m["peak_ratio_simulated"], "%.3f") << "</td><td>" << fmt(m["magnification"]["time_domain"], "%.3g") << "</td><td>"
      << fmt(m["magnification"]["spectral"], "%.3g") << "</td><td class=\"l\">" << angles(m["measured_bursts_deg"]) << " | "
      << angles(m["simulated_bursts_deg"]) << "</td></tr>";
  }
  h << "</table>";
  // Overlays (the first, α3, is the one the short print keeps).
  h << "<div class=\"grid2 overlays\">";
  for (const auto& [q, s] : r["series"].items()) {
    if (!s.contains("measured")) continue;
    chart_box(h, "r" + std::to_string(ri) + "-" + q, html_escape(quantity_label(q)) + ": measured, clearance model, nominal",
              false, true);
  }
  h << "</div>";
  if (!r["metrics"].empty()) {
    h << "<div class=\"grid2\">";
    chart_box(h, "r" + std::to_string(ri) + "-orders", "Deviation from the nominal response per crank order", true, true);
    chart_box(h, "r" + std::to_string(ri) + "-factor", "Magnification factor a per order (thesis eq. 8.1.2)", true, true);
    const json& mg = r["metrics"].begin().value()["magnification"];
    h << "</div><p class=\"note\">" << html_escape(mg["spectral_method"].get<std::string>())
      << ". An order is significant when the measured amplitude is 3× above the floor between the order lines. "
      << html_escape(spectral_orders_note(mg)) << "</p>";
  }
  if (!at(r, {"spectra"}).empty()) chart_box(h, "r" + std::to_string(ri) + "-spectrum", "Spectrum of the measured angular acceleration", true, true);
  h << "<h3>Impact directions in the clearance model (thesis Figs 8.11/8.12)</h3><div>"
    << polar_svg(r["impacts"], "pin_deg", "on the pin (coupler frame: 0° along the coupler, A→B)")
    << polar_svg(r["impacts"], "bushing_deg", "on the bushing (rocker frame: 0° along the rocker, O4→C)") << "</div>";
  // In print the long two-column list runs in two columns of the page (report.css).
  h << "<h3>Analysis</h3><div class=\"settings-list\"><table>";
  settings_rows(h, at(r, {"analysis"}), "");
  settings_rows(h, at(r, {"acquisition"}), "acquisition");
  h << "<tr><td class=\"l\">theory energy balance residual (rel.)</td><td class=\"l\">" << fmt(th["energy_residual_rel"]) << "</td></tr></table></div>";
  h << "<h3>Input files</h3>";
  files_table(h, r["files"]);
  h << "</section>";
}

}  // namespace fourbar
