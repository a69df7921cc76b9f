// How much do modelling choices without a physical counterpart move the
// fit's statistics (docs/fit.md "Modelling choices")? A second, equally
// valid implementation of the same rigid three-mode physics may end a
// chattering sequence at another settle speed, or sample α at a point
// instead of averaging it over the sample period; the fit must not read
// such a choice as a change of e or μ.
//
//   fit_modelling_choices SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU [SIM_TURNS] [THREADS] [REPLICATES]
//
// SESSION_DIR from bench/make_fit_session.sh. Per recording, link and
// statistic (the fit's: spread and the band energy above the averaging
// filter, plus the others for the record), the model at the truth with
//   baseline      settle speed 1e-6 m/s, α averaged over each grid cell;
//   settle 1e-4, settle 1e-3 m/s (a rebound slower than this ends chatter);
//   point         α at the grid point (the simulator's instantaneous α);
// and REPLICATES replicates of the baseline (e nudged by 0.001 …: the
// chaotic motion's own noise), each as the change of the (log) statistic
// from the baseline, in % and in the measured standard error. The last
// lines give per statistic the RMS over the recordings and links of each
// choice's change, and of the replicates': a choice matters where it
// exceeds the replicates' noise.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "truth_args.hpp"
#include "cluster/case_queue.hpp"
#include "fit/recording_target.hpp"
#include "report/session_settings.hpp"

using namespace fourbar;

namespace {

struct Variant {
  std::string label;
  ContactParameters p;
  ModellingChoices choices;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: fit_modelling_choices SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU [SIM_TURNS] [THREADS] [REPLICATES]\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const ContactParameters truth = bench::truth_from_args(argv);
  const int sim_turns = argc > 5 ? std::stoi(argv[5]) : 50;
  const unsigned threads = argc > 6 ? static_cast<unsigned>(std::stoi(argv[6])) : 2;
  const int replicates = argc > 7 ? std::stoi(argv[7]) : 3;

  const SessionSettings settings = load_session_settings(dir);
  AnalyzeOptions options = settings.analysis;
  options.keep_revolutions = true;
  options.progress = false;
  std::vector<RecordingTarget> targets;
  for (const auto& rec : find_session_files(dir).recordings) {
    auto manifest = rec;
    manifest.replace_extension(".toml");
    const RecordingAnalysis a = analyze_recording(rec, manifest, options);
    std::optional<RecordingAnalysis> band;
    if (const auto bo = band_analysis_options(a, options)) band = analyze_recording(rec, manifest, *bo);
    targets.push_back(make_recording_target(a, band ? &*band : nullptr, rec.filename().string()));
  }
  std::vector<Variant> variants = {{"baseline", truth, {}},
                                   {"settle1e-4", truth, {1e-4, false}},
                                   {"settle1e-3", truth, {1e-3, false}},
                                   {"point", truth, {1e-6, true}}};
  const std::size_t choices = variants.size();
  for (int k = 1; k <= replicates; ++k) {
    ContactParameters p = truth;
    p.restitution = std::min(1.0, truth.restitution + 0.001 * k);
    variants.push_back({"replicate" + std::to_string(k), p, {}});
  }
  std::vector<std::size_t> jobs(variants.size() * targets.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) jobs[i] = i;
  std::vector<SimulatedStatistics> sims(jobs.size());
  std::mutex m;
  run_case_queue(jobs, threads,
                 [&](std::size_t j) {
                   const Variant& v = variants[j / targets.size()];
                   SimulatedStatistics r = simulate_statistics(targets[j % targets.size()], v.p, 20, sim_turns, 1e-8, v.choices);
                   std::lock_guard lock(m);
                   sims[j] = std::move(r);
                   return std::string();
                 },
                 [](std::size_t, std::string&&) {});

  std::printf("# session %s: truth e = %.2f, %s, mu = %.2f; %zu recordings, model 20 + %d turns\n", dir.c_str(),
              truth.restitution, to_string(truth.contact), truth.friction_coefficient, targets.size(), sim_turns);
  std::printf("# change of the statistic from the baseline: %% (log ratio x 100) / in measured standard errors\n");
  std::printf("%-22s %-7s %-15s", "recording", "link", "statistic");
  for (std::size_t c = 1; c < variants.size(); ++c) std::printf(" %18s", variants[c].label.c_str());
  std::printf("\n");
  // Per statistic (band = "band_excess"), per variant: sum of squared log changes and the count.
  std::map<std::string, std::vector<std::pair<double, int>>> sums;
  for (std::size_t r = 0; r < targets.size(); ++r) {
    const RecordingTarget& t = targets[r];
    for (FitLink l : kFitLinks) {
      const auto li = static_cast<std::size_t>(l);
      if (!t.measured[li]) continue;
      auto print = [&](const std::string& stat, auto value, double measured, double measured_se) {
        const double b = value(sims[r]);
        if (!(b > 0)) return;
        auto& acc = sums[stat];
        acc.resize(variants.size(), {0.0, 0});
        std::printf("%-22s %-7s %-15s", t.name.c_str(), std::string(name_of(l)).c_str(), stat.c_str());
        for (std::size_t c = 1; c < variants.size(); ++c) {
          const double v = value(sims[c * targets.size() + r]);
          const double d = v > 0 ? std::log(v / b) : NAN;
          std::printf(" %8.1f%% %7.2fse", 100 * d, d / (measured_se / measured));
          if (std::isfinite(d)) acc[c].first += d * d, acc[c].second += 1;
        }
        std::printf("\n");
      };
      for (ResponseStatistic s : kResponseStatistics) {
        if (!is_magnitude(s)) continue;
        const auto si = index_of(s);
        print(std::string(name_of(s)), [&](const SimulatedStatistics& x) { return x.link[li] ? x.link[li]->value[si] : 0.0; },
              t.measured[li]->value[si], t.measured[li]->standard_error[si]);
      }
      if (t.measured_band[li])
        print("band_excess", [&](const SimulatedStatistics& x) { return x.band[li] ? x.band[li]->excess : 0.0; },
              t.measured_band[li]->excess, t.measured_band[li]->standard_error);
    }
  }
  std::printf("\n# RMS change over recordings and links (%%): choices");
  for (std::size_t c = 1; c < choices; ++c) std::printf(" | %s", variants[c].label.c_str());
  std::printf(" | replicates (noise)\n");
  for (const auto& [stat, acc] : sums) {
    std::printf("%-15s", stat.c_str());
    for (std::size_t c = 1; c < choices; ++c) std::printf(" %8.1f", acc[c].second ? 100 * std::sqrt(acc[c].first / acc[c].second) : NAN);
    double s = 0;
    int n = 0;
    for (std::size_t c = choices; c < variants.size(); ++c) s += acc[c].first, n += acc[c].second;
    std::printf(" %8.1f\n", n ? 100 * std::sqrt(s / n) : NAN);
  }
  return 0;
}
