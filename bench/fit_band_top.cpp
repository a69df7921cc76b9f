// Where do a rigid-impact model and a recording of another contact agree in
// the band energy the fit uses to find e (docs/fit.md "Band top")? A rigid
// impact is an impulse (flat spectrum); a compliant one lasts 0.1–0.3 ms and
// its spectrum falls above ≈ 1/(3·duration). Per band top, per recording and
// link: the measured band energy, the model's at the truth and at e ∓ DE,
// z = (log model − log measured) / combined standard error at the truth,
// the sensitivity (z change per +0.1 of e) and the e shift it implies
// (−z / sensitivity × 0.1), and the spread's z for comparison.
//
//   fit_band_top SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU TOPS_HZ [SIM_TURNS] [THREADS] [DE]
//
// TOPS_HZ: comma-separated upper band edges (0: the default, 0.3 × the
// sample rate). SESSION_DIR: any session with known truth (bench/make_fit_session.sh,
// tests/independent_rig/make_session.py).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "truth_args.hpp"
#include "cluster/case_queue.hpp"
#include "fit/recording_target.hpp"
#include "report/session_settings.hpp"

using namespace fourbar;

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: fit_band_top SESSION_DIR TRUE_E TRUE_CONTACT TRUE_MU TOPS_HZ [SIM_TURNS] [THREADS] [DE]\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const ContactParameters truth = bench::truth_from_args(argv);
  std::vector<double> tops;
  {
    std::stringstream ss(argv[5]);
    for (std::string item; std::getline(ss, item, ',');) tops.push_back(std::stod(item));
  }
  const int sim_turns = argc > 6 ? std::stoi(argv[6]) : 50;
  const unsigned threads = argc > 7 ? static_cast<unsigned>(std::stoi(argv[7])) : 2;
  const double de = argc > 8 ? std::stod(argv[8]) : 0.15;

  const SessionSettings settings = load_session_settings(dir);
  AnalyzeOptions options = settings.analysis;
  options.keep_revolutions = true;
  options.progress = false;
  // targets[top][recording]
  std::vector<std::vector<RecordingTarget>> targets(tops.size());
  for (const auto& rec : find_session_files(dir).recordings) {
    auto manifest = rec;
    manifest.replace_extension(".toml");
    const RecordingAnalysis a = analyze_recording(rec, manifest, options);
    for (std::size_t k = 0; k < tops.size(); ++k) {
      std::optional<RecordingAnalysis> band;
      if (const auto bo = band_analysis_options(a, options, tops[k])) band = analyze_recording(rec, manifest, *bo);
      targets[k].push_back(make_recording_target(a, band ? &*band : nullptr, rec.filename().string()));
    }
  }
  const std::size_t nrec = targets[0].size();
  std::vector<ContactParameters> points(3, truth);
  points[1].restitution = std::max(0.0, truth.restitution - de);
  points[2].restitution = std::min(1.0, truth.restitution + de);
  const double step = points[2].restitution - points[1].restitution;
  std::vector<std::size_t> jobs(tops.size() * nrec * points.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) jobs[i] = i;
  std::vector<SimulatedStatistics> sims(jobs.size());
  std::mutex m;
  auto index = [&](std::size_t k, std::size_t r, std::size_t p) { return (k * nrec + r) * points.size() + p; };
  run_case_queue(jobs, threads,
                 [&](std::size_t j) {
                   const std::size_t p = j % points.size(), r = (j / points.size()) % nrec, k = j / points.size() / nrec;
                   SimulatedStatistics s = simulate_statistics(targets[k][r], points[p], 20, sim_turns, 1e-8);
                   std::lock_guard lock(m);
                   sims[j] = std::move(s);
                   return std::string();
                 },
                 [](std::size_t, std::string&&) {});

  std::printf("# session %s: truth e = %.2f, %s, mu = %.2f; %zu recordings, model 20 + %d turns, e -/+ %.2f\n",
              dir.c_str(), truth.restitution, to_string(truth.contact), truth.friction_coefficient, nrec, sim_turns, de);
  std::printf("| band Hz | recording | link | measured band | model band at truth | z band | sens per 0.1 e | e shift | z spread |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < tops.size(); ++k) {
    double sum_shift = 0, sum_z2 = 0;
    int n = 0;
    for (std::size_t r = 0; r < nrec; ++r) {
      const RecordingTarget& t = targets[k][r];
      for (FitLink l : kFitLinks) {
        const auto li = static_cast<std::size_t>(l);
        if (!t.measured[li] || !t.measured_band[li]) continue;
        const BandEnergy& meas = *t.measured_band[li];
        auto z = [&](const SimulatedStatistics& s) {
          if (!s.band[li]) return static_cast<double>(NAN);
          const BandEnergy& b = *s.band[li];
          const double var = std::pow(meas.standard_error / meas.excess, 2) + std::pow(b.standard_error / b.excess, 2);
          return std::log(b.excess / meas.excess) / std::sqrt(var);
        };
        const double z0 = z(sims[index(k, r, 0)]);
        const double sens = (z(sims[index(k, r, 2)]) - z(sims[index(k, r, 1)])) / (step / 0.1);
        const double shift = -z0 / sens * 0.1;
        const StatisticValues& ms = *t.measured[li];
        const auto si = index_of(ResponseStatistic::spread);
        double zs = NAN;
        if (sims[index(k, r, 0)].link[li]) {
          const StatisticValues& s = *sims[index(k, r, 0)].link[li];
          zs = std::log(s.value[si] / ms.value[si]) /
               std::sqrt(std::pow(ms.standard_error[si] / ms.value[si], 2) + std::pow(s.standard_error[si] / s.value[si], 2));
        }
        std::printf("| %.0f–%.0f | %s | %s | %.4g ± %.2g | %.4g | %+.2f | %+.2f | %+.3f | %+.2f |\n", t.band_filter->low_hz,
                    t.band_filter->high_hz, t.name.c_str(), std::string(name_of(l)).c_str(), meas.excess,
                    meas.standard_error, sims[index(k, r, 0)].band[li] ? sims[index(k, r, 0)].band[li]->excess : NAN, z0,
                    sens, shift, zs);
        if (std::isfinite(shift)) sum_shift += shift, sum_z2 += z0 * z0, ++n;
      }
    }
    std::printf("# top %.0f Hz: mean e shift %+.3f, RMS z %.2f over %d links\n", tops[k], n ? sum_shift / n : NAN,
                n ? std::sqrt(sum_z2 / n) : NAN, n);
  }
  return 0;
}
