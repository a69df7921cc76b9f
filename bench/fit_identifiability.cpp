// Identifiability study of the contact parameters (docs/fit.md): which
// response statistics carry the restitution e and the Coulomb μ, measured on
// a SYNTHETIC session made by bench/make_fit_session.sh with known
// parameters.
//
//   fit_identifiability SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU [SIM_TURNS] [THREADS] [mu-scan]
//
// With `mu-scan` step 2 is instead μ = 0, 0.1 … 0.5 at the true e (stick-slip)
// and three replicates of the truth (e nudged by 0.001, 0.002, 0.003: the
// chaotic motion's point-to-point noise), and step 3 prints, per statistic
// and μ, (model(μ) − model(truth)) / measured standard error: where the
// statistics stop changing with μ, μ cannot be told apart from the data.
//
// 1. Every recording through acquire + analyze (the session's defaults, every
//    turn kept) → the measured statistics with their jackknife standard error.
// 2. The clearance model at each recording's operating point for e = 0.2,
//    0.5, 0.8 (smooth) and stick-slip μ = 0.1, 0.3 (at e = 0.5), SIM_TURNS
//    turns after 20 warm-up turns → the same statistics.
// 3. Per statistic: sensitivity = change of the (log) statistic per 0.1 of e
//    or of μ, in units of the measurement's standard error; and the
//    agreement of measurement and model at the true parameters (z).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "truth_args.hpp"
#include "cluster/case_queue.hpp"
#include "fit/recording_target.hpp"
#include "report/session_settings.hpp"

using namespace fourbar;

namespace {

double transformed(ResponseStatistic s, double v) { return is_magnitude(s) ? std::log(std::max(v, 1e-300)) : v; }
double transformed_se(ResponseStatistic s, double v, double se) { return is_magnitude(s) ? se / std::max(v, 1e-300) : se; }

struct Case {
  std::string label;
  ContactParameters p;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: fit_identifiability SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU [SIM_TURNS] [THREADS]\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const ContactParameters truth = bench::truth_from_args(argv);
  const int sim_turns = argc > 5 ? std::stoi(argv[5]) : 100;
  const unsigned threads = argc > 6 ? static_cast<unsigned>(std::stoi(argv[6])) : 2;
  const bool mu_scan = argc > 7 && std::string(argv[7]) == "mu-scan";

  SessionSettings settings = load_session_settings(dir);
  AnalyzeOptions options = settings.analysis;
  options.keep_revolutions = true;
  options.progress = false;
  std::vector<RecordingTarget> targets;
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& rec : find_session_files(dir).recordings) {
    auto manifest = rec;
    manifest.replace_extension(".toml");
    const RecordingAnalysis a = analyze_recording(rec, manifest, options);
    std::optional<RecordingAnalysis> band;
    if (const auto bo = band_analysis_options(a, options)) band = analyze_recording(rec, manifest, *bo);
    targets.push_back(make_recording_target(a, band ? &*band : nullptr, rec.filename().string()));
  }
  const double analyse_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::vector<Case> cases = {{"e=0.2", {0.2, ContactLaw::smooth, 0}},
                             {"e=0.5", {0.5, ContactLaw::smooth, 0}},
                             {"e=0.8", {0.8, ContactLaw::smooth, 0}},
                             {"e=0.5 mu=0.1", {0.5, ContactLaw::stick_slip, 0.1}},
                             {"e=0.5 mu=0.3", {0.5, ContactLaw::stick_slip, 0.3}},
                             {"truth", truth}};
  if (mu_scan) {
    cases.clear();
    for (double mu : {0.0, 0.1, 0.2, 0.3, 0.4, 0.5})
      cases.push_back({"mu=" + std::to_string(mu).substr(0, 3),
                       {truth.restitution, mu > 0 ? ContactLaw::stick_slip : ContactLaw::smooth, mu}});
    for (double d : {0.001, 0.002, 0.003})
      cases.push_back({"truth+" + std::to_string(d).substr(0, 5),
                       {truth.restitution + d, truth.contact, truth.friction_coefficient}});
    cases.push_back({"truth", truth});
  }
  // One simulation per (case, recording).
  std::vector<std::size_t> jobs(cases.size() * targets.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) jobs[i] = i;
  std::vector<SimulatedStatistics> sims(jobs.size());
  std::vector<double> sim_s(jobs.size());
  std::mutex m;
  const auto t1 = std::chrono::steady_clock::now();
  run_case_queue(jobs, threads,
                 [&](std::size_t j) {
                   const auto s = std::chrono::steady_clock::now();
                   SimulatedStatistics r = simulate_statistics(targets[j % targets.size()], cases[j / targets.size()].p, 20, sim_turns);
                   const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count();
                   std::lock_guard lock(m);
                   sims[j] = r, sim_s[j] = dt;
                   return std::string();
                 },
                 [](std::size_t, std::string&&) {});
  const double sim_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  double sim_cpu_s = 0;
  for (double s : sim_s) sim_cpu_s += s;

