// The magnification factor a at the TRUE contact parameters, and how much of
// it is the averaging noise of a finite number of turns (docs/fit.md, "The
// magnification factor a of the fitted model"). On a SYNTHETIC session made
// by bench/make_fit_session.sh with known parameters:
//
//   fit_magnification SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU [MODEL_TURNS] [THREADS] [BLOCK] [E:MU ...]
//
// Each E:MU after BLOCK (MU 0: smooth) is a further point (the fitted values,
// the prior) at which a is given as `fourbar fit` computes it
// (matched_magnification from MODEL_TURNS turns) and as the scatter ratio.
//
// Per recording, α3 (the link the fit's a is taken on):
// 1. The measurement through acquire + analyze (session settings, every turn
//    kept): mean_deviation (RMS of the averaged deviation, what a sees) with
//    its jackknife standard error, spread, band_excess. When the recording
//    holds at least 2 × BLOCK turns (a long recording) also the same
//    statistics on its consecutive blocks of BLOCK turns: the measurement's
//    own scatter from block to block (independent chaotic windows).
// 2. The clearance model at the truth, 20 warm-up + MODEL_TURNS turns, split
//    into consecutive blocks of R (the measured turns) and of 2R (what the
//    fit's model averages): the model's own block-to-block scatter of each
//    statistic, and the first block (turns 20 … 20 + R, the window the
//    recording holds) against the later ones (is the chaos still growing?).
// 3. a at the truth: a_fit = md(model, 2R turns)/md(measured) (fit.json
//    before this bench), a_R = md(model, R turns)/md(measured) (matched
//    turns), a_exp = √(d² + σ²/R)/md(measured) with d² = md_M² − σ_M²/M the
//    model's repeatable curve from all M turns (the model's expected
//    mean_deviation of R turns, converged) and its standard error from the
//    measured jackknife.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "truth_args.hpp"
#include "cluster/case_queue.hpp"
#include "fit/matched_magnification.hpp"
#include "fit/recording_target.hpp"
#include "report/session_settings.hpp"

using namespace fourbar;

