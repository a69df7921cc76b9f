#include "fit/fit_json.hpp"

#include "common/format.hpp"
#include "fit/linkage_statistics.hpp"

namespace fourbar {

using nlohmann::json;

std::string not_identifiable_advice(const std::string& parameter) {
  return parameter + ": not identifiable from these recordings (the objective stays within its noise over more than "
                     "half the box); record more turns per recording (the statistics' error falls as 1/sqrt(turns)), "
                     "at a sample rate of at least 8x the averaging filter's corner (e shows in the band above it), "
                     "with the rocker channel as well as the coupler, and at the larger clearance and higher speed, "
                     "where impacts are strongest";
}

std::string parameter_advice(const ParameterEstimate& p) {
  if (p.identifiable) return {};
  if (p.name != "friction_coefficient") return not_identifiable_advice(p.name);
  // μ: measured on the recovery sessions (docs/fit.md, "μ above 0.2"): from
  // μ ≈ 0.2 up, nearly every impact sticks and the statistics change by less
  // than their noise, so more of the same recording does not pin μ down.
  std::string s = p.name + ": not identifiable from these recordings";
  if (p.lower_bound_only)
    s += " above " + format_number(p.low, 2) + " (only " + p.name + " >= " + format_number(p.low, 2) +
         " is measured: the objective stays within its noise from there to the top of the box, " +
         format_number(p.high, 2) + ")";
  else
    s += " (the objective stays within its noise from " + format_number(p.low, 2) + " to " + format_number(p.high, 2) + ")";
  return s + ". With friction of about 0.2 or more nearly every impact sticks, and a larger coefficient changes the "
             "statistics by less than their noise at 25 turns; record at a higher crank speed (the statistics' "
             "response to friction above 0.2 was larger at 350 than at 250 rpm) with several times more turns, "
             "or measure the bushing pair's friction coefficient directly (tribometer or inclined-plane test)";
}

namespace {

json contact_json(const ContactParameters& p) {
  json j = {{"restitution", p.restitution}, {"contact", to_string(p.contact)}};
  if (p.contact == ContactLaw::stick_slip) j["friction_coefficient"] = p.friction_coefficient;
  return j;
}

}  // namespace

json fit_to_json(const FitResult& f, const std::vector<RecordingTarget>& targets, const ContactParameters& prior,
                 const FitOptions& o) {
  json params = json::object();
  for (const ParameterEstimate& p : f.parameters) {
    json pj = {{"value", p.value}, {"low", p.low}, {"high", p.high}, {"identifiable", p.identifiable}};
    json prof = json::array();
    for (std::size_t i = 0; i < p.profile_at.size(); ++i) prof.push_back({p.profile_at[i], p.profile_chi2[i]});
    pj["profile"] = prof;
    if (!p.identifiable) pj["advice"] = parameter_advice(p);
    if (p.lower_bound_only) pj["only_lower_bound"] = true;
    if (f.model_family.rejected) pj["interval"] = "widened by the model-error scale (the model family is rejected)";
    params[p.name] = pj;
  }
  json contact = {{"value", to_string(f.best.contact)}};
  if (o.fit_friction) {
    const auto& mu = f.parameters.at(1);
    contact["smooth_possible"] = mu.low <= o.box.friction_low + 1e-12;
  }
  params["contact"] = contact;
  json recs = json::array();
  for (std::size_t r = 0; r < f.recordings.size(); ++r) {
    const RecordingFitTerm& t = f.recordings[r];
    json rj = {{"file", t.name},
               {"chi2", t.chi2},
               {"terms", t.terms},
               {"chi2_per_term", t.terms > 0 ? t.chi2 / t.terms : 0.0},
               {"chi2_prior", t.chi2_prior}};
    if (r < targets.size()) {
      const RecordingTarget& tg = targets[r];
      rj["clearance_mm"] = tg.clearance_m * 1e3;
      rj["crank_speed_rpm"] = std::abs(tg.crank_speed_rad_s) * 60.0 / (2.0 * 3.14159265358979323846);
      rj["measured_turns"] = tg.turns;
      json stats = json::object();
      for (FitLink l : kFitLinks) {
        const auto& m = tg.measured[static_cast<std::size_t>(l)];
        if (!m) continue;
        json sj = json::object();
        for (ResponseStatistic s : kResponseStatistics)
          sj[std::string(name_of(s))] = {{"value", m->value[index_of(s)]}, {"standard_error", m->standard_error[index_of(s)]}};
        stats[std::string(name_of(l))] = sj;
      }
      rj["measured_statistics"] = stats;
      // A periodic motion in the measured turns (analyze/turn_repeat.hpp).
      json repeat = json::object();
      for (FitLink l : kFitLinks)
        if (const TurnRepeat& tr = tg.repeat[static_cast<std::size_t>(l)]; tg.measured[static_cast<std::size_t>(l)])
          repeat[std::string(name_of(l))] = {{"period_turns", tr.period}, {"ratio", tr.ratio()}, {"neighbours", tr.neighbours()}};
      rj["measured_turns_repeat"] = repeat;
      if (tg.band_filter) rj["band_hz"] = {tg.band_filter->low_hz, tg.band_filter->high_hz};
    }
    if (r < f.magnification_fitted.size()) {
      // a with its standard error: with 25 turns a is noise-limited (±8–36 %),
      // so a bare number would read as a verdict it cannot give.
      if (const auto& a = f.magnification_fitted[r])
        rj["magnification_fitted"] = a->value, rj["magnification_fitted_standard_error"] = a->standard_error;
      if (const auto& a = f.magnification_prior[r])
        rj["magnification_prior"] = a->value, rj["magnification_prior_standard_error"] = a->standard_error;
    }
    if (r < f.measured_scatter_share.size() && f.measured_scatter_share[r])
      rj["measured_scatter_share"] = *f.measured_scatter_share[r];
    if (r < f.magnification_from_scatter_fitted.size() && f.magnification_from_scatter_fitted[r])
      rj["magnification_from_scatter_fitted"] = *f.magnification_from_scatter_fitted[r];
    recs.push_back(rj);
  }
  json stats = json::array();
  for (ResponseStatistic s : o.statistics) stats.push_back(std::string(name_of(s)));
  json offsets = json::object();
  for (const auto& [name, eta] : f.modelling_offsets) {
    double width = name == "band_excess" ? o.modelling_offset_sigma.band : 0.0;
    for (ResponseStatistic s : o.statistics)
      if (name_of(s) == name) width = o.modelling_offset_sigma.statistic[index_of(s)];
    offsets[name] = {{"sigma", width}, {"offset_at_fit", eta}};
  }
  json j = {{"parameters", params},
            {"fitted", contact_json(f.best)},
            {"prior", contact_json(prior)},
            {"chi2", f.chi2},
            {"chi2_prior", f.chi2_prior},
            {"terms", f.terms},
            {"chi2_per_term", f.terms > 0 ? f.chi2 / f.terms : 0.0},
            {"recordings", recs},
            {"statistics", stats},
            {"modelling_offsets", offsets},
            {"interval_delta_chi2", f.interval_delta},
            {"interval_level", f.noise.level},
            {"objective_noise",
             {{"bottom_chi2", f.noise.bottom},
              {"noise_sd_chi2", f.noise.noise_sd},
              {"replicates", f.noise.replicates},
              {"dispersion", f.noise.dispersion}}},
            {"smooth_model", {{"fitted", f.surrogate_ok}, {"residual_rms", f.surrogate_residual_rms}}},
            {"evaluations", f.evaluations},
            {"simulations", f.simulations},
            {"simulations_on_rank_0", f.simulations_on_rank_0},
            {"turns_per_simulation", o.warmup_turns + o.simulated_turns},
            {"warmup_turns", o.warmup_turns},
            {"simulated_turns", o.simulated_turns},
            {"turns_simulated", f.turns_simulated},
            {"magnification_turns", f.magnification_turns},
            {"magnification_simulations", f.magnification_simulations},
            {"seconds", f.seconds},
            {"cpu_seconds", f.cpu_seconds},
            {"seconds_per_simulation", f.seconds_per_simulation},
            {"simulation_cpu_seconds", f.simulation_cpu_seconds},
            {"simulation_idle_wall_seconds", f.simulation_idle_wall_seconds},
            {"threads", o.threads},
            {"notes", f.notes}};
  j["model"] = std::string(name_of(o.model.kind));
  if (o.model.kind == FitModelKind::elastic) {
    j["elastic_modes"] = o.model.elastic_modes;  // 0: the rig table's
    j["tolerance"] = o.tolerance;
    if (!targets.empty() && targets.front().rig)
      j["contact_stiffness_N_per_m_1_5"] = elastic_fit_stiffness(*targets.front().rig, o.model, targets.front().clearance_m);
  }
  if (f.correlation) j["correlation_restitution_friction"] = *f.correlation;
  j["model_family"] = {{"verdict", f.model_family.rejected ? "rejected" : "not rejected"},
                       {"reasons", f.model_family.reasons},
                       {"error_scale", f.model_family.error_scale}};
  if (!f.model_family.spectral_model.empty())
    j["model_family"]["spectral_check"] = {{"model", f.model_family.spectral_model},
                                           {"recordings", f.model_family.spectral_recordings}};
  return j;
}

}  // namespace fourbar