  std::printf("# session %s: truth e = %.2f, %s, mu = %.2f; %zu recordings analysed in %.1f s\n", dir.c_str(),
              truth.restitution, to_string(truth.contact), truth.friction_coefficient, targets.size(), analyse_s);
  std::printf("# %zu simulations of 20 + %d turns: %.1f s wall on %u threads, %.2f ms per simulated turn\n", jobs.size(),
              sim_turns, sim_wall_s, threads, 1e3 * sim_cpu_s / (static_cast<double>(jobs.size()) * (20 + sim_turns)));
  if (mu_scan) {
    // Per statistic: (model(case) − model(truth)) in measured standard errors.
    std::printf("# (model(case) - model(truth)) / measured SE (log for magnitudes); the last three columns are\n"
                "# replicates of the truth (e nudged by 0.001-0.003): the objective's own noise\n");
    std::printf("%-24s %-6s %-14s", "recording", "link", "statistic");
    for (std::size_t c = 0; c + 1 < cases.size(); ++c) std::printf(" %12s", cases[c].label.c_str());
    std::printf("\n");
    const std::size_t tc = cases.size() - 1;
    for (std::size_t r = 0; r < targets.size(); ++r) {
      const RecordingTarget& t = targets[r];
      for (FitLink l : kFitLinks) {
        const auto li = static_cast<std::size_t>(l);
        if (!t.measured[li]) continue;
        for (ResponseStatistic s : {ResponseStatistic::spread, ResponseStatistic::mean_deviation,
                                    ResponseStatistic::peak_p90}) {
          const auto si = index_of(s);
          const double mv = t.measured[li]->value[si];
          const double se_t = transformed_se(s, mv, t.measured[li]->standard_error[si]);
          std::printf("%-24s %-6s %-14s", t.name.c_str(), std::string(name_of(l)).c_str(), std::string(name_of(s)).c_str());
          for (std::size_t c = 0; c < tc; ++c)
            std::printf(" %12.2f", (transformed(s, sims[c * targets.size() + r].link[li]->value[si]) -
                                    transformed(s, sims[tc * targets.size() + r].link[li]->value[si])) / se_t);
          std::printf("\n");
        }
        if (!t.measured_band[li]) continue;
        const double se_t = t.measured_band[li]->standard_error / t.measured_band[li]->excess;
        std::printf("%-24s %-6s %-14s", t.name.c_str(), std::string(name_of(l)).c_str(), "band_excess");
        for (std::size_t c = 0; c < tc; ++c)
          std::printf(" %12.2f", (std::log(sims[c * targets.size() + r].band[li]->excess) -
                                  std::log(sims[tc * targets.size() + r].band[li]->excess)) / se_t);
        std::printf("\n");
      }
    }
    return 0;
  }
  std::printf("# sens_e: change of the statistic (log for magnitudes) per +0.1 in e (0.2→0.8 smooth), in measured SEs;\n");
  std::printf("# sens_mu: per +0.1 in mu (stick-slip 0.1→0.3 at e = 0.5); z: (measured − model at truth)/combined SE\n");
  std::printf("%-28s %-6s %-16s %11s %9s %9s %9s %9s %9s %8s %8s %8s\n", "recording", "link", "statistic", "measured",
              "se_rel", "e=0.2", "e=0.5", "e=0.8", "mu=0.1", "mu=0.3", "sens_e", "sens_mu");
  for (std::size_t r = 0; r < targets.size(); ++r) {
    const RecordingTarget& t = targets[r];
    for (FitLink l : kFitLinks) {
      const auto li = static_cast<std::size_t>(l);
      if (!t.measured[li]) continue;
      for (ResponseStatistic s : kResponseStatistics) {
        const auto si = index_of(s);
        const double mv = t.measured[li]->value[si], mse = t.measured[li]->standard_error[si];
        auto sim_value = [&](std::size_t c) { return sims[c * targets.size() + r].link[li]->value[si]; };
        const double se_t = transformed_se(s, mv, mse);
        const double sens_e = (transformed(s, sim_value(2)) - transformed(s, sim_value(0))) / 6.0 / se_t;
        const double sens_mu = (transformed(s, sim_value(4)) - transformed(s, sim_value(3))) / 2.0 / se_t;
        const auto& tr = *sims[5 * targets.size() + r].link[li];
        const double z = (transformed(s, mv) - transformed(s, tr.value[si])) /
                         std::hypot(se_t, transformed_se(s, tr.value[si], tr.standard_error[si]));
        std::printf("%-28s %-6s %-16s %11.4g %9.3f %9.4g %9.4g %9.4g %9.4g %9.4g %8.2f %8.2f  z=%.2f\n", t.name.c_str(),
                    std::string(name_of(l)).c_str(), std::string(name_of(s)).c_str(), mv,
                    is_magnitude(s) ? mse / mv : mse, sim_value(0), sim_value(1), sim_value(2), sim_value(3),
                    sim_value(4), sens_e, sens_mu, z);
      }
    }
    for (FitLink l : kFitLinks) {
      const auto li = static_cast<std::size_t>(l);
      if (!t.measured_band[li]) continue;
      const BandEnergy& mb = *t.measured_band[li];
      auto v = [&](std::size_t c) { return sims[c * targets.size() + r].band[li]->excess; };
      const double se_t = mb.standard_error / mb.excess;
      const auto& tr = *sims[5 * targets.size() + r].band[li];
      const double z = (std::log(mb.excess) - std::log(tr.excess)) / std::hypot(se_t, tr.standard_error / tr.excess);
      std::printf("%-28s %-6s %-16s %11.4g %9.3f %9.4g %9.4g %9.4g %9.4g %9.4g %8.2f %8.2f  z=%.2f floor=%.3g band=%.0f-%.0f Hz\n",
                  t.name.c_str(), std::string(name_of(l)).c_str(), "band_excess", mb.excess, se_t, v(0), v(1), v(2), v(3),
                  v(4), (std::log(v(2)) - std::log(v(0))) / 6.0 / se_t, (std::log(v(4)) - std::log(v(3))) / 2.0 / se_t, z,
                  mb.floor, t.band_filter->low_hz, t.band_filter->high_hz);
    }
    std::printf("%-28s impacts/turn (settle-speed dependent, not used): e=0.2 %.1f, e=0.5 %.1f, e=0.8 %.1f; sum F/turn %.3g %.3g %.3g N s\n",
                t.name.c_str(), sims[0 * targets.size() + r].impacts_per_rev, sims[1 * targets.size() + r].impacts_per_rev,
                sims[2 * targets.size() + r].impacts_per_rev, sims[0 * targets.size() + r].sum_normal_impulse_per_rev_Ns,
                sims[1 * targets.size() + r].sum_normal_impulse_per_rev_Ns,
                sims[2 * targets.size() + r].sum_normal_impulse_per_rev_Ns);
  }
  return 0;
}