namespace {

struct Stat {
  double md = 0, md_se = 0, spread = 0, spread_se = 0, band = 0, band_se = 0;
};

/// Statistics of rows [r0, r1) of `turns` (R × n) and, when `band_turns` is
/// given, of the same rows of the band grid (R × nb).
Stat stats_of(const std::vector<double>& turns, const std::vector<double>& nominal, std::size_t r0, std::size_t r1,
              const std::vector<double>* band_turns, std::size_t nb) {
  const std::size_t n = nominal.size();
  const std::vector<double> x(turns.begin() + static_cast<std::ptrdiff_t>(r0 * n),
                              turns.begin() + static_cast<std::ptrdiff_t>(r1 * n));
  const StatisticValues v = response_statistics(x, nominal);
  Stat s;
  s.md = v.value[index_of(ResponseStatistic::mean_deviation)];
  s.md_se = v.standard_error[index_of(ResponseStatistic::mean_deviation)];
  s.spread = v.value[index_of(ResponseStatistic::spread)];
  s.spread_se = v.standard_error[index_of(ResponseStatistic::spread)];
  if (band_turns && !band_turns->empty()) {
    const std::vector<double> b(band_turns->begin() + static_cast<std::ptrdiff_t>(r0 * nb),
                                band_turns->begin() + static_cast<std::ptrdiff_t>(r1 * nb));
    const BandEnergy e = band_energy(b, nb);
    s.band = e.excess, s.band_se = e.standard_error;
  }
  return s;
}

struct Blocks {
  std::vector<Stat> s;
  double mean(double Stat::*f) const {
    double m = 0;
    for (const Stat& x : s) m += x.*f / static_cast<double>(s.size());
    return m;
  }
  double sd(double Stat::*f) const {
    const double m = mean(f);
    double v = 0;
    for (const Stat& x : s) v += (x.*f - m) * (x.*f - m);
    return s.size() > 1 ? std::sqrt(v / static_cast<double>(s.size() - 1)) : 0.0;
  }
};

Blocks blocks_of(const std::vector<double>& turns, const std::vector<double>& nominal, std::size_t block,
                 const std::vector<double>* band, std::size_t nb) {
  Blocks b;
  const std::size_t rows = turns.size() / nominal.size();
  for (std::size_t r = 0; r + block <= rows; r += block) b.s.push_back(stats_of(turns, nominal, r, r + block, band, nb));
  return b;
}

struct ModelRun {
  std::vector<double> alpha3;  ///< M × N, analysis pass band, analysis grid
  std::vector<double> band3;   ///< M × Nb, band pass (empty without a band)
};

ModelRun simulate(const RecordingTarget& t, const ContactParameters& p, int turns) {
  TheorySettings s;
  s.restitution = p.restitution, s.contact = p.contact;
  s.friction_coefficient = p.contact == ContactLaw::stick_slip ? p.friction_coefficient : 0.0;
  s.warmup_revolutions = 20, s.averaged_revolutions = turns, s.tolerance = 1e-8;
  CrankGrid fine = t.grid;
  if (t.band_filter) fine.grid_points_per_rev = t.band_grid_points_per_rev;
  MatchedTheory th = simulate_matched_theory(*t.rig, t.clearance_m, t.crank_speed_rad_s, fine, s);
  ModelRun out;
  const auto q = index_of(LinkQuantity::alpha3);
  if (t.band_filter) {
    MatchedTheory band = th;
    apply_pass_band(band, *t.band_filter);
    out.band3 = band.series[q].clearance_revolutions;
  }
  apply_pass_band(th, t.filter);
  const std::size_t k = fine.grid_points_per_rev / t.grid.grid_points_per_rev;
  const std::vector<double>& v = th.series[q].clearance_revolutions;
  for (std::size_t j = 0; j * k < v.size(); ++j) out.alpha3.push_back(v[j * k]);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: fit_magnification SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU [MODEL_TURNS] [THREADS] [BLOCK]\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const ContactParameters truth = bench::truth_from_args(argv);
  const int model_turns = argc > 5 ? std::stoi(argv[5]) : 460;
  const unsigned threads = argc > 6 ? static_cast<unsigned>(std::stoi(argv[6])) : 1;
  const std::size_t block = argc > 7 ? static_cast<std::size_t>(std::stoi(argv[7])) : 23;

  std::vector<ContactParameters> points;
  for (int i = 8; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto colon = arg.find(':');
    ContactParameters p;
    p.restitution = std::stod(arg.substr(0, colon));
    p.friction_coefficient = colon == std::string::npos ? 0.0 : std::stod(arg.substr(colon + 1));
    p.contact = p.friction_coefficient > 0 ? ContactLaw::stick_slip : ContactLaw::smooth;
    points.push_back(p);
  }
  SessionSettings settings = load_session_settings(dir);
  AnalyzeOptions options = settings.analysis;
  options.keep_revolutions = true;
  options.progress = false;
  struct Rec {
    RecordingTarget t;
    std::vector<double> alpha3, band3;
  };
  std::vector<Rec> recs;
  for (const auto& rec : find_session_files(dir).recordings) {
    auto manifest = rec;
    manifest.replace_extension(".toml");
    const RecordingAnalysis a = analyze_recording(rec, manifest, options);
    std::optional<RecordingAnalysis> band;
    if (const auto bo = band_analysis_options(a, options)) band = analyze_recording(rec, manifest, *bo);
    Rec r{make_recording_target(a, band ? &*band : nullptr, rec.filename().string()), a.coupler->alpha_grid, {}};
    if (band && r.t.band_filter) r.band3 = band->coupler->alpha_grid;
    recs.push_back(std::move(r));
  }
  std::vector<ModelRun> runs(recs.size());
  std::vector<std::size_t> jobs(recs.size() * (1 + points.size()));
  for (std::size_t i = 0; i < jobs.size(); ++i) jobs[i] = i;
  std::vector<std::vector<StatisticValues>> at_points(recs.size(), std::vector<StatisticValues>(points.size()));
  std::mutex m;
  run_case_queue(jobs, threads,
                 [&](std::size_t j) {
                   const std::size_t r = j % recs.size(), c = j / recs.size();
                   ModelRun run = simulate(recs[r].t, c == 0 ? truth : points[c - 1], model_turns);
                   std::lock_guard lock(m);
                   if (c == 0) runs[r] = std::move(run);
                   else at_points[r][c - 1] = response_statistics(run.alpha3, recs[r].t.nominal[0]);
                   return std::string();
                 },
                 [](std::size_t, std::string&&) {});

  std::printf("# session %s: truth e = %.2f %s mu = %.2f; model 20 + %d turns; alpha3\n", dir.c_str(), truth.restitution,
              to_string(truth.contact), truth.friction_coefficient, model_turns);
  for (std::size_t i = 0; i < recs.size(); ++i) {
    const Rec& r = recs[i];
    const RecordingTarget& t = r.t;
    const std::size_t R = t.turns, nb = t.band_grid_points_per_rev;
    const std::vector<double>& nom = t.nominal[0];
    const Stat meas = stats_of(r.alpha3, nom, 0, R, r.band3.empty() ? nullptr : &r.band3, nb);
    const ModelRun& run = runs[i];
    const std::vector<double>* mb = run.band3.empty() ? nullptr : &run.band3;
    const std::size_t M = run.alpha3.size() / nom.size();
    const std::size_t Rs = std::min<std::size_t>(R, block);  // the measurement's block (R for a short recording)
    const Stat all = stats_of(run.alpha3, nom, 0, M, mb, nb);
    const Blocks bR = blocks_of(run.alpha3, nom, Rs, mb, nb), b2R = blocks_of(run.alpha3, nom, 2 * Rs, mb, nb);
    const double d2 = all.md * all.md - all.spread * all.spread / static_cast<double>(M);
    std::printf("\n## %s  measured %zu turns: md %.4g ± %.3g (rel %.3f)  spread %.4g ± %.3g  band %.4g ± %.3g\n",
                t.name.c_str(), R, meas.md, meas.md_se, meas.md_se / meas.md, meas.spread, meas.spread_se, meas.band,
                meas.band_se);
    std::printf("   model %zu turns: md %.4g spread %.4g band %.4g; repeatable curve d = %.4g, scatter share of %zu turns "
                "sigma/sqrt(R)/sqrt(d^2+sigma^2/R) = %.2f\n",
                M, all.md, all.spread, all.band, std::sqrt(std::max(0.0, d2)), Rs,
                all.spread / std::sqrt(double(Rs)) / std::sqrt(std::max(0.0, d2) + all.spread * all.spread / double(Rs)));
    auto line = [&](const char* what, const Blocks& b) {
      std::printf("   model blocks of %-3s (%2zu): md %.4g sd %.3g (rel %.3f, mean jackknife rel %.3f) | spread %.4g sd %.3g "
                  "(jk %.3g) | band %.4g sd %.3g (jk %.3g) | first block md %.4g spread %.4g band %.4g\n",
                  what, b.s.size(), b.mean(&Stat::md), b.sd(&Stat::md), b.sd(&Stat::md) / b.mean(&Stat::md),
                  b.mean(&Stat::md_se) / b.mean(&Stat::md), b.mean(&Stat::spread), b.sd(&Stat::spread),
                  b.mean(&Stat::spread_se), b.mean(&Stat::band), b.sd(&Stat::band), b.mean(&Stat::band_se),
                  b.s[0].md, b.s[0].spread, b.s[0].band);
    };
    line("R", bR);
    line("2R", b2R);
    // Spread and band of the first block (the recording's window) against the later ones.
    Blocks later{std::vector<Stat>(bR.s.begin() + 1, bR.s.end())};
    std::printf("   transient: first block / later blocks: spread %.3f (z %.2f), band %.3f (z %.2f)\n",
                bR.s[0].spread / later.mean(&Stat::spread),
                (bR.s[0].spread - later.mean(&Stat::spread)) / later.sd(&Stat::spread),
                mb ? bR.s[0].band / later.mean(&Stat::band) : 0.0,
                mb ? (bR.s[0].band - later.mean(&Stat::band)) / later.sd(&Stat::band) : 0.0);
    // z of the measurement against the model's R-turn blocks (its own scatter as the yardstick).
    std::printf("   z(measured - model R-blocks, in model block sd): md %.2f spread %.2f band %.2f; log: spread %.3f band %.3f\n",
                (meas.md - bR.mean(&Stat::md)) / bR.sd(&Stat::md),
                (meas.spread - bR.mean(&Stat::spread)) / bR.sd(&Stat::spread),
                mb ? (meas.band - bR.mean(&Stat::band)) / bR.sd(&Stat::band) : 0.0,
                std::log(meas.spread / all.spread), mb ? std::log(meas.band / all.band) : 0.0);
    // The fit's z = (log measured − log model) / √(rel se_meas² + rel se_model²)
    // with both jackknife errors, on the model alone: its R-blocks of the
    // first half as "measurements" against its 2R-blocks of the second half
    // as "models" (the same process, no processing chain between them).
    {
      const std::size_t half = b2R.s.size() / 2;
      double zs = 0, zb = 0, zs_true = 0, zb_true = 0;
      int pairs = 0;
      const double sd_ls = later.sd(&Stat::spread) / later.mean(&Stat::spread), sd_lb = later.sd(&Stat::band) / later.mean(&Stat::band);
      for (std::size_t k = 0; k < 2 * half && k < bR.s.size(); ++k) {
        const Stat &x = bR.s[k], &y = b2R.s[half + k % (b2R.s.size() - half)];
        zs += std::log(x.spread / y.spread) / std::hypot(x.spread_se / x.spread, y.spread_se / y.spread);
        zs_true += std::log(x.spread / y.spread) / (sd_ls * std::sqrt(1.5));
        if (mb) {
          zb += std::log(x.band / y.band) / std::hypot(x.band_se / x.band, y.band_se / y.band);
          zb_true += std::log(x.band / y.band) / (sd_lb * std::sqrt(1.5));
        }
        ++pairs;
      }
      std::printf("   model vs model (%d pairs R-block / 2R-block, disjoint turns): mean z with jackknife errors: spread %.2f band %.2f;"
                  " with the blocks' true scatter: spread %.2f band %.2f\n",
                  pairs, zs / pairs, zb / pairs, zs_true / pairs, zb_true / pairs);
    }
    const double a_fit = b2R.s[0].md / meas.md, a_R = bR.s[0].md / meas.md;
    const double a_exp = std::sqrt(std::max(0.0, d2) + all.spread * all.spread / double(R)) / meas.md;
    std::printf("   a at truth: fit-style (first 2R) %.2f, matched (first R) %.2f, blocks of R %.2f..%.2f, "
                "converged expected %.2f ± %.2f\n",
                a_fit, a_R,
                std::min_element(bR.s.begin(), bR.s.end(), [](auto& x, auto& y) { return x.md < y.md; })->md / meas.md,
                std::max_element(bR.s.begin(), bR.s.end(), [](auto& x, auto& y) { return x.md < y.md; })->md / meas.md,
                a_exp, a_exp * meas.md_se / meas.md);
    for (std::size_t c = 0; c < points.size(); ++c) {
      const auto a = matched_magnification(*t.measured[0], R, at_points[i][c], M);
      const double sr = at_points[i][c].value[index_of(ResponseStatistic::spread)] / meas.spread;
      std::printf("   at e = %.4g mu = %.4g: a = %.3f ± %.3f (measured rel %.3f, model rel %.3f), a from scatter %.3f\n",
                  points[c].restitution, points[c].friction_coefficient, a ? a->value : 0.0, a ? a->standard_error : 0.0,
                  a ? a->measured_relative_error : 0.0, a ? a->model_relative_error : 0.0, sr);
    }
    if (R >= 2 * block) {
      // A long recording: the measurement's own scatter from block to block.
      const Blocks mbk = blocks_of(r.alpha3, nom, block, r.band3.empty() ? nullptr : &r.band3, nb);
      const double pred = std::sqrt(std::max(0.0, d2) + all.spread * all.spread / double(block));
      std::vector<double> a;
      for (const Stat& s : mbk.s) a.push_back(pred / s.md);
      double la = 0, la2 = 0;
      for (double v : a) la += std::log(v) / double(a.size());
      for (double v : a) la2 += (std::log(v) - la) * (std::log(v) - la);
      int inside = 0;
      for (double v : a) inside += v >= 0.8 && v <= 1.25;
      std::printf("   measured blocks of %zu (%zu): md %.4g sd %.3g (rel %.3f, mean jackknife rel %.3f) | spread %.4g sd %.3g "
                  "(jk %.3g) | band %.4g sd %.3g (jk %.3g)\n",
                  block, mbk.s.size(), mbk.mean(&Stat::md), mbk.sd(&Stat::md), mbk.sd(&Stat::md) / mbk.mean(&Stat::md),
                  mbk.mean(&Stat::md_se) / mbk.mean(&Stat::md), mbk.mean(&Stat::spread), mbk.sd(&Stat::spread),
                  mbk.mean(&Stat::spread_se), mbk.mean(&Stat::band), mbk.sd(&Stat::band), mbk.mean(&Stat::band_se));
      // The fit's z of each measured block against the model's 2R-blocks (through the processing chain).
      double zs = 0, zb = 0;
      int pairs = 0;
      for (std::size_t k = 0; k < mbk.s.size(); ++k) {
        const Stat &x = mbk.s[k], &y = b2R.s[k % b2R.s.size()];
        zs += std::log(x.spread / y.spread) / std::hypot(x.spread_se / x.spread, y.spread_se / y.spread);
        if (mb) zb += std::log(x.band / y.band) / std::hypot(x.band_se / x.band, y.band_se / y.band);
        ++pairs;
      }
      std::printf("   measured vs model (%d pairs measured %zu-block / model 2R-block): mean z with jackknife errors: spread %.2f band %.2f\n",
                  pairs, block, zs / pairs, zb / pairs);
      std::printf("   a (converged truth / measured block): ");
      for (double v : a) std::printf("%.2f ", v);
      std::printf(" -> sd(log a) %.3f, within 0.8-1.25: %d of %zu\n", std::sqrt(la2 / double(a.size() - 1)), inside,
                  a.size());
    }
  }
  return 0;
}
