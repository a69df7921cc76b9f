#include "report/comparison_record.hpp"

#include <cmath>

#include "common/units.hpp"
#include "compare/session_severity.hpp"
#include "report/setup_check_record.hpp"

namespace fourbar {

namespace {

using nlohmann::json;

json optional_json(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json quantity_metrics(const QuantityComparison& c) {
  const Magnification& m = c.magnification;
  json orders = json::array();
  for (const OrderRatio& o : m.orders)
    orders.push_back({{"order", o.order},
                      {"measured_amplitude", o.measured_amplitude},
                      {"simulated_amplitude", o.simulated_amplitude},
                      {"measured_floor", o.measured_floor},
                      {"significant", o.significant},
                      {"mains", o.mains},
                      {"factor", optional_json(o.factor)}});
  return {{"measured_rms", c.measured_rms},
          {"simulated_rms", c.simulated_rms},
          {"nominal_rms", c.nominal_rms},
          {"rms_difference_simulated", c.rms_difference_simulated},
          {"rms_difference_nominal", c.rms_difference_nominal},
          {"correlation_simulated", c.correlation_simulated},
          {"correlation_nominal", c.correlation_nominal},
          {"peak_ratio_simulated", c.peak_ratio_simulated},
          {"peak_ratio_nominal", c.peak_ratio_nominal},
          {"measured_bursts_deg", c.measured_bursts_deg},
          {"simulated_bursts_deg", c.simulated_bursts_deg},
          {"largest_burst_offset_deg", c.largest_burst_offset_deg},
          {"magnification",
           {{"measured_deviation_rms", m.measured_deviation_rms},
            {"simulated_deviation_rms", m.simulated_deviation_rms},
            {"time_domain", optional_json(m.time_domain)},
            {"spectral", optional_json(m.spectral)},
            {"spectral_method", m.spectral_method},
            {"orders_used", m.orders_used},
            {"nominal_band_orders", m.nominal_band_orders},
            {"floor_rms", m.floor_rms},
            {"effect_to_floor", optional_json(m.effect_to_floor)},
            {"model_effect_to_floor", optional_json(m.model_effect_to_floor)},
            {"orders", orders}}}};
}

std::optional<double> opt(const json& j, const char* key) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  return j[key].get<double>();
}

}  // namespace

json theory_settings_json(const TheorySettings& t) {
  json j = {{"restitution", t.restitution},
            {"contact", to_string(t.contact)},
            {"friction_coefficient", t.friction_coefficient},
            {"warmup_revolutions", t.warmup_revolutions},
            {"averaged_revolutions", t.averaged_revolutions},
            {"tolerance", t.tolerance},
            {"max_order", t.max_order}};
  if (t.model == ClearanceKind::compliant) {  // (the three-mode settings as before: cached records stay valid)
    const CompliantSettings& k = t.compliant;
    j["contact"] = std::string("compliant, ") + to_string(k.damping) + " damping";  // (the HTML report's theory cell)
    j["model"] = to_string(t.model);
    j["damping"] = to_string(k.damping);
    j["contact_stiffness_N_per_m_n"] = k.stiffness_N_per_m_n > 0 ? json(k.stiffness_N_per_m_n) : json("from the rig");
    j["contact_exponent"] = k.exponent;
    j["friction_stick_speed_mm_s"] = k.friction_stick_speed_m_s * 1e3;
    j["friction_slip_speed_mm_s"] = k.friction_slip_speed_m_s * 1e3;
    j["damping_floor_speed_mm_s"] = k.damping_floor_speed_m_s * 1e3;
    if (k.film.viscosity_Pa_s > 0) {  // (a dry bearing's record as before)
      j["lubricant_viscosity_Pa_s"] = k.film.viscosity_Pa_s;
      j["film"] = to_string(k.film.extent);
      j["film_break_eccentricity"] = k.film.break_eccentricity;
    }
  }
  return j;
}

json comparison_record(const MeasuredResponse& measured, const MatchedTheory& t, const RecordingComparison& c) {
  std::size_t revolutions = 0;
  for (const auto& s : measured.series)
    if (s) revolutions = std::max(revolutions, s->revolution_count);
  // Crank angles θ2 from the ground line (the pulse angle plus the turned angle).
  auto theta2_deg = [&](double turned_deg) {
    return units::rad_to_deg(t.grid.start_rad) + t.grid.direction * turned_deg;
  };
  json r;
  r["status"] = "ok";
  r["operating_point"] = {{"speed_rpm", units::rad_s_to_rpm(std::abs(measured.crank_speed_rad_s))},
                          {"direction", t.grid.direction > 0 ? "ccw" : "cw"},
                          {"clearance_mm", units::m_to_mm(t.clearance_m)},
                          {"revolutions_averaged", revolutions}};
  json sev = {{"impacts_per_rev", t.severity.impacts_per_rev},
              {"sum_normal_impulse_per_rev_Ns", t.severity.sum_normal_impulse_per_rev_Ns},
              {"impact_index_Ns", optional_json(t.severity.impact_index_Ns)},
              {"contact_losses_per_rev", t.severity.contact_losses_per_rev},
              {"following_share", t.severity.following_share},
              {"impacts_by_rev", t.severity.impacts_by_rev},
              {"sum_impulse_by_rev_Ns", t.severity.sum_impulse_by_rev_Ns}};
  r["theory"] = {{"settings", theory_settings_json(t.settings)},
                 {"crank_speed_rpm", units::rad_s_to_rpm(std::abs(t.crank_speed_rad_s))},
                 {"clearance_mm", units::m_to_mm(t.clearance_m)},
                 {"severity", sev},
                 {"energy_residual_rel", t.energy_residual_rel},
                 {"max_penetration_rel", t.max_penetration_rel}};
  std::vector<double> deg(t.grid.grid_points_per_rev);
  for (std::size_t k = 0; k < deg.size(); ++k) deg[k] = theta2_deg(t.grid.turned_deg(k));
  r["grid"] = {{"crank_deg", deg}, {"pulse_angle_deg", units::rad_to_deg(t.grid.start_rad)}};
  json series = json::object(), metrics = json::object();
  for (LinkQuantity q : kLinkQuantities) {
    const TheorySeries& ts = t.series[index_of(q)];
    json s = {{"nominal", ts.nominal}, {"clearance", ts.clearance.mean}, {"clearance_std", ts.clearance.std}};
    if (const auto& m = measured.series[index_of(q)]) {
      s["measured"] = m->mean;
      s["measured_std"] = m->std;
    }
    if (const auto& qc = c.quantities[index_of(q)]) {
      s["modified"] = qc->magnification.modified;
      json mj = quantity_metrics(*qc);
      for (const char* key : {"measured_bursts_deg", "simulated_bursts_deg"})
        for (json& v : mj[key]) v = theta2_deg(v.get<double>());
      metrics[std::string(column_name(q))] = mj;
    }
    series[std::string(column_name(q))] = s;
  }
  r["series"] = series;
  r["metrics"] = metrics;
  json impacts = json::array();
  for (const BearingImpact& b : t.impacts)
    impacts.push_back({{"crank_deg", theta2_deg(b.turned_deg)},
                       {"revolution", b.revolution},
                       {"normal_impulse_Ns", b.normal_impulse_Ns},
                       {"pin_deg", b.pin_deg},
                       {"bushing_deg", b.bushing_deg},
                       {"global_deg", b.global_deg}});
  r["impacts"] = impacts;
  r["acquisition"] = json::object();
  r["analysis"] = json::object();
  r["spectra"] = json::object();
  r["warnings"] = json::array();
  return r;
}

json severity_record(const json& records) {
  std::vector<SeverityPoint> points;
  for (const json& r : records) {
    if (!is_analysed(r)) continue;
    SeverityPoint p;
    p.recording = r["name"];
    p.clearance_mm = r["operating_point"]["clearance_mm"];
    p.speed_rpm = r["operating_point"]["speed_rpm"];
    const json& m = r["metrics"];
    if (m.contains("alpha3_rad_s2")) {
      p.measured_alpha3_fluctuation_rms = m["alpha3_rad_s2"]["magnification"]["measured_deviation_rms"].get<double>();
      p.simulated_alpha3_fluctuation_rms = m["alpha3_rad_s2"]["magnification"]["simulated_deviation_rms"].get<double>();
      p.magnification_alpha3 = opt(m["alpha3_rad_s2"]["magnification"], "time_domain");
    }
    if (m.contains("alpha4_rad_s2"))
      p.measured_alpha4_fluctuation_rms = m["alpha4_rad_s2"]["magnification"]["measured_deviation_rms"].get<double>();
    const json& sv = r["theory"]["severity"];
    p.impacts_per_rev = sv["impacts_per_rev"];
    p.sum_normal_impulse_per_rev_Ns = sv["sum_normal_impulse_per_rev_Ns"];
    p.impact_index_Ns = opt(sv, "impact_index_Ns");
    points.push_back(p);
  }
  auto point_json = [](const SeverityPoint& p) {
    auto o = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
    return json{{"recording", p.recording},
                {"clearance_mm", p.clearance_mm},
                {"speed_rpm", p.speed_rpm},
                {"measured_alpha3_fluctuation_rms", o(p.measured_alpha3_fluctuation_rms)},
                {"measured_alpha4_fluctuation_rms", o(p.measured_alpha4_fluctuation_rms)},
                {"simulated_alpha3_fluctuation_rms", o(p.simulated_alpha3_fluctuation_rms)},
                {"impacts_per_rev", p.impacts_per_rev},
                {"sum_normal_impulse_per_rev_Ns", p.sum_normal_impulse_per_rev_Ns},
                {"impact_index_Ns", o(p.impact_index_Ns)},
                {"magnification_alpha3", o(p.magnification_alpha3)}};
  };
  auto groups_json = [&](const std::vector<SeverityGroup>& groups) {
    json a = json::array();
    for (const SeverityGroup& g : groups) {
      json pts = json::array();
      for (const auto& p : g.points) pts.push_back(point_json(p));
      a.push_back({{"value", g.value}, {"points", pts}});
    }
    return a;
  };
  const SeverityTables t = severity_tables(points);
  return {{"by_speed", groups_json(t.by_speed)}, {"by_clearance", groups_json(t.by_clearance)}};
}


}  // namespace fourbar
