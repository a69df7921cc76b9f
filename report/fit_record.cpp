#include "report/fit_record.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "common/error.hpp"
#include "report/file_hash.hpp"

namespace fourbar {

namespace {

using nlohmann::json;

[[noreturn]] void bad(const std::filesystem::path& file, const std::string& key, const std::string& what) {
  throw InputError(file.string() + ": " + key + ": " + what +
                   "; give the fit.json written by `fourbar fit` (or run the report with --no-fit)");
}

FittedContact contact_of(const std::filesystem::path& file, const json& fitted, const std::string& where) {
  if (!fitted.is_object()) bad(file, where, "missing (an object with restitution and contact)");
  FittedContact c;
  if (!fitted.contains("restitution") || !fitted["restitution"].is_number())
    bad(file, where + ".restitution", "missing or not a number");
  c.restitution = fitted["restitution"].get<double>();
  if (!(c.restitution >= 0.0 && c.restitution <= 1.0)) bad(file, where + ".restitution", "must lie in [0, 1]");
  const std::string law = fitted.contains("contact") && fitted["contact"].is_string() ? fitted["contact"].get<std::string>() : "";
  if (law == "smooth") c.contact = ContactLaw::smooth;
  else if (law == "rough") c.contact = ContactLaw::rough;
  else if (law == "stick-slip") c.contact = ContactLaw::stick_slip;
  else bad(file, where + ".contact", "must be \"smooth\", \"rough\" or \"stick-slip\"");
  if (c.contact == ContactLaw::stick_slip) {
    if (!fitted.contains("friction_coefficient") || !fitted["friction_coefficient"].is_number())
      bad(file, where + ".friction_coefficient", "missing or not a number (contact is stick-slip)");
    c.friction_coefficient = fitted["friction_coefficient"].get<double>();
    if (!(c.friction_coefficient >= 0.0)) bad(file, where + ".friction_coefficient", "must be 0 or more");
  }
  return c;
}

/// √(mean over the angles of std²): the turn-to-turn scatter of a series.
std::optional<double> scatter_rms(const json& std_series) {
  if (!std_series.is_array() || std_series.empty()) return std::nullopt;
  double s = 0;
  for (const json& v : std_series) {
    if (!v.is_number()) return std::nullopt;
    s += v.get<double>() * v.get<double>();
  }
  return std::sqrt(s / static_cast<double>(std_series.size()));
}

json json_or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

/// Measured vs one model run (the prior's or the fitted one) on the quantity `q`.
json model_row(const json& metrics, const json& series, const std::optional<double>& measured_scatter, double measured_turns,
               double measured_deviation, double model_turns) {
  json row = {{"a", metrics["magnification"]["time_domain"]},
              {"a_spectral", metrics["magnification"]["spectral"]},
              {"rms_difference", metrics["rms_difference_simulated"]},
              {"correlation", metrics["correlation_simulated"]},
              {"model_deviation_rms", metrics["magnification"]["simulated_deviation_rms"]}};
  const std::optional<double> s = scatter_rms(series["clearance_std"]);
  row["model_scatter_rms"] = json_or_null(s);
  // Averaged over R turns, the deviation's mean square holds σ²/R of scatter
  // (turns independent): the a that scatter alone would give, and a with the
  // scatter taken out of both averaged deviations (absent when nothing is left).
  std::optional<double> a_scatter, a_without;
  if (s && measured_scatter && *measured_scatter > 0 && model_turns > 0 && measured_turns > 0) {
    a_scatter = (*s / std::sqrt(model_turns)) / (*measured_scatter / std::sqrt(measured_turns));
    const double dm2 = measured_deviation * measured_deviation - *measured_scatter * *measured_scatter / measured_turns;
    const double ds = metrics["magnification"]["simulated_deviation_rms"].get<double>();
    const double ds2 = ds * ds - *s * *s / model_turns;
    if (dm2 > 0 && ds2 > 0) a_without = std::sqrt(ds2 / dm2);
  }
  row["a_from_scatter_alone"] = json_or_null(a_scatter);
  row["a_without_scatter"] = json_or_null(a_without);
  return row;
}

}  // namespace

std::optional<FittedContact> ReportFit::for_recording(const std::string& name) const {
  if (shared) return shared;
  const auto it = by_recording.find(name);
  if (it == by_recording.end()) return std::nullopt;
  return it->second;
}

ReportFit load_report_fit(const std::filesystem::path& file, const std::vector<std::filesystem::path>& recordings) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot be read; give the fit.json written by `fourbar fit SESSION_DIR`");
  ReportFit f;
  f.file = file;
  try {
    f.fit = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError(file.string() + ": not JSON (" + e.what() + "); give the fit.json written by `fourbar fit`");
  }
  std::set<std::string> fitted_names;
  auto names_of = [&](const json& recs, const std::string& where) {
    if (!recs.is_array()) bad(file, where, "missing (the recordings the fit used)");
    for (const json& r : recs) {
      if (!r.contains("file") || !r["file"].is_string()) bad(file, where + "[].file", "missing");
      fitted_names.insert(r["file"].get<std::string>());
    }
  };
  if (f.fit.contains("per_recording")) {
    const json& per = f.fit["per_recording"];
    if (!per.is_array()) bad(file, "per_recording", "not an array");
    for (std::size_t i = 0; i < per.size(); ++i) {
      const std::string where = "per_recording[" + std::to_string(i) + "]";
      if (!per[i].contains("file") || !per[i]["file"].is_string()) bad(file, where + ".file", "missing");
      f.by_recording[per[i]["file"].get<std::string>()] = contact_of(file, per[i].value("fitted", json()), where + ".fitted");
      if (!per[i].contains("parameters")) bad(file, where + ".parameters", "missing");
      names_of(per[i].value("recordings", json()), where + ".recordings");
    }
  } else {
    f.shared = contact_of(file, f.fit.value("fitted", json()), "fitted");
    if (!f.fit.contains("parameters") || !f.fit["parameters"].is_object()) bad(file, "parameters", "missing");
    names_of(f.fit.value("recordings", json()), "recordings");
  }
  std::set<std::string> session_names;
  for (const auto& r : recordings) session_names.insert(r.filename().string());
  for (const std::string& n : fitted_names)
    if (!session_names.count(n))
      f.warnings.push_back("the fit used " + n + ", which is not a recording of this session: it may be another session's fit");
  for (const std::string& n : session_names)
    if (!fitted_names.count(n))
      f.warnings.push_back(n + " was not in the fit" +
                           std::string(f.shared ? " (its theory uses the session's fitted values all the same)"
                                                : " (no fitted theory for it)"));
  const auto fit_time = std::filesystem::last_write_time(file);
  for (const auto& r : recordings)
    if (fitted_names.count(r.filename().string()) && std::filesystem::last_write_time(r) > fit_time)
      f.warnings.push_back(r.filename().string() + " changed after " + file.filename().string() +
                           " was written: run `fourbar fit` again");
  return f;
}

