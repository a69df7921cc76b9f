#include "compare/matched_theory.hpp"

#include <algorithm>
#include <cmath>

#include "analyze/fft_filter.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "sim/drive/crank_motion.hpp"
#include "sim/run/clearance_simulation.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {

namespace {

double wrap_deg(double deg) {
  const double w = std::fmod(deg, 360.0);
  return w < 0 ? w + 360.0 : w;
}

void check(bool ok, const std::string& key, double value, const std::string& rule) {
  if (!ok) throw InputError("theory setting '" + key + "' = " + std::to_string(value) + ": " + rule);
}

/// The averaged turns of either clearance simulator.
void run_model(ClearanceSimulation& sim, const CrankGrid& grid, const ConstantSpeedCrank& crank, const TheorySettings& settings,
               MatchedTheory& out);

}  // namespace

ClearanceSettings clearance_settings(const Rig& rig, double clearance_m, const TheorySettings& settings) {
  ClearanceSettings cs;
  cs.radial_clearance_m = clearance_m;
  cs.model = settings.model;
  cs.restitution = settings.restitution;
  cs.contact = settings.contact;
  cs.friction_coefficient = settings.friction_coefficient;
  cs.tolerance = settings.tolerance;
  cs.settle_speed_m_s = settings.settle_speed_m_s;
  const std::string source = settings.source.empty() ? std::string("[theory]") : settings.source;
  if (settings.model == ClearanceKind::compliant) {
    cs.compliant = settings.compliant;
    resolve_contact_stiffness(rig, clearance_m, cs, [&](const char* key, const std::string& what) {
      throw InputError("theory setting '" + std::string(key) + "' (" + source + ") " + what);
    });
  } else if (rig.bearing.lubricant_viscosity_Pa_s) {
    throw InputError("theory setting 'model' (" + source + ") is the three-mode model, which has no lubricant film, "
                     "but " + (rig.source.empty() ? std::string("the rig") : rig.source.string()) +
                     "'s bearing is lubricated (lubricant_viscosity_Pa_s); use model = \"compliant\"");
  }
  return cs;
}

MatchedTheory simulate_matched_theory(const Rig& rig, double clearance_m, double crank_speed_rad_s,
                                      const CrankGrid& grid, const TheorySettings& settings) {
  check(std::isfinite(crank_speed_rad_s) && crank_speed_rad_s != 0, "crank_speed_rad_s", crank_speed_rad_s,
        "the crank must turn");
  check(clearance_m > 0 && std::isfinite(clearance_m), "clearance_mm", units::m_to_mm(clearance_m),
        "the clearance model needs a radial clearance > 0");
  check(settings.warmup_revolutions >= 0, "warmup_revolutions", settings.warmup_revolutions, "must be >= 0");
  check(settings.averaged_revolutions >= 1, "averaged_revolutions", settings.averaged_revolutions, "must be >= 1");
  check(grid.grid_points_per_rev >= 8, "points_per_rev", static_cast<double>(grid.grid_points_per_rev), "must be >= 8");

  MatchedTheory out;
  out.grid = grid;
  out.crank_speed_rad_s = crank_speed_rad_s;
  out.clearance_m = clearance_m;
  out.settings = settings;
  const std::size_t n = grid.grid_points_per_rev;
  const double w = std::abs(crank_speed_rad_s);
  const double cell_s = units::kTwoPi / (static_cast<double>(n) * w);  // time between grid points

  // Nominal: ω at the grid points and half-way between them; α as cell means.
  auto nominal_at = [&](double k) { return solve_motion(rig, CrankState{grid.angle_rad(k), crank_speed_rad_s, 0.0}); };
  for (LinkQuantity q : kLinkQuantities) out.series[index_of(q)].nominal.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double kk = static_cast<double>(k);
    const NominalMotion m = nominal_at(kk), lo = nominal_at(kk - 0.5), hi = nominal_at(kk + 0.5);
    out.series[index_of(LinkQuantity::omega3)].nominal[k] = m.omega3_rad_s;
    out.series[index_of(LinkQuantity::omega4)].nominal[k] = m.omega4_rad_s;
    out.series[index_of(LinkQuantity::alpha3)].nominal[k] = (hi.omega3_rad_s - lo.omega3_rad_s) / cell_s;
    out.series[index_of(LinkQuantity::alpha4)].nominal[k] = (hi.omega4_rad_s - lo.omega4_rad_s) / cell_s;
  }

  // Clearance model: the nominal start at the grid's first angle, `warm`
  // turns, then samples at every half grid cell of the averaged turns.
  const ClearanceSettings cs = clearance_settings(rig, clearance_m, settings);
  out.settings.compliant = cs.compliant;  // with the stiffness it used
  const ClearanceModel model(rig, clearance_m);
  const ConstantSpeedCrank crank(grid.start_rad, crank_speed_rad_s);
  run_model(*make_clearance_simulation(model, crank, cs), grid, crank, settings, out);
  return out;
}

