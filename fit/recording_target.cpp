#include "fit/recording_target.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

std::string_view name_of(FitLink l) { return l == FitLink::coupler ? "alpha3" : "alpha4"; }

namespace {

constexpr std::size_t kMinTurns = 8;

LinkQuantity quantity_of(FitLink l) { return l == FitLink::coupler ? LinkQuantity::alpha3 : LinkQuantity::alpha4; }

}  // namespace

std::optional<AnalyzeOptions> band_analysis_options(const RecordingAnalysis& a, AnalyzeOptions base,
                                                    double band_top_hz) {
  const double fs = a.acquisition.recording.sample_rate_hz;
  if (a.filter.band != BandType::bandpass && a.filter.band != BandType::lowpass) return std::nullopt;
  const double low = a.filter.high_hz;
  const double high = band_top_hz > 0 ? std::min(band_top_hz, kBandTopPerSampleRate * fs) : kBandTopPerSampleRate * fs;
  if (!(high >= 2 * low)) return std::nullopt;
  const double crank_hz = std::abs(a.mean_crank_speed_rad_s) / units::kTwoPi;
  const double fastest_hz = std::max(crank_hz, a.acquisition.speed.max_rpm / 60.0);
  const auto needed = static_cast<std::size_t>(std::ceil(high / (0.4 * 0.95 * fastest_hz)));
  const std::size_t n = a.grid_points_per_rev;
  base.filter.band = BandType::bandpass;
  base.filter.low_hz = low, base.filter.high_hz = high;
  base.grid_points_per_rev = n * ((needed + n - 1) / n);
  return base;
}

RecordingTarget make_recording_target(const RecordingAnalysis& a, const RecordingAnalysis* band,
                                      const std::string& name) {
  RecordingTarget t;
  t.name = name;
  t.rig = a.rig;
  t.clearance_m = a.clearance_m;
  t.crank_speed_rad_s = a.mean_crank_speed_rad_s;
  t.grid.grid_points_per_rev = a.grid_points_per_rev;
  t.grid.start_rad = a.crank_deg.empty() ? 0.0 : units::deg_to_rad(a.crank_deg[0]);
  t.grid.direction = a.crank_direction;
  t.filter = a.filter;
  t.turns = a.revolutions;
  if (!a.rig) throw InputError(name + ": the analysis has no rig");
  if (!(a.clearance_m > 0))
    throw InputError(name + ": the manifest gives no radial clearance (clearance_mm); the fit needs the bearing's clearance");
  if (a.revolutions < kMinTurns)
    throw InputError(name + ": " + std::to_string(a.revolutions) + " analysed turns; the fit needs at least " +
                     std::to_string(kMinTurns) + " (record longer)");
  // The nominal response on the grid through the pass band: a matched theory
  // of one turn carries it (its clearance part is not used).
  MatchedTheory nominal = simulate_matched_theory(*t.rig, t.clearance_m, t.crank_speed_rad_s, t.grid,
                                                  theory_settings({}, 0, 1, 1e-6));
  apply_pass_band(nominal, t.filter);
  const std::array<const std::optional<LinkResult>*, 2> links{&a.coupler, &a.rocker};
  for (FitLink l : kFitLinks) {
    const auto i = static_cast<std::size_t>(l);
    t.nominal[i] = nominal.series[index_of(quantity_of(l))].nominal;
    const std::optional<LinkResult>& link = *links[i];
    if (!link) continue;
    if (link->alpha_grid.size() != a.revolutions * a.grid_points_per_rev)
      throw RunError(name + ": the analysis did not keep every turn (keep_revolutions)");
    t.measured[i] = response_statistics(link->alpha_grid, t.nominal[i]);
    t.repeat[i] = link->alpha_repeat;  // over the same turns, streamed by the analysis
  }
  if (band && band->grid_points_per_rev % t.grid.grid_points_per_rev == 0 && band->revolutions >= kMinTurns) {
    t.band_filter = band->filter;
    t.band_grid_points_per_rev = band->grid_points_per_rev;
    const std::array<const std::optional<LinkResult>*, 2> band_links{&band->coupler, &band->rocker};
    for (std::size_t i = 0; i < 2; ++i)
      if (*band_links[i] && t.measured[i]) t.measured_band[i] = band_energy((*band_links[i])->alpha_grid, t.band_grid_points_per_rev);
  }
  for (std::size_t i = 0; i < 2; ++i) {
    if (!t.measured[i]) continue;
    BandEnergy e;
    if (t.measured_band[i]) {
      e = *t.measured_band[i];
    } else {
      std::vector<double> dev = (*links[i])->alpha_grid;
      const std::vector<double>& mean = (*links[i])->alpha_rad_s2.mean;
      const std::size_t n = t.grid.grid_points_per_rev;
      for (std::size_t j = 0; j < dev.size(); ++j) dev[j] -= mean[j % n];
      e = band_energy(dev, n);
    }
    t.effect_ratio = std::max(t.effect_ratio, e.floor > 0 ? e.excess / e.floor : (e.excess > 0 ? 1e9 : 0.0));
  }
  if (!t.measured[0] && !t.measured[1])
    throw InputError(name + ": neither a coupler nor a rocker tangential channel; the fit needs at least one");
  return t;
}

