#include "report/recording_job.hpp"

#include <algorithm>
#include <cmath>

#include "analyze/analysis_channels.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "compare/elastic_reference.hpp"
#include "compare/link_vibration.hpp"
#include "fit/response_statistics.hpp"
#include "report/comparison_record.hpp"
#include "report/verdict_family.hpp"
#include "report/setup_check_record.hpp"
#include "report/theory_omega.hpp"
#include "report/views_record.hpp"

namespace fourbar {

namespace {

using nlohmann::json;

json filter_json(const FilterSpec& f) {
  static const char* bands[] = {"all_pass", "lowpass", "highpass", "bandpass", "bandstop"};
  return {{"band", bands[static_cast<int>(f.band)]}, {"low_hz", f.low_hz},          {"high_hz", f.high_hz},
          {"mains_hz", f.mains_hz},                  {"mains_width_hz", f.mains_width_hz},
          {"window", to_string(f.window)},           {"transition_hz", f.transition_hz}};
}

AngleSeries series_from(const AngleAverage& avg, const std::vector<double>& grid) {
  AngleSeries s;
  s.mean = avg.mean;
  s.std = avg.std;
  s.revolutions = grid;
  s.revolution_count = avg.revolutions;
  return s;
}

/// The measured α spectrum of a link up to `max_order` crank orders.
json link_spectrum(const RecordingAnalysis& a, const LinkResult& link, double max_order) {
  json order = json::array(), amp = json::array();
  for (std::size_t i = 0; i < a.spectra.order.size() && i < link.alpha_amplitude.size(); ++i) {
    if (a.spectra.order[i] > max_order) break;
    order.push_back(a.spectra.order[i]);
    amp.push_back(link.alpha_amplitude[i]);
  }
  return {{"order", order}, {"amplitude", amp}};
}

}  // namespace

json unseen_speed_json(const RecordingAnalysis& a) {
  if (!a.unseen_speed) return nullptr;
  const UnseenSpeedSensitivity& u = *a.unseen_speed;
  const bool coupler = a.unseen_speed_link == SensedLink::coupler;
  return {
      {"quantities", coupler ? json::array({"alpha3_rad_s2", "omega3_rad_s"}) : json::array({"alpha4_rad_s2", "omega4_rad_s"})},
      {"speed_change_pct", 100 * u.amplitude},
      {"once_per_turn_pct", {{"alpha", 100 * u.once_per_turn.alpha_rel_rms}, {"omega", 100 * u.once_per_turn.omega_rel_rms}}},
      {"twice_per_turn_pct", {{"alpha", 100 * u.twice_per_turn.alpha_rel_rms}, {"omega", 100 * u.twice_per_turn.omega_rel_rms}}}};
}

MeasuredResponse measured_response(const RecordingAnalysis& a) {
  MeasuredResponse m;
  m.grid.grid_points_per_rev = a.grid_points_per_rev;
  m.grid.start_rad = a.crank_deg.empty() ? 0.0 : units::deg_to_rad(a.crank_deg[0]);
  m.grid.direction = a.crank_direction;
  m.crank_speed_rad_s = a.mean_crank_speed_rad_s;
  const SpeedStats& sp = a.acquisition.speed;
  m.speed_rel_std = sp.mean_rpm > 0 ? sp.std_rpm / sp.mean_rpm : 0.0;
  // The mains frequency the analysis was given ([analysis] mains_hz); when it
  // was given none, both 50 and 60 Hz, since every lab has one of them and an
  // order wrongly left out costs less than hum counted as impact response.
  m.mains_hz = a.filter.mains_hz > 0 ? std::vector<double>{a.filter.mains_hz} : std::vector<double>{50.0, 60.0};
  if (a.coupler) {
    m.series[index_of(LinkQuantity::alpha3)] = series_from(a.coupler->alpha_rad_s2, a.coupler->alpha_grid);
    m.series[index_of(LinkQuantity::omega3)] = series_from(a.coupler->omega_rad_s, a.coupler->omega_grid);
  }
  if (a.rocker) {
    m.series[index_of(LinkQuantity::alpha4)] = series_from(a.rocker->alpha_rad_s2, a.rocker->alpha_grid);
    m.series[index_of(LinkQuantity::omega4)] = series_from(a.rocker->omega_rad_s, a.rocker->omega_grid);
  }
  return m;
}

json recording_record(const RecordingAnalysis& a, const MeasuredResponse& measured, const MatchedTheory& t,
                       const RecordingComparison& c) {
  const AcquisitionReport& acq = a.acquisition;
  json r = comparison_record(measured, t, c);
  r["acquisition"] = {{"format", acq.recording.format},
                      {"sample_format", acq.recording.sample_format},
                      {"channels", acq.recording.channels},
                      {"sample_rate_hz", acq.recording.sample_rate_hz},
                      {"duration_s", acq.recording.duration_s()},
                      {"revolutions_kept", acq.revolutions},
                      {"revolutions_repaired", acq.revolutions_repaired},
                      {"revolutions_clipped", acq.revolutions_clipped},
                      {"revolutions_in_gaps", acq.revolutions_in_gaps},
                      {"range", {{"start_s", acq.range.start_s ? json(*acq.range.start_s) : json()},
                                 {"end_s", acq.range.end_s ? json(*acq.range.end_s) : json()}}},
                      {"clipping_checked", acq.clipping_checked},
                      {"speed_rpm", {{"mean", acq.speed.mean_rpm}, {"std", acq.speed.std_rpm}, {"min", acq.speed.min_rpm}, {"max", acq.speed.max_rpm}}}};
  r["analysis"] = {{"points_per_rev", a.grid_points_per_rev},
                   {"filter", filter_json(a.filter)},
                   {"kernel_taps", a.kernel_taps},
                   {"conversion", to_string(a.options.conversion)},
                   {"integration", to_string(a.options.integration)},
                   {"guard_revolutions", a.options.guard_revolutions},
                   {"rig", a.rig ? a.rig->name : ""}};
  json spectra = json::object();
  const double max_order = 4.0 * t.settings.max_order;
  if (a.coupler) spectra["alpha3_rad_s2"] = link_spectrum(a, *a.coupler, max_order);
  if (a.rocker) spectra["alpha4_rad_s2"] = link_spectrum(a, *a.rocker, max_order);
  r["spectra"] = spectra;
  r["warnings"] = a.warnings;
  if (a.unseen_speed) r["acquisition"]["one_pulse_per_turn"] = unseen_speed_json(a);
  return r;
}

namespace {

json turns_repeat_json(const TurnRepeat& r) {
  json lags = json::array();
  for (double v : r.by_lag) lags.push_back(v);
  return {{"turns", r.turns},           {"period_turns", r.period}, {"unconfirmed_period_turns", r.unconfirmed_period},
          {"ratio", r.ratio()},          {"neighbours", r.neighbours()}, {"by_lag", lags}};
}

/// The relative standard error of a (scatter) = model / measured turn-to-turn
/// scatter of α3 (α4): the delete-block jackknife errors of the measured and
/// the model spread (fit/response_statistics.hpp: √ mean over θ of the
/// variance over turns, blocks of consecutive turns) in quadrature, as
/// magnification.scatter_relative_error. Left out with fewer than 4 turns on
/// either side. Beside it, turns_repeat: whether the measured (the analysis'
/// averaged turns) and the model's turns repeat every few turns
/// (analyze/turn_repeat.hpp; the verdict says when the measured motion is
/// periodic).
void add_scatter_errors(json& r, const RecordingAnalysis& a, const MatchedTheory& t) {
  const std::array<std::pair<const std::optional<LinkResult>*, LinkQuantity>, 2> links{
      {{&a.coupler, LinkQuantity::alpha3}, {&a.rocker, LinkQuantity::alpha4}}};
  constexpr std::size_t spread = index_of(ResponseStatistic::spread);
  for (const auto& [link, q] : links) {
    const std::string key(column_name(q));
    if (!*link || !r["metrics"].contains(key)) continue;
    const TheorySeries& s = t.series[index_of(q)];
    const std::vector<double>& turns = (**link).alpha_grid;
    const std::size_t n = s.nominal.size();
    if (n == 0 || turns.size() % n != 0 || s.clearance_revolutions.size() % n != 0 || turns.size() / n < 4 ||
        s.clearance_revolutions.size() / n < 4)
      continue;
    r["metrics"][key]["turns_repeat"] = {
        {"measured", turns_repeat_json((**link).alpha_repeat)},
        {"model", turns_repeat_json(turn_repeat(s.clearance_revolutions, n))}};
    const StatisticValues measured = response_statistics(turns, s.nominal);
    const StatisticValues model = response_statistics(s.clearance_revolutions, s.nominal);
    if (!(measured.value[spread] > 0) || !(model.value[spread] > 0)) continue;
    r["metrics"][key]["magnification"]["scatter_relative_error"] =
        std::hypot(measured.standard_error[spread] / measured.value[spread], model.standard_error[spread] / model.value[spread]);
  }
}

}  // namespace

json process_recording(const std::filesystem::path& recording, const AnalyzeOptions& options,
                       const TheorySettings& settings, const TheorySettings* fitted, const ModelFamilySettings& family) {
  try {
    AnalyzeOptions with_excerpt = options;
    with_excerpt.excerpt_revolutions = kExcerptRevolutions;
    DeviationMapCollector map;
    const RecordingAnalysis a = analyze_recording(recording, {}, with_excerpt, &map);
    if (!a.coupler && !a.rocker)
      throw InputError(recording.string() + ": no tangential channel on the coupler or the rocker; the comparison needs one");
    const MeasuredResponse measured = measured_response(a);
    auto theory_at = [&](const TheorySettings& s) {
      MatchedTheory t;
      try {
        t = simulate_matched_theory(*a.rig, a.clearance_m, a.mean_crank_speed_rad_s, measured.grid, s);
      } catch (const InputError& e) {
        throw InputError(a.manifest_file.string() + ": " + e.what());
      }
      // ω as the measurement's is made: the model's α integrated turn by turn
      // (report/theory_omega.hpp), from α before the pass band, whose ideal
      // filter over the turns one after the other gives each turn's α a mean
      // of its own; ω is not filtered after (integration already cuts the
      // high orders by 1/order, and turn by turn nothing is left below one).
      MatchedTheory integrated = t;
      const bool replaced = integrate_theory_omega(integrated, *a.rig, a.options.integration);
      apply_pass_band(t, a.filter);
      if (replaced)
        for (LinkQuantity q : {LinkQuantity::omega3, LinkQuantity::omega4}) {
          t.series[index_of(q)].clearance = integrated.series[index_of(q)].clearance;
          t.series[index_of(q)].clearance_revolutions = integrated.series[index_of(q)].clearance_revolutions;
        }
      return t;
    };
    const MatchedTheory t = theory_at(settings);
    const RecordingComparison c = compare_response(measured, t);
    json r = recording_record(a, measured, t, c);
    add_scatter_errors(r, a, t);
    {
      const LinkQuantity q = a.coupler ? LinkQuantity::alpha3 : LinkQuantity::alpha4;
      const LinkResult& link = a.coupler ? *a.coupler : *a.rocker;
      const TheorySeries& ts = t.series[index_of(q)];
      const bool has_top = a.filter.band == BandType::lowpass || a.filter.band == BandType::bandpass;
      ModelFamilyCheck check = check_model_family(link.alpha_grid, ts.clearance_revolutions, ts.nominal,
                                                  std::abs(a.mean_crank_speed_rad_s) / units::kTwoPi,
                                                  has_top ? a.filter.high_hz : 0.0, family);
      // The rig's modal data: the elastic-link reference says where the
      // links' vibration lies (compare/link_vibration.hpp).
      json vibration;
      if (check.checked && (a.rig->coupler_elastic || a.rig->rocker_elastic)) {
        ElasticReferenceRun where;
        where.rig = a.rig.get();
        where.clearance_m = a.clearance_m;
        where.crank_speed_rad_s = a.mean_crank_speed_rad_s;
        where.grid = measured.grid;
        where.filter = a.filter;
        where.name = a.recording.filename().string();
        where.sensor = tangential_mounts(*a.rig, a.manifest_file);
        const ElasticReference ref = elastic_reference(where, settings, family, check.checked_up_to_hz);
        if (ref.theory) {
          const LinkVibrationCheck lv = check_link_vibration(
              check, link.alpha_grid, ts.clearance_revolutions, ref.rigid_links->series[index_of(q)].clearance_revolutions,
              ref.theory->series[index_of(q)].clearance_revolutions, ts.nominal);
          vibration = link_vibration_json(lv);
          vibration["reference"] = ref.description;
        } else {
          vibration = {{"checked", false}, {"not_checked", ref.not_run}};
        }
      }
      r["model_family"] = model_family_json(check);
      r["model_family"]["quantity"] = std::string(column_name(q));
      if (!vibration.is_null()) r["model_family"]["link_vibration"] = vibration;
    }
    r["operating_point"]["clearance_source"] = a.clearance_from_rig ? "rig file (clearance_mm = \"rig\")" : "manifest";
    if (fitted) {
      // The same theory path at the fitted contact parameters.
      const MatchedTheory tf = theory_at(*fitted);
      const json f = comparison_record(measured, tf, compare_response(measured, tf));
      json series = json::object();
      for (const auto& [q, s] : f["series"].items())
        series[q] = {{"clearance", s["clearance"]}, {"clearance_std", s["clearance_std"]}};
      r["fitted_theory"] = {{"settings", f["theory"]["settings"]},
                            {"severity", f["theory"]["severity"]},
                            {"metrics", f["metrics"]},
                            {"series", series}};
      for (auto& [q, m] : r["fitted_theory"]["metrics"].items()) m["magnification"].erase("orders");
    }
    if (a.setup_check) {
      r["status"] = analysed_status(*a.setup_check);
      r["setup_check"] = setup_check_json(*a.setup_check, a.manifest_file.filename().string());
    }
    r["views"] = views_record(a, map, r);
    return r;
  } catch (const InputError& e) {
    return {{"status", "failed"}, {"error_kind", "input"}, {"error", e.what()}};
  } catch (const RunError& e) {
    return {{"status", "failed"}, {"error_kind", "run"}, {"error", e.what()}};
  } catch (const std::exception& e) {
    return {{"status", "failed"}, {"error_kind", "run"}, {"error", std::string("internal error: ") + e.what()}};
  }
}

}  // namespace fourbar