namespace {

void run_model(ClearanceSimulation& sim, const CrankGrid& grid, const ConstantSpeedCrank& crank, const TheorySettings& settings,
               MatchedTheory& out) {
  const std::size_t n = grid.grid_points_per_rev, turns = static_cast<std::size_t>(settings.averaged_revolutions);
  const int warm = settings.warmup_revolutions;
  sim.set_revolution_origin(grid.start_rad);
  sim.start_nominal(0.0);
  auto time_at = [&](double turns_from_start) {
    return crank.time_at_angle(grid.start_rad + grid.direction * units::kTwoPi * turns_from_start);
  };
  const std::size_t half_points = 2 * n * turns + 1;  // from half a cell before the first grid point
  std::vector<double> times(half_points);
  for (std::size_t j = 0; j < half_points; ++j)
    times[j] = time_at(warm + (static_cast<double>(j) - 1.0) / (2.0 * static_cast<double>(n)));
  if (warm == 0) times[0] = 0.0, times[1] = std::max(times[1], 0.0);  // the run cannot start before t = 0
  sim.set_sample_times(times);
  sim.advance_to(time_at(warm + static_cast<double>(turns)));
  const auto& samples = sim.samples();
  if (samples.size() != half_points)
    throw RunError("clearance model: " + std::to_string(samples.size()) + " samples instead of " +
                   std::to_string(half_points));

  for (LinkQuantity q : kLinkQuantities) out.series[index_of(q)].clearance_revolutions.resize(n * turns);
  for (std::size_t i = 0; i < n * turns; ++i) {
    const ClearanceSample &lo = samples[2 * i], &mid = samples[2 * i + 1], &hi = samples[2 * i + 2];
    const double dt = hi.time_s - lo.time_s;
    out.series[index_of(LinkQuantity::omega3)].clearance_revolutions[i] = mid.links.omega3_rad_s;
    out.series[index_of(LinkQuantity::omega4)].clearance_revolutions[i] = mid.links.omega4_rad_s;
    out.series[index_of(LinkQuantity::alpha3)].clearance_revolutions[i] =
        settings.point_samples ? mid.alpha3_rad_s2 : (hi.links.omega3_rad_s - lo.links.omega3_rad_s) / dt;
    out.series[index_of(LinkQuantity::alpha4)].clearance_revolutions[i] =
        settings.point_samples ? mid.alpha4_rad_s2 : (hi.links.omega4_rad_s - lo.links.omega4_rad_s) / dt;
  }
  for (auto& s : out.series) s.clearance = synchronous_average(s.clearance_revolutions, n);

  // Impacts and per-turn severity in the averaged turns.
  for (const ImpactRecord& r : sim.impacts()) {
    if (r.revolution < warm || r.revolution >= warm + static_cast<int>(turns)) continue;
    BearingImpact b;
    b.revolution = r.revolution - warm;
    b.turned_deg = wrap_deg(units::rad_to_deg(grid.direction * (r.crank_angle_rad - grid.start_rad)));
    b.normal_impulse_Ns = r.result.normal_impulse_Ns;
    b.global_deg = wrap_deg(units::rad_to_deg(r.eta_rad));
    b.pin_deg = wrap_deg(units::rad_to_deg(r.eta_rad - r.theta3_rad));
    b.bushing_deg = wrap_deg(units::rad_to_deg(r.eta_rad - r.theta4_rad));
    out.impacts.push_back(b);
  }
  TheorySeverity& sv = out.severity;
  double following = 0, total = 0, sum_f = 0;
  int sum_n = 0, losses = 0;
  for (const RevolutionRecord& r : sim.revolutions()) {
    if (r.index < warm || r.index >= warm + static_cast<int>(turns)) continue;
    sv.impacts_by_rev.push_back(r.impacts);
    sv.sum_impulse_by_rev_Ns.push_back(r.sum_normal_impulse_Ns);
    sum_n += r.impacts, sum_f += r.sum_normal_impulse_Ns, losses += r.contact_losses;
    following += r.following_time_s, total += r.following_time_s + r.free_time_s;
  }
  const double nt = static_cast<double>(std::max<std::size_t>(1, sv.impacts_by_rev.size()));
  sv.impacts_per_rev = sum_n / nt;
  sv.sum_normal_impulse_per_rev_Ns = sum_f / nt;
  if (sum_n > 0) sv.impact_index_Ns = sum_f / sum_n;
  sv.contact_losses_per_rev = losses / nt;
  sv.following_share = total > 0 ? following / total : 1.0;
  ClearanceDiagnostics d = sim.diagnostics();
  out.energy_residual_rel = d.energy_scale_J > 0 ? d.max_energy_residual_J / d.energy_scale_J : 0.0;
  out.max_penetration_rel = d.max_penetration;
}

}  // namespace

