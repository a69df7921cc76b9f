#include "fit/session_fit.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>

#include <nlopt.h>

#include "common/error.hpp"
#include "common/format.hpp"
#include "fit/matched_magnification.hpp"
#include "fit/nuisance_offset.hpp"
#include "fit/objective_surrogate.hpp"
#include "fit/orbit_search.hpp"
#include "fit/simulation_cache.hpp"

namespace fourbar {

namespace {

/// χ² of a failed simulation: worse than any real fit.
constexpr double kFailedChi2 = 1e12;

double transformed(ResponseStatistic s, double v) { return is_magnitude(s) ? std::log(std::max(v, 1e-30)) : v; }
double transformed_se(ResponseStatistic s, double v, double se) {
  return is_magnitude(s) ? se / std::max(std::abs(v), 1e-30) : se;
}

ContactParameters point(const FitOptions& o, const double* x) {
  ContactParameters p;
  p.restitution = x[0];
  if (o.fit_friction && x[1] > 0) p.contact = ContactLaw::stick_slip, p.friction_coefficient = x[1];
  return p;
}

/// One compared statistic where model and measurement differ most (before
/// the modelling offset is profiled out): what a rejection names.
struct WorstTerm {
  std::size_t recording = 0;
  std::string what;  ///< e.g. "spread of alpha3"
  double model = 0, measured = 0, measured_se = 0, model_se = 0;
  double z = 0;  ///< difference over its standard error (transformed scale)
};

struct Chi2 {
  double total = 0;
  int terms = 0;
  std::vector<double> by_recording;
  std::vector<int> terms_by_recording;
  std::vector<std::pair<std::string, double>> offsets;  ///< η̂ per compared statistic ("band_excess" last)
  std::optional<WorstTerm> worst;
};

/// One compared statistic's residuals over the recordings and links, with
/// the recording each belongs to; profiled together with a shared
/// log-offset (nuisance_offset.hpp).
struct StatisticResiduals {
  std::vector<double> d, var;
  std::vector<std::size_t> recording;
  void add(double residual, double variance, std::size_t r) { d.push_back(residual), var.push_back(variance), recording.push_back(r); }
};

Chi2 chi2_at(const SimulationCache& cache, const FitOptions& o, const ContactParameters& p) {
  const auto& targets = cache.targets();
  Chi2 c;
  c.by_recording.assign(targets.size(), 0.0);
  c.terms_by_recording.assign(targets.size(), 0);
  auto failed = [&](std::size_t r) {
    c.by_recording[r] += kFailedChi2, c.terms_by_recording[r] += 1;
    c.total += kFailedChi2, c.terms += 1;
  };
  std::vector<StatisticResiduals> per_statistic(o.statistics.size());
  StatisticResiduals band_residuals;
  for (std::size_t r = 0; r < targets.size(); ++r) {
    const CachedSimulation& sim = cache.at(r, p);
    for (FitLink l : kFitLinks) {
      const auto li = static_cast<std::size_t>(l);
      const auto& meas = targets[r].measured[li];
      if (!meas) continue;
      for (std::size_t k = 0; k < o.statistics.size(); ++k) {
        const ResponseStatistic s = o.statistics[k];
        const auto si = index_of(s);
        if (!sim.error.empty()) {
          failed(r);
          continue;
        }
        const StatisticValues& m = *sim.statistics.link[li];
        const double d = transformed(s, m.value[si]) - transformed(s, meas->value[si]);
        const double var = std::pow(transformed_se(s, meas->value[si], meas->standard_error[si]), 2) +
                           std::pow(transformed_se(s, m.value[si], m.standard_error[si]), 2);
        per_statistic[k].add(d, var, r);
        const double z = d / std::sqrt(var);
        if (!c.worst || std::abs(z) > std::abs(c.worst->z))
          c.worst = WorstTerm{r, std::string(name_of(s)) + " of " + std::string(name_of(l)), m.value[si],
                              meas->value[si], meas->standard_error[si], m.standard_error[si], z};
      }
      const auto& band = targets[r].measured_band[li];
      if (!o.use_band || !band) continue;
      if (!sim.error.empty() || !sim.statistics.band[li]) {
        failed(r);
        continue;
      }
      const BandEnergy& m = *sim.statistics.band[li];
      const double d = std::log(std::max(m.excess, 1e-30)) - std::log(std::max(band->excess, 1e-30));
      const double var = std::pow(band->standard_error / std::max(band->excess, 1e-30), 2) +
                         std::pow(m.standard_error / std::max(m.excess, 1e-30), 2);
      band_residuals.add(d, var, r);
      const double z = d / std::sqrt(var);
      if (!c.worst || std::abs(z) > std::abs(c.worst->z))
        c.worst = WorstTerm{r, "band energy of " + std::string(name_of(l)), m.excess, band->excess,
                            band->standard_error, m.standard_error, z};
    }
  }
  // Each statistic with its modelling-choice offset profiled out (a statistic
  // that is no magnitude has no log-offset: σ = 0).
  auto add = [&](const StatisticResiduals& res, double sigma, std::string_view name) {
    const ProfiledOffset po = profile_shared_offset(res.d, res.var, sigma);
    if (!res.d.empty()) c.offsets.emplace_back(std::string(name), po.eta);
    for (std::size_t i = 0; i < res.d.size(); ++i) {
      c.by_recording[res.recording[i]] += po.terms[i], c.terms_by_recording[res.recording[i]] += 1;
      c.total += po.terms[i], c.terms += 1;
    }
    c.total += po.prior_chi2;
  };
  for (std::size_t k = 0; k < o.statistics.size(); ++k)
    add(per_statistic[k], is_magnitude(o.statistics[k]) ? o.modelling_offset_sigma.statistic[index_of(o.statistics[k])] : 0.0,
        name_of(o.statistics[k]));
  add(band_residuals, o.modelling_offset_sigma.band, "band_excess");
  return c;
}

struct Search {
  std::vector<EvaluatedPoint> points;
  SimulationCache* cache = nullptr;
  const FitOptions* options = nullptr;
  int evaluations = 0;
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  std::exception_ptr error;
};

/// NLopt's objective (C callback: nothing may be thrown through it; an
/// exception is kept and rethrown after the optimiser returns).
double objective(unsigned n, const double* x, double* /*grad: derivative-free only*/, void* data) {
  auto* s = static_cast<Search*>(data);
  if (s->error) return kFailedChi2;
  try {
    const ContactParameters p = point(*s->options, x);
    s->cache->ensure({p});
    const double v = chi2_at(*s->cache, *s->options, p).total;
    ++s->evaluations;
    s->points.push_back({p.restitution, p.friction_coefficient, v});
    if (v < s->best) s->best = v, s->best_x.assign(x, x + n);
    return v;
  } catch (...) {
    s->error = std::current_exception();
    return kFailedChi2;
  }
}

void run_nlopt(nlopt_algorithm algorithm, Search& search, const std::vector<double>& lo, const std::vector<double>& hi,
               std::vector<double>& x, int max_evaluations, double step) {
  const auto n = static_cast<unsigned>(lo.size());
  nlopt_opt opt = nlopt_create(algorithm, n);
  if (!opt) throw RunError("fit: NLopt could not create its optimiser");
  nlopt_set_lower_bounds(opt, lo.data());
  nlopt_set_upper_bounds(opt, hi.data());
  nlopt_set_min_objective(opt, objective, &search);
  nlopt_set_maxeval(opt, max_evaluations);
  nlopt_set_xtol_abs1(opt, 1e-3);
  if (step > 0) {
    std::vector<double> dx(n, step);
    nlopt_set_initial_step(opt, dx.data());
  }
  double f = 0;
  nlopt_optimize(opt, x.data(), &f);  // a stop at maxeval or tolerance is a normal end here
  nlopt_destroy(opt);
  if (search.error) std::rethrow_exception(search.error);
  if (!search.best_x.empty()) x = search.best_x;
}

std::vector<double> grid(double lo, double hi, int points) {
  std::vector<double> g;
  for (int i = 0; i < points; ++i)
    g.push_back(points == 1 ? 0.5 * (lo + hi) : lo + (hi - lo) * static_cast<double>(i) / (points - 1));
  return g;
}

}  // namespace

void judge_identifiability(ParameterEstimate& p, double box_low, double box_high, bool top_is_physical,
                           double identifiable_width) {
  const double box = box_high - box_low;
  p.identifiable = (p.high - p.low) <= identifiable_width * box;
  p.lower_bound_only = false;
  // e ≤ 1 is physics, but μ's box top is only where the search stopped: an
  // interval that reaches it and not the bottom bounds μ from below only.
  if (!top_is_physical && p.high >= box_high - 1e-9 * box && p.low > box_low + 1e-9 * box)
    p.lower_bound_only = true, p.identifiable = false;
}

void reject_model_family(FitResult& f, const std::string& reason, const FitOptions& o) {
  f.model_family.rejected = true;
  f.model_family.reasons.push_back(reason);
  f.model_family.error_scale = std::sqrt(std::max(1.0, f.terms > 0 ? f.chi2 / f.terms : 1.0));
  for (ParameterEstimate& p : f.parameters) {
    const bool is_e = p.name == "restitution";
    widen_for_model_error(p, f.interval_delta, f.model_family.error_scale, is_e ? o.box.restitution_low : o.box.friction_low,
                          is_e ? o.box.restitution_high : o.box.friction_high);
    p.lower_bound_only = false;
  }
}

ModellingOffsetSigma default_modelling_offset_sigma() {
  // docs/fit.md "Modelling choices": the RMS change each choice causes, less
  // the replicates' noise (that noise is measured in every fit), in quadrature.
  ModellingOffsetSigma s;
  s.statistic[index_of(ResponseStatistic::spread)] = kSpreadOffsetSigma;
  s.band = kBandOffsetSigma;
  return s;
}

void validate_fit_options(const FitOptions& o) {
  const FitBox& b = o.box;
  auto bad = [](const std::string& what, const std::string& rule) { throw InputError("fit option " + what + ": " + rule); };
  if (!(b.restitution_low >= 0 && b.restitution_high <= 1))
    bad("--restitution " + format_number(b.restitution_low) + ":" + format_number(b.restitution_high),
        "the restitution box must lie in [0, 1]");
  if (!(b.restitution_low < b.restitution_high))
    bad("--restitution " + format_number(b.restitution_low) + ":" + format_number(b.restitution_high),
        "the box is given backwards or empty (low must be below high); write --restitution LOW:HIGH");
  if (!(b.friction_low >= 0 && b.friction_high <= 2))
    bad("--friction " + format_number(b.friction_low) + ":" + format_number(b.friction_high),
        "the friction box must lie in [0, 2]");
  if (!(b.friction_low < b.friction_high))
    bad("--friction " + format_number(b.friction_low) + ":" + format_number(b.friction_high),
        "the box is given backwards or empty (low must be below high); write --friction LOW:HIGH");
  if (o.simulated_turns < 8) bad("--turns " + std::to_string(o.simulated_turns), "simulate at least 8 turns");
  if (o.magnification_turns < 0) bad("magnification turns", "must be >= 0 (0: 8x the measured turns)");
  if (o.warmup_turns < 0) bad("--warmup " + std::to_string(o.warmup_turns), "must be >= 0");
  if (o.global_evaluations < 1 || o.local_evaluations < 0 || o.profile_points_e < 3 || o.profile_points_mu < 3)
    bad("evaluations", "the global stage needs >= 1 evaluation and each profile >= 3 points");
  if (o.statistics.empty()) bad("statistics", "choose at least one statistic");
  if (!(o.modelling_offset_sigma.band >= 0))
    bad("--band-offset-sigma " + format_number(o.modelling_offset_sigma.band), "must be 0 or more (e.g. 0.26)");
  for (double v : o.modelling_offset_sigma.statistic)
    if (!(v >= 0)) bad("--spread-offset-sigma " + format_number(v), "must be 0 or more (e.g. 0.022)");
  if (o.replicates < 1) bad("replicates", "at least one replicate is needed to measure the objective's noise");
  if (!(o.interval_level > 0 && o.interval_level < 1)) bad("interval level", "must lie in (0, 1)");
}

double clearance_effect_ratio(const std::vector<RecordingTarget>& targets) {
  double best = 0;
  for (const RecordingTarget& t : targets) best = std::max(best, t.effect_ratio);
  return best;
}

std::size_t expected_simulations(std::size_t recordings, const FitOptions& o) {
  const int profile = o.profile_points_e * (o.fit_friction ? o.profile_points_mu : 1);
  const int points = o.global_evaluations + o.local_evaluations + profile + o.replicates + 1;  // + the prior
  return recordings * static_cast<std::size_t>(std::max(1, points) + 2);                       // + the runs for a
}

/// "; the largest difference: …" for a rejection's note: the statistic, the
/// recording, both values with their standard errors (from their turns) and
/// the difference in standard errors. A recording whose turns repeat (a
/// periodic motion) has a spread with a tiny error; the model's run from
/// one start may be in another motion (docs/fit.md, the e = 0.8 session).
std::string worst_term_text(const Chi2& c, const std::vector<RecordingTarget>& targets) {
  if (!c.worst) return "";
  const WorstTerm& w = *c.worst;
  return "; the largest difference: the " + w.what + " in " + targets[w.recording].name + ", model " +
         format_number(w.model, 4) + " ± " + format_number(w.model_se, 2) + " against measured " +
         format_number(w.measured, 4) + " ± " + format_number(w.measured_se, 2) + ", " +
         format_number(std::abs(w.z), 3) + " standard errors";
}

FitResult fit_contact_parameters(const std::vector<RecordingTarget>& targets, const ContactParameters& prior,
                                 const FitOptions& o) {
  validate_fit_options(o);
  if (targets.empty()) throw InputError("fit: no recordings to fit");
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  SimulationCache cache(targets, {o.warmup_turns, o.simulated_turns, o.tolerance, std::max(1u, o.threads), o.model, o.on_simulation});
  FitResult out;

  // Global stage (DIRECT-L over the box), then the local one (BOBYQA).
  std::vector<double> lo{o.box.restitution_low}, hi{o.box.restitution_high};
  if (o.fit_friction) lo.push_back(o.box.friction_low), hi.push_back(o.box.friction_high);
  std::vector<double> x(lo.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 0.5 * (lo[i] + hi[i]);
  Search search;
  search.cache = &cache, search.options = &o;
  run_nlopt(NLOPT_GN_DIRECT_L, search, lo, hi, x, o.global_evaluations, 0);
  if (o.local_evaluations > 0) run_nlopt(NLOPT_LN_BOBYQA, search, lo, hi, x, o.local_evaluations, 0.05);

  // Profiles over a grid of the box (one batch over the queue).
  const std::vector<double> ge = grid(lo[0], hi[0], o.profile_points_e);
  const std::vector<double> gm = o.fit_friction ? grid(lo[1], hi[1], o.profile_points_mu) : std::vector<double>{0.0};
  std::vector<ContactParameters> points;
  for (double e : ge)
    for (double m : gm) {
      const double xy[2] = {e, m};
      points.push_back(point(o, xy));
    }
  points.push_back(prior);
  cache.ensure(points);
  std::vector<std::vector<double>> chi(ge.size(), std::vector<double>(gm.size()));
  ContactParameters best = point(o, search.best_x.empty() ? x.data() : search.best_x.data());
  double best_chi = chi2_at(cache, o, best).total;
  for (std::size_t i = 0; i < ge.size(); ++i)
    for (std::size_t j = 0; j < gm.size(); ++j) {
      chi[i][j] = chi2_at(cache, o, points[i * gm.size() + j]).total;
      if (chi[i][j] < best_chi) best_chi = chi[i][j], best = points[i * gm.size() + j];
    }
  out.evaluations = search.evaluations + static_cast<int>(points.size());

  // The objective's own noise, measured: replicates at the lowest point with
  // e nudged by 0.001, 0.002, … (towards the inside of the box) come from
  // different chaotic trajectories (objective_noise.hpp).
  const int nu = chi2_at(cache, o, best).terms;
  const int parameters = o.fit_friction ? 2 : 1;
  {
    const double dir = best.restitution + 0.001 * o.replicates <= hi[0] ? 1.0 : -1.0;
    std::vector<ContactParameters> reps{best};
    for (int k = 1; k <= o.replicates; ++k) {
      ContactParameters q = best;
      q.restitution += dir * 0.001 * k;
      reps.push_back(q);
    }
    cache.ensure(reps);
    std::vector<double> values;
    for (const ContactParameters& q : reps) values.push_back(chi2_at(cache, o, q).total);
    out.evaluations += o.replicates;
    out.noise = objective_noise(values, nu, parameters, o.interval_level);
  }
  out.interval_delta = out.noise.delta;

  // The evaluated points → the smooth model of χ² (objective_surrogate.hpp);
  // its minimum is the estimate and its profile the interval. Without a
  // curved model, the raw grid profile bounds it, from the replicates' mean.
  std::vector<EvaluatedPoint> evaluated = search.points;
  for (std::size_t i = 0; i < ge.size(); ++i)
    for (std::size_t j = 0; j < gm.size(); ++j) evaluated.push_back({ge[i], gm[j], chi[i][j]});
  // The quadratic is fitted to the points within 6·√(2ν) of the lowest: a
  // wider window takes in the steep wall towards e = 1, which no quadratic
  // follows (measured: with 6·2σ one recovery session's minimum moved to the
  // box's edge, e 0.04 against a truth of 0.2).
  const SurrogateFit sf = fit_surrogate(evaluated, lo[0], hi[0], o.fit_friction ? lo[1] : 0.0,
                                        o.fit_friction ? hi[1] : 1.0, o.fit_friction, std::sqrt(2.0 * nu),
                                        out.interval_delta);
  out.surrogate_residual_rms = sf.residual_rms;
  double bottom = out.noise.bottom;
  bool use_surrogate = sf.ok;
  if (sf.ok) {
    // The smooth model's minimum, checked: χ² there must be within the
    // objective's noise of the bottom (else the quadratic does not describe
    // it and the raw profile is used).
    const double xy[2] = {sf.restitution, sf.friction};
    const ContactParameters candidate = point(o, xy);
    cache.ensure({candidate});
    ++out.evaluations;
    const double at = chi2_at(cache, o, candidate).total;
    if (at <= out.noise.bottom + out.interval_delta) {
      best = candidate;
    } else {
      use_surrogate = false;
      out.notes.push_back("the smooth model of the objective missed its bottom (χ² " + format_number(at, 3) +
                          " at its minimum, " + format_number(out.noise.bottom, 3) +
                          " at the bottom found): the interval comes from the raw profile");
      if (at < best_chi) best_chi = at, best = candidate;
    }
  }
  out.surrogate_ok = use_surrogate;
  ParameterEstimate pe{"restitution", best.restitution, 0, 0, true, false, ge, {}};
  for (std::size_t i = 0; i < ge.size(); ++i) pe.profile_chi2.push_back(*std::min_element(chi[i].begin(), chi[i].end()));
  if (use_surrogate) pe.low = sf.restitution_low, pe.high = sf.restitution_high;
  else {
    const auto [l, h] = profile_interval(pe.profile_at, pe.profile_chi2, pe.value, bottom, out.interval_delta, lo[0], hi[0]);
    pe.low = l, pe.high = h;
  }
  pe.low = std::min(pe.low, pe.value), pe.high = std::max(pe.high, pe.value);
  out.parameters.push_back(pe);
  if (o.fit_friction) {
    ParameterEstimate pm{"friction_coefficient", best.friction_coefficient, 0, 0, true, false, gm, {}};
    for (std::size_t j = 0; j < gm.size(); ++j) {
      double m = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < ge.size(); ++i) m = std::min(m, chi[i][j]);
      pm.profile_chi2.push_back(m);
    }
    if (use_surrogate) pm.low = sf.friction_low, pm.high = sf.friction_high;
    else {
      const auto [l, h] = profile_interval(pm.profile_at, pm.profile_chi2, pm.value, bottom, out.interval_delta, lo[1], hi[1]);
      pm.low = l, pm.high = h;
    }
    pm.low = std::min(pm.low, pm.value), pm.high = std::max(pm.high, pm.value);
    out.parameters.push_back(pm);
    if (use_surrogate) out.correlation = sf.correlation;
  }
  for (ParameterEstimate& p : out.parameters) {
    const bool is_e = p.name == "restitution";
    judge_identifiability(p, is_e ? lo[0] : lo[1], is_e ? hi[0] : hi[1], /*top_is_physical=*/is_e,
                          o.identifiable_width);
  }

  const Chi2 at_best = chi2_at(cache, o, best), at_prior = chi2_at(cache, o, prior);
  out.best = SimulationCache::canonical(best);
  out.chi2 = at_best.total, out.terms = at_best.terms, out.chi2_prior = at_prior.total;
  out.modelling_offsets = at_best.offsets;
  for (std::size_t r = 0; r < targets.size(); ++r)
    out.recordings.push_back({targets[r].name, at_best.by_recording[r], at_best.terms_by_recording[r],
                              at_prior.by_recording[r]});
  // The magnification factor a at the fit and at the prior, from runs of
  // many more turns than the measurement's, turned into what the model
  // expects of an averaged curve of the measured turns (matched_magnification.hpp).
  std::size_t max_turns = 0;
  for (const RecordingTarget& t : targets) max_turns = std::max(max_turns, t.turns);
  out.magnification_turns =
      o.magnification_turns > 0 ? o.magnification_turns
                                : kMagnificationTurnsPerMeasuredTurn * static_cast<int>(std::max<std::size_t>(max_turns, 1));
  SimulationCache long_runs(targets,
                            {o.warmup_turns, out.magnification_turns, o.tolerance, std::max(1u, o.threads), o.model, o.on_simulation});
  long_runs.ensure({best, prior});
  out.magnification_simulations = long_runs.simulations();
  for (std::size_t r = 0; r < targets.size(); ++r) {
    // α3, or α4 without a coupler channel.
    std::size_t li = 0;
    while (li + 1 < kFitLinks.size() && !targets[r].measured[li]) ++li;
    const auto& m = targets[r].measured[li];
    auto a = [&](const ContactParameters& p) -> std::optional<MatchedMagnification> {
      const CachedSimulation& sim = long_runs.at(r, p);
      if (!m || !sim.error.empty() || !sim.statistics.link[li]) return std::nullopt;
      return matched_magnification(*m, targets[r].turns, *sim.statistics.link[li],
                                   static_cast<std::size_t>(out.magnification_turns));
    };
    out.magnification_fitted.push_back(a(best));
    out.magnification_prior.push_back(a(prior));
    std::optional<double> share, from_scatter;
    if (m) {
      const double md = m->value[index_of(ResponseStatistic::mean_deviation)];
      const double sm = m->value[index_of(ResponseStatistic::spread)] / std::sqrt(static_cast<double>(targets[r].turns));
      if (md > 0) share = sm / md;
      // Both scatters over the measured number of turns: σ_model / σ_measured.
      const CachedSimulation& sim = long_runs.at(r, best);
      if (sim.error.empty() && sim.statistics.link[li] && sm > 0)
        from_scatter = sim.statistics.link[li]->value[index_of(ResponseStatistic::spread)] /
                       m->value[index_of(ResponseStatistic::spread)];
    }
    out.measured_scatter_share.push_back(share);
    out.magnification_from_scatter_fitted.push_back(from_scatter);
  }
  for (const ParameterEstimate& p : out.parameters)
    if (p.lower_bound_only)
      out.notes.push_back(p.name + " not identifiable from these recordings: only " + p.name + " >= " +
                          format_number(p.low, 2) + " (the statistics stay within their noise from there to the box's top " +
                          format_number(p.high, 2) + ")");
    else if (!p.identifiable)
      out.notes.push_back(p.name + " not identifiable from these recordings");
  if (out.terms > 0 && out.chi2 / out.terms > kModelFamilyChi2PerTerm) {
    // Where the model family fails most: the recording with the largest χ² per statistic.
    std::size_t worst = 0;
    auto per_term = [&](std::size_t r) { return out.recordings[r].chi2 / std::max(1, out.recordings[r].terms); };
    for (std::size_t r = 1; r < out.recordings.size(); ++r)
      if (per_term(r) > per_term(worst)) worst = r;
    out.notes.push_back("at the best parameters the statistics still differ by " +
                        format_number(std::sqrt(out.chi2 / out.terms), 2) +
                        " standard errors (RMS; most in " + out.recordings[worst].name + ", " +
                        format_number(std::sqrt(per_term(worst)), 2) + worst_term_text(at_best, targets) +
                        "): the model family does not describe this bearing; the values are effective ones and their "
                        "intervals, which assume the model describes the measurement, are not uncertainties");
    std::vector<std::optional<std::array<TurnRepeat, 2>>> model_repeat;
    for (std::size_t r = 0; r < targets.size(); ++r) {
      const CachedSimulation& sim = cache.at(r, best);
      model_repeat.push_back(sim.error.empty() ? std::optional(sim.statistics.repeat) : std::nullopt);
    }
    for (std::string& n : periodic_notes(targets, model_repeat, best, orbit_search_options(o)))
      out.notes.push_back(std::move(n));
    reject_model_family(out,
                        "chi2/term " + format_number(out.chi2 / out.terms, 3) + " at the best parameters, above " +
                            format_number(kModelFamilyChi2PerTerm, 2) + " (the statistics' noise gives about 1)",
                        o);
  }
  out.simulations = cache.simulations() + long_runs.simulations();
  out.simulations_on_rank_0 = cache.computed_here() + long_runs.computed_here();
  out.turns_simulated = cache.turns_simulated() + long_runs.turns_simulated();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  out.simulation_cpu_seconds = cache.simulation_cpu_seconds() + long_runs.simulation_cpu_seconds();
  out.simulation_idle_wall_seconds = cache.idle_wall_seconds() + long_runs.idle_wall_seconds();
  out.seconds_per_simulation =
      cache.simulations() > 0 ? cache.compute_seconds() * std::max(1u, o.threads) / cache.simulations() : 0.0;
  return out;
}

}  // namespace fourbar
