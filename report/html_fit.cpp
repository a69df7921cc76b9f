#include "report/html_fit.hpp"

#include <string>
#include <vector>

#include "report/html_blocks.hpp"
#include "report/html_text.hpp"

namespace fourbar {

using nlohmann::json;

namespace {

const char* kNotIdentifiable =
    "not identifiable from these recordings: the objective stays within its noise over more than half the box. Record "
    "more turns per recording, at a sample rate of at least 8× the averaging filter's corner, with the rocker channel as "
    "well as the coupler, and at the larger clearance and higher speed";

std::string contact_text(const json& s) {
  std::string t = "e = " + fmt(s["restitution"], "%.3g") + ", " + fmt(s["contact"]);
  if (s.value("contact", "") == "stick-slip") t += ", μ = " + fmt(s["friction_coefficient"], "%.3g");
  return t;
}

std::string arrow(const json& before, const json& after, const char* f) {
  return fmt(before, f) + " → <b>" + fmt(after, f) + "</b>";
}

/// `row[key]` ± `row[key_standard_error]` (the bare value when the fit gave no error).
std::string with_error(const json& row, const std::string& key) {
  std::string t = fmt(row.value(key, json()), "%.3g");
  if (row.contains(key + "_standard_error")) t += " ± " + fmt(row[key + "_standard_error"], "%.2g");
  return t;
}

/// One fit's parameters, χ² and notes (the session's, or one recording's).
void fit_summary(std::ostringstream& h, const json& f, const std::string& id_prefix) {
  const json& prior = f["prior"];
  h << "<table><tr><th class=\"l\">parameter</th><th>fitted</th><th>interval</th><th class=\"l\">identifiable</th>"
       "<th>prior (session.toml)</th></tr>";
  // e first, then μ, then any other fitted parameter (the JSON object is sorted by name).
  std::vector<std::string> names;
  for (const char* n : {"restitution", "friction_coefficient"})
    if (f["parameters"].contains(n)) names.push_back(n);
  for (const auto& [name, p] : f["parameters"].items())
    if (name != "contact" && name != "restitution" && name != "friction_coefficient") names.push_back(name);
  for (const std::string& name : names) {
    const json& p = f["parameters"][name];
    // A smooth prior has μ = 0.
    const json prior_value = prior.contains(name)                                          ? prior[name]
                             : name == "friction_coefficient" && prior.value("contact", "") == "smooth" ? json(0.0)
                                                                                             : json(nullptr);
    h << "<tr><td class=\"l\">" << html_escape(name) << "</td><td>" << fmt(p["value"], "%.3g") << "</td><td>["
      << fmt(p["low"], "%.3g") << ", " << fmt(p["high"], "%.3g") << "]</td><td class=\"l\">"
      << (p.value("identifiable", false) ? std::string("yes")
                                         : "<span class=\"failed\">" +
                                               (p.contains("advice") && p["advice"].is_string()
                                                    ? html_escape(p["advice"].get<std::string>())
                                                    : std::string(kNotIdentifiable)) +
                                               "</span>")
      << "</td><td>" << fmt(prior_value, "%.3g") << "</td></tr>";
  }
  h << "</table>";
  const json& contact = at(f, {"parameters", "contact"});
  h << "<p>Fitted: <b>" << contact_text(f["fitted"]) << "</b> (prior: " << contact_text(prior) << ")";
  if (contact.contains("smooth_possible"))
    h << "; " << (contact["smooth_possible"].get<bool>() ? "μ's interval reaches 0: the smooth law fits as well"
                                                          : "μ's interval excludes 0: the contact is not smooth");
  h << ". χ² per statistic compared: <b>" << fmt(f["chi2_per_term"], "%.3g") << "</b> at the fit, "
    << fmt(json(f["terms"].get<double>() > 0 ? f["chi2_prior"].get<double>() / f["terms"].get<double>() : 0.0), "%.3g")
    << " at the prior (" << fmt(f["terms"], "%.0f") << " statistics; ≈ 1 when the model describes the measurement "
    << "within its noise). The interval is where the objective stays within Δχ² = " << fmt(f["interval_delta_chi2"], "%.3g")
    << " of its minimum";
  if (f.contains("correlation_restitution_friction"))
    h << "; correlation of e and μ " << fmt(f["correlation_restitution_friction"], "%.2f");
  h << ". " << fmt(f["evaluations"], "%.0f") << " evaluations, " << fmt(f["simulations"], "%.0f") << " simulations of "
    << fmt(f["turns_per_simulation"], "%.0f") << " turns, " << fmt(f["seconds"], "%.3g") << " s.</p>";
  if (!f["notes"].empty()) {
    h << "<ul class=\"warn\">";
    for (const json& n : f["notes"]) h << "<li>" << html_escape(n) << "</li>";
    h << "</ul>";
  }
  bool profiles = false;
  for (const auto& [name, p] : f["parameters"].items())
    if (p.contains("profile") && p["profile"].size() >= 2) profiles = true;
  if (!profiles) return;
  h << "<div class=\"grid2\">";
  for (const auto& [name, p] : f["parameters"].items())
    if (p.contains("profile") && p["profile"].size() >= 2)
      chart_box(h, id_prefix + name, "Profile of χ² along " + html_escape(name) + " (lowest over the other parameter)", true);
  h << "</div>";
}

}  // namespace

void fit_section(std::ostringstream& h, const json& data) {
  if (!data.contains("fit")) return;
  const json& fit = data["fit"];
  h << "<section id=\"fit\"><h2>Fitted bearing parameters</h2><p class=\"note\">From <code>" << html_escape(fit["file"])
    << "</code> (SHA-256 <span class=\"hash\">" << fmt(fit["sha256"]) << "</span>), written by <code>fourbar fit</code>: "
    << "the restitution e and stick-slip μ whose turn-to-turn statistics (spread over the turns, band energy above the "
       "averaging filter) match the measured ones. Below, the report's own theory is run a second time at the fitted "
       "values (same warm-up and averaged turns as at the prior) and compared with the measurement the same way.</p>";
  if (!fit["warnings"].empty()) {
    h << "<div class=\"warn\"><b>Warnings</b><ul>";
    for (const json& w : fit["warnings"]) h << "<li>" << html_escape(w) << "</li>";
    h << "</ul></div>";
  }
  if (fit.contains("session_fit")) {
    if (fit["session_fit"].contains("command_line"))
      h << "<p class=\"note\">Fit: <code>" << html_escape(fit["session_fit"]["command_line"]) << "</code></p>";
    fit_summary(h, fit["session_fit"], "fit-profile-");
  } else if (fit.contains("per_recording")) {
    const json& per = fit["per_recording"];
    for (std::size_t i = 0; i < per.size(); ++i) {
      h << "<h3>" << html_escape(per[i]["file"]) << " alone</h3>";
      fit_summary(h, per[i], "fit-profile-" + std::to_string(i) + "-");
    }
  }

  const json& rows = fit["recordings"];
  if (rows.empty()) {
    h << "<p class=\"warn\">No analysed recording has a fitted theory.</p></section>";
    return;
  }
  h << "<h3>Before → after: the model at the prior → at the fitted values</h3><p class=\"note\">On "
       "α3 (α4 without a coupler channel). a = RMS(model − nominal) / RMS(measured − nominal) of the averaged curves; RMS "
       "difference and correlation of the averaged measured and model curves. Averaged over R turns, a deviation that "
       "varies from turn to turn leaves σ/√R in the average (σ: the turn-to-turn scatter): <i>scatter share</i> = "
       "(σ/√R)/RMS(measured − nominal), near 1 when the measured averaged deviation is that scatter and not a repeatable "
       "curve; <i>a from scatter</i> = the a that the two scatters alone would give; <i>a without scatter</i> takes σ²/R "
       "out of both mean squares (– when nothing is left); <i>a in the fit's statistics</i> = what a long model run expects "
       "of an averaged curve of the measured turns over the measured one, ± its standard error (the measured turns' "
       "noise: a within about 2 errors of 1 is all a can say).</p><table><tr><th class=\"l\">recording</th><th>turns</th>"
       "<th>a</th><th>RMS difference</th><th>correlation</th><th>scatter share (measured)</th><th>a from scatter</th>"
       "<th>a without scatter</th><th>a in the fit's statistics</th><th>χ²/statistic in the fit</th></tr>";
  bool scatter_dominated = false;
  for (const json& r : rows) {
    const json &p = r["prior"], &f = r["fitted"];
    const json& share = r["measured_scatter_share"];
    if (share.is_number() && share.get<double>() > 0.7) scatter_dominated = true;
    h << "<tr><td class=\"l\">" << html_escape(r["name"]) << "</td><td>" << fmt(r["measured_turns"], "%.0f") << "</td><td>"
      << arrow(p["a"], f["a"], "%.3g") << "</td><td>" << arrow(p["rms_difference"], f["rms_difference"], "%.3g") << "</td><td>"
      << arrow(p["correlation"], f["correlation"], "%.3f") << "</td><td>" << fmt(share, "%.2f") << "</td><td>"
      << arrow(p["a_from_scatter_alone"], f["a_from_scatter_alone"], "%.3g") << "</td><td>"
      << arrow(p["a_without_scatter"], f["a_without_scatter"], "%.3g") << "</td><td>"
      << (r.contains("fit_a_fitted") ? with_error(r, "fit_a_prior") + " → <b>" + with_error(r, "fit_a_fitted") + "</b>"
                                     : std::string("–"))
      << "</td><td>"
      << (r.contains("fit_chi2_per_term") ? arrow(r["fit_chi2_prior_per_term"], r["fit_chi2_per_term"], "%.3g") : std::string("–"))
      << "</td></tr>";
  }
  h << "</table>";
  if (scatter_dominated)
    h << "<p class=\"warn\">In at least one recording the measured averaged deviation is mostly turn-to-turn scatter "
         "(scatter share above 0.7): its a compares what is left of the scatter after averaging, not how violent the "
         "model is, and moves with the number of turns averaged on each side. Judge the fit by its χ² above; for a "
         "meaningful a, record more turns.</p>";
  h << "<div class=\"grid2\">";
  const json& recs = data["recordings"];
  for (std::size_t i = 0; i < recs.size(); ++i)
    if (recs[i].contains("fitted_theory"))
      chart_box(h, "fit-r" + std::to_string(i),
                html_escape(recs[i]["name"]) + ": measured vs the model at the prior and at the fitted values", true, true);
  h << "</div></section>";
}

}  // namespace fourbar
