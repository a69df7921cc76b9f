// Work–precision of the linkage model with an elastic coupler (sim/flex,
// pinned–pinned modes from data/rigs/thesis_elastic.toml: 25 × 4 mm steel,
// ζ = 2 %, 1.5 %): 350 rpm, clearance 0.254 mm at B, e = 0.5, K = 1e10
// N/m^1.5, μ = 0, one turn from the nominal links with the modes at rest.
// Error: relative RMS of α3 at 720 crank angles against the same model at
// tolerance 1e-12; time: wall clock per turn (median of `repeats`). Lines for
// 2 and 4 modes.
//
//   bench/elastic_linkage_work_precision [repeats]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "common/units.hpp"
#include "sim/linkage/linkage_simulator.hpp"

using namespace fourbar;

namespace {

struct Result {
  std::vector<double> alpha3;
  double seconds = 0;
};

double rel_rms(const std::vector<double>& a, const std::vector<double>& b) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < a.size(); ++i) num += (a[i] - b[i]) * (a[i] - b[i]), den += b[i] * b[i];
  return std::sqrt(num / den);
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  std::vector<double> times;
  for (int i = 0; i <= 720; ++i) times.push_back(T * i / 720.0);
  auto run = [&](int modes, double tol, int reps) {
    LinkageSpec s;
    s.clearance_m = {0, 0.254e-3, 0};
    s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
    s.friction = {0.0, 1e-4, 1e-3};
    s.tolerance = tol;
    s.elastic = {false, true, false};
    s.elastic_modes = modes;
    const LinkageModel m = build_linkage(rig, s);
    Result r;
    std::vector<double> secs;
    for (int k = 0; k < reps; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      LinkageSimulator sim(m, crank);
      sim.set_sample_times(times);
      sim.start_centred(0.0);
      sim.advance_to(T);
      secs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      r.alpha3.clear();
      for (const LinkageSample& x : sim.samples()) r.alpha3.push_back(x.alpha3_rad_s2);
    }
    std::sort(secs.begin(), secs.end());
    r.seconds = secs[secs.size() / 2];
    return r;
  };
  const Result ref2 = run(2, 1e-12, 1), ref4 = run(4, 1e-12, 1);
  std::printf("# one turn, thesis_elastic rig 350 rpm, clearance at B, e = 0.5, K = 1e10; elastic coupler\n");
  std::printf("# error = relative RMS of alpha3 against the same model at tol 1e-12 (2 modes: %.3f s, 4: %.3f s)\n",
              ref2.seconds, ref4.seconds);
  std::printf("%-8s  %-24s  %-24s\n", "tol", "2 modes (s/turn, error)", "4 modes (s/turn, error)");
  for (double tol : {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11}) {
    const Result a = run(2, tol, repeats), b = run(4, tol, repeats);
    std::printf("%-8.0e  %8.4f  %10.3e     %8.4f  %10.3e\n", tol, a.seconds, rel_rms(a.alpha3, ref2.alpha3), b.seconds,
                rel_rms(b.alpha3, ref4.alpha3));
  }
  return 0;
}