void apply_pass_band(MatchedTheory& theory, const FilterSpec& spec_in) {
  const std::size_t n = theory.grid.grid_points_per_rev;
  const double fs = static_cast<double>(n) * std::abs(theory.crank_speed_rad_s) / units::kTwoPi;
  FilterSpec spec = spec_in;
  spec.window = WindowSpec{};
  spec.transition_hz = 0;
  // A corner at or above the grid's Nyquist frequency passes everything there.
  const double nyquist = fs / 2;
  if (spec.band == BandType::lowpass && spec.high_hz >= nyquist) spec.band = BandType::all_pass;
  if (spec.band == BandType::bandpass && spec.high_hz >= nyquist) spec.band = BandType::highpass;
  if (spec.band == BandType::all_pass && spec.mains_hz == 0) return;
  auto filter = [&](std::vector<double>& x, bool keep_mean) {
    const std::size_t rows = x.size() / n;
    std::vector<double> mean(rows, 0.0);
    for (std::size_t r = 0; r < rows; ++r)
      for (std::size_t k = 0; k < n; ++k) mean[r] += x[r * n + k] / static_cast<double>(n);
    FftFilter f(spec, fs, x.size(), rows > 1 ? Boundary::reflect : Boundary::periodic);
    f.apply(x, x);
    if (!keep_mean) return;
    for (std::size_t r = 0; r < rows; ++r) {
      double m = 0;
      for (std::size_t k = 0; k < n; ++k) m += x[r * n + k] / static_cast<double>(n);
      for (std::size_t k = 0; k < n; ++k) x[r * n + k] += mean[r] - m;
    }
  };
  for (LinkQuantity q : kLinkQuantities) {
    TheorySeries& s = theory.series[index_of(q)];
    const bool keep_mean = !is_acceleration(q);
    filter(s.nominal, keep_mean);
    filter(s.clearance_revolutions, keep_mean);
    s.clearance = synchronous_average(s.clearance_revolutions, n);
  }
}

}  // namespace fourbar