TheorySettings theory_settings(const ContactParameters& p, int warmup, int turns, double tolerance) {
  TheorySettings s;
  s.restitution = p.restitution;
  s.contact = p.contact;
  s.friction_coefficient = p.contact == ContactLaw::stick_slip ? p.friction_coefficient : 0.0;
  s.warmup_revolutions = warmup;
  s.averaged_revolutions = turns;
  s.tolerance = tolerance;
  return s;
}

SimulatedStatistics simulate_statistics(const RecordingTarget& t, const ContactParameters& p, int warmup, int turns,
                                        double tolerance, const ModellingChoices& choices) {
  TheorySettings settings = theory_settings(p, warmup, turns, tolerance);
  settings.settle_speed_m_s = choices.settle_speed_m_s;
  settings.point_samples = choices.point_samples;
  // With a band: one run on the band's finer grid; the analysis band is its
  // every k-th point after the analysis pass band (the grids share angle 0).
  CrankGrid fine = t.grid;
  if (t.band_filter) fine.grid_points_per_rev = t.band_grid_points_per_rev;
  MatchedTheory th = simulate_matched_theory(*t.rig, t.clearance_m, t.crank_speed_rad_s, fine, settings);
  return statistics_of_theory(t, std::move(th), turns);
}

SimulatedStatistics statistics_of_theory(const RecordingTarget& t, MatchedTheory th, int turns) {
  const CrankGrid fine = th.grid;
  SimulatedStatistics out;
  if (t.band_filter) {
    MatchedTheory band = th;
    apply_pass_band(band, *t.band_filter);
    for (FitLink l : kFitLinks) {
      const auto i = static_cast<std::size_t>(l);
      if (t.measured_band[i])
        out.band[i] = band_energy(band.series[index_of(quantity_of(l))].clearance_revolutions, fine.grid_points_per_rev);
    }
    apply_pass_band(th, t.filter);
    const std::size_t k = fine.grid_points_per_rev / t.grid.grid_points_per_rev;
    for (TheorySeries& s : th.series) {
      auto decimate = [k](std::vector<double>& v) {
        for (std::size_t j = 0; j * k < v.size(); ++j) v[j] = v[j * k];
        v.resize(v.size() / k);
      };
      decimate(s.nominal), decimate(s.clearance_revolutions);
    }
  } else {
    apply_pass_band(th, t.filter);
  }
  out.turns = turns;
  out.impacts_per_rev = th.severity.impacts_per_rev;
  out.sum_normal_impulse_per_rev_Ns = th.severity.sum_normal_impulse_per_rev_Ns;
  for (FitLink l : kFitLinks) {
    const auto i = static_cast<std::size_t>(l);
    if (!t.measured[i]) continue;
    const TheorySeries& s = th.series[index_of(quantity_of(l))];
    out.link[i] = response_statistics(s.clearance_revolutions, s.nominal);
    out.repeat[i] = turn_repeat(s.clearance_revolutions, t.grid.grid_points_per_rev);
  }
  return out;
}

}  // namespace fourbar
