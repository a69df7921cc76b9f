#include "sim/studies/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "common/error.hpp"
#include "common/csv_writer.hpp"
#include "common/mean_standard_error.hpp"
#include "common/toml_section.hpp"
#include "common/units.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "sim/run/clearance_simulation.hpp"

namespace fourbar {

SweepGrid load_sweep(const std::filesystem::path& file, Scene& base) {
  const toml::table doc = parse_toml_file(file);
  // Arrays of numbers are read from `doc` directly (errors through `full`);
  // everything else through `root`, which then rejects unknown keys.
  const TomlSection full(doc, file);
  toml::table rest = doc;
  for (const char* key : {"radial_mm", "crank_speed_rpm", "restitution", "friction_coefficient"}) rest.erase(key);
  TomlSection root(rest, file);
  const std::filesystem::path scene_file = root.path("scene");
  try {
    base = load_scene(scene_file);
  } catch (const InputError& e) {
    throw InputError(root.where("scene") + ": " + e.what());
  }
  if (base.model != Model::clearance) root.fail("scene", "must be a scene with model = \"clearance\"");
  SweepGrid g;
  auto array = [&](std::string_view key, double lo, double hi, double fallback, double to_si) {
    std::vector<double> out;
    if (!doc.contains(key)) return std::vector<double>{fallback * to_si};  // `fallback` is in the file's unit
    const toml::array* arr = doc[key].as_array();
    if (!arr || arr->empty()) full.fail(key, "must be a non-empty array of numbers, e.g. [0.1, 0.2]");
    for (const auto& el : *arr) {
      std::optional<double> v;
      if (el.is_floating_point()) v = el.as_floating_point()->get();
      if (el.is_integer()) v = static_cast<double>(el.as_integer()->get());
      if (!v || !std::isfinite(*v) || *v < lo || *v > hi)
        full.fail(key, "must hold numbers in [" + format_double(lo) + ", " + format_double(hi) + "]");
      out.push_back(*v * to_si);
    }
    return out;
  };
  g.radial_clearance_m = array("radial_mm", 1e-9, 100, units::m_to_mm(base.clearance_m()), 1e-3);
  for (double xi : g.radial_clearance_m)
    if (const double margin = toggle_margin_m(*base.rig); !(xi < margin))
      full.fail("radial_mm", "holds " + format_double(units::m_to_mm(xi)) + " mm: the rig's loop comes within " +
                                 format_double(std::round(units::m_to_mm(margin) * 1e6) / 1e6) +
                                 " mm of a toggle, so the pin on the bushing wall cannot close it; use clearances "
                                 "below that");
  g.crank_speed_rad_s = array("crank_speed_rpm", -1e5, 1e5, units::rad_s_to_rpm(base.crank_speed_rad_s),
                              units::kTwoPi / 60.0);
  for (double w : g.crank_speed_rad_s)
    if (w == 0) full.fail("crank_speed_rpm", "holds 0: the crank must turn");
  g.restitution = array("restitution", 0, 1, base.clearance.restitution, 1.0);
  g.friction_coefficient = array("friction_coefficient", 0, 100, base.clearance.friction_coefficient, 1.0);
  if (doc.contains("friction_coefficient") && base.clearance.contact != ContactLaw::stick_slip &&
      base.clearance.model != ClearanceKind::compliant)
    full.fail("friction_coefficient", "needs a base scene with contact = \"stick-slip\" or model = \"compliant\"");
  g.revolutions = static_cast<int>(root.integer("revolutions", 1, 100000, SweepGrid{}.revolutions));
  g.skip_revolutions = static_cast<int>(root.integer("skip_revolutions", 0, 100000, SweepGrid{}.skip_revolutions));
  root.optional_string("notes");
  root.finish();
  return g;
}

std::vector<SweepPoint> sweep_points(const SweepGrid& g) {
  std::vector<SweepPoint> points;
  for (double xi : g.radial_clearance_m)
    for (double w : g.crank_speed_rad_s)
      for (double e : g.restitution)
        for (double mu : g.friction_coefficient) {
          SweepPoint p;
          p.radial_clearance_m = xi;
          p.crank_speed_rad_s = w;
          p.restitution = e;
          p.friction_coefficient = mu;
          points.push_back(p);
        }
  return points;
}

void compute_sweep_point(const Scene& base, const SweepGrid& g, SweepPoint& p) {
  try {
    ClearanceSettings s = base.clearance;
    s.restitution = p.restitution;
    s.friction_coefficient = p.friction_coefficient;
    // The scene's model: the compliant one's stiffness (when the rig's
    // bearing gives it) and film depend on the clearance, so per point.
    if (s.model == ClearanceKind::compliant)
      resolve_contact_stiffness(*base.rig, p.radial_clearance_m, s, [&](const char* key, const std::string& what) {
        throw RunError(std::string("[clearance] ") + key + " " + what);
      });
    const ClearanceModel model(*base.rig, p.radial_clearance_m);
    const ConstantSpeedCrank crank(base.start_angle_rad, p.crank_speed_rad_s);
    const std::unique_ptr<ClearanceSimulation> simulation = make_clearance_simulation(model, crank, s);
    ClearanceSimulation& sim = *simulation;
    sim.set_revolution_origin(base.start_angle_rad);
    sim.start_nominal(0.0);
    const int total = g.skip_revolutions + g.revolutions;
    sim.advance_to(
        crank.time_at_angle(base.start_angle_rad + (p.crank_speed_rad_s > 0 ? 1 : -1) * units::kTwoPi * total));
    double n = 0, sumF = 0, losses = 0, follow = 0, span = 0;
    std::vector<double> n_by_turn, sumF_by_turn;
    const auto& revs = sim.revolutions();
    for (int k = g.skip_revolutions; k < total && k < static_cast<int>(revs.size()); ++k) {
      n += revs[k].impacts;
      sumF += revs[k].sum_normal_impulse_Ns;
      n_by_turn.push_back(revs[k].impacts);
      sumF_by_turn.push_back(revs[k].sum_normal_impulse_Ns);
      losses += revs[k].contact_losses;
      follow += revs[k].following_time_s;
      span += revs[k].end_time_s - revs[k].start_time_s;
    }
    p.impacts_per_rev = n / g.revolutions;
    p.sum_normal_impulse_per_rev_Ns = sumF / g.revolutions;
    p.impact_index_Ns = n > 0 ? sumF / n : 0.0;
    // Standard error of a per-turn mean, the correlation between turns
    // counted (common/mean_standard_error.hpp): s/√turns · √τ.
    p.impacts_per_rev_standard_error = mean_standard_error(n_by_turn).standard_error;
    p.sum_normal_impulse_per_rev_standard_error_Ns = mean_standard_error(sumF_by_turn).standard_error;
    p.contact_losses_per_rev = losses / g.revolutions;
    p.following_share = span > 0 ? follow / span : 0.0;
    const ClearanceDiagnostics d = sim.diagnostics();
    p.energy_residual_rel = std::abs(d.energy_residual_J) / d.energy_scale_J;
    p.max_penetration_rel = d.max_penetration;
    p.error.clear();
  } catch (const RunError& e) {
    p.error = e.what();
  }
}

namespace {

double* result_fields(SweepPoint& p, std::size_t k) {
  double* fields[] = {&p.impacts_per_rev,        &p.sum_normal_impulse_per_rev_Ns, &p.impact_index_Ns,
                      &p.contact_losses_per_rev, &p.following_share,               &p.energy_residual_rel,
                      &p.max_penetration_rel,    &p.impacts_per_rev_standard_error,
                      &p.sum_normal_impulse_per_rev_standard_error_Ns};
  return k < std::size(fields) ? fields[k] : nullptr;
}

}  // namespace

std::string encode_sweep_result(const SweepPoint& p) {
  if (p.failed()) {
    std::string text = "failed ";
    for (char ch : p.error) text += (ch == '\n' || ch == '\r') ? ' ' : ch;  // one line
    return text;
  }
  std::string text = "ok";
  SweepPoint copy = p;
  for (std::size_t k = 0; double* v = result_fields(copy, k); ++k) {
    char buf[40];
    std::snprintf(buf, sizeof buf, " %a", *v);  // exact: hexadecimal floating point
    text += buf;
  }
  return text;
}

bool decode_sweep_result(std::string_view text, SweepPoint& p) {
  if (text.starts_with("failed ")) {
    p.error = std::string(text.substr(7));
    return !p.error.empty();
  }
  if (!text.starts_with("ok")) return false;
  const std::string s(text.substr(2));
  const char* at = s.c_str();
  SweepPoint out = p;
  for (std::size_t k = 0; double* v = result_fields(out, k); ++k) {
    char* end = nullptr;
    *v = std::strtod(at, &end);
    if (end == at || !std::isfinite(*v)) return false;
    at = end;
  }
  if (*at != '\0') return false;
  out.error.clear();
  p = out;
  return true;
}

}  // namespace fourbar