TheorySettings with_fitted_contact(TheorySettings t, const FittedContact& c) {
  t.restitution = c.restitution;
  t.contact = c.contact;
  t.friction_coefficient = c.contact == ContactLaw::stick_slip ? c.friction_coefficient : 0.0;
  return t;
}

std::optional<json> fit_report_row(const ReportFit& fit, const json& r) {
  if (!r.contains("fitted_theory") || !r.contains("metrics")) return std::nullopt;
  const char* q = r["metrics"].contains("alpha3_rad_s2") ? "alpha3_rad_s2" : "alpha4_rad_s2";
  if (!r["metrics"].contains(q) || !r["fitted_theory"]["metrics"].contains(q)) return std::nullopt;
  const json& m = r["metrics"][q];
  const std::optional<double> sm = scatter_rms(r["series"][q]["measured_std"]);
  const double rm = r["operating_point"]["revolutions_averaged"].get<double>();
  const double dm = m["magnification"]["measured_deviation_rms"].get<double>();
  json row = {{"name", r["name"]},
              {"quantity", q},
              {"measured_turns", rm},
              {"measured_deviation_rms", dm},
              {"measured_scatter_rms", json_or_null(sm)},
              // The share of the measured averaged deviation that scatter
              // over the turns alone would give: near 1, a compares scatter.
              {"measured_scatter_share", sm && dm > 0 ? json(*sm / std::sqrt(rm) / dm) : json(nullptr)}};
  row["prior"] = model_row(m, r["series"][q], sm, rm, dm, r["theory"]["settings"]["averaged_revolutions"].get<double>());
  row["prior"]["settings"] = r["theory"]["settings"];
  const json& ft = r["fitted_theory"];
  row["fitted"] = model_row(ft["metrics"][q], ft["series"][q], sm, rm, dm, ft["settings"]["averaged_revolutions"].get<double>());
  row["fitted"]["settings"] = ft["settings"];
  std::vector<const json*> fit_recordings;
  if (fit.fit.contains("recordings"))
    for (const json& fr : fit.fit["recordings"]) fit_recordings.push_back(&fr);
  if (fit.fit.contains("per_recording"))
    for (const json& p : fit.fit["per_recording"])
      for (const json& fr : p["recordings"]) fit_recordings.push_back(&fr);
  for (const json* frp : fit_recordings)
    if (const json& fr = *frp; fr.value("file", "") == r["name"]) {
      row["fit_chi2_per_term"] = fr.value("chi2_per_term", 0.0);
      row["fit_chi2_prior_per_term"] = fr.value("terms", 0) > 0 ? fr.value("chi2_prior", 0.0) / fr["terms"].get<double>() : 0.0;
      if (fr.contains("magnification_fitted")) row["fit_a_fitted"] = fr["magnification_fitted"];
      if (fr.contains("magnification_prior")) row["fit_a_prior"] = fr["magnification_prior"];
      // Their standard errors (fits before they were written have none).
      if (fr.contains("magnification_fitted_standard_error"))
        row["fit_a_fitted_standard_error"] = fr["magnification_fitted_standard_error"];
      if (fr.contains("magnification_prior_standard_error"))
        row["fit_a_prior_standard_error"] = fr["magnification_prior_standard_error"];
    }
  return row;
}

json fit_report_record(const ReportFit& fit, const std::vector<json>& rows, const std::filesystem::path& session_dir) {
  json out = {{"file", std::filesystem::proximate(fit.file, session_dir).string()},
              {"sha256", sha256_file(fit.file)},
              {"warnings", fit.warnings}};
  // The fit itself, without the per-recording measured statistics (they are in fit.json).
  auto brief = [](json j) {
    if (j.contains("recordings"))
      for (json& r : j["recordings"]) r.erase("measured_statistics");
    return j;
  };
  if (fit.fit.contains("per_recording")) {
    json per = json::array();
    for (const json& p : fit.fit["per_recording"]) per.push_back(brief(p));
    out["per_recording"] = per;
  } else {
    out["session_fit"] = brief(fit.fit);
  }
  json recordings = json::array();
  for (const json& row : rows) recordings.push_back(row);
  out["recordings"] = recordings;
  return out;
}

}  // namespace fourbar
