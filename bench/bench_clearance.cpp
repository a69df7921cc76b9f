// Work–precision of the clearance simulator (issue 3), like SciMLBenchmarks:
// thesis rig, 350 rpm, ξ = 0.254 mm, smooth impacts, e = 1 and e = 0.5.
// For each integrator and tolerance: the RMS error of α3 against a reference
// run at the tightest tolerance (CVODE, 1e-13), relative to the RMS of the
// reference α3, and the run time per revolution (minimum of several timed
// runs after a warm-up, without output sampling).
//
// The run starts in the following mode at crank angle 0; the first contact
// loss comes at about 373°, so turns 0 and 1 are simulated and the error is
// taken over turn 1 (360°–720°, 3600 samples) and over a short horizon
// 360°–390° that holds the first impact burst.
//
//   bench_clearance [--quick] [--csv FILE]
//   bench_clearance --profile E INTEGRATOR TOL N   (N untimed runs of one case, for a profiler)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "sim/three_mode/simulator.hpp"

using namespace fourbar;

namespace {

constexpr double kRpm = 350, kXi = 0.254e-3;
constexpr int kSamplesPerTurn = 3600;

struct Trial {
  std::vector<double> alpha3;  // turn 1, samples 0..3600
  std::size_t impacts = 0, steps = 0;
};

double period() { return units::kTwoPi / units::rpm_to_rad_s(kRpm); }

Trial simulate(const Rig& rig, double e, IntegratorKind kind, double tol, bool sample) {
  const ClearanceModel model(rig, kXi);
  const ConstantSpeedCrank crank(0.0, units::rpm_to_rad_s(kRpm));
  ClearanceSettings s;
  s.restitution = e;
  s.integrator = kind;
  s.tolerance = tol;
  ClearanceSimulator sim(model, crank, s);
  if (sample) {
    std::vector<double> t(kSamplesPerTurn + 1);
    for (int i = 0; i <= kSamplesPerTurn; ++i) t[i] = period() * (1.0 + static_cast<double>(i) / kSamplesPerTurn);
    sim.set_sample_times(t);
  }
  sim.start_nominal(0.0);
  sim.advance_to(2 * period());
  Trial out;
  for (const auto& x : sim.samples()) out.alpha3.push_back(x.alpha3_rad_s2);
  const auto d = sim.diagnostics();
  out.impacts = d.impacts;
  out.steps = d.steps;
  return out;
}

double seconds_per_turn(const Rig& rig, double e, IntegratorKind kind, double tol, int repeats) {
  simulate(rig, e, kind, tol, false);  // warm-up
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    simulate(rig, e, kind, tol, false);
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
  }
  return best / 2;  // two turns per run
}

/// RMS error over samples [0, n] relative to the reference RMS over the same samples.
double rel_rms(const std::vector<double>& a, const std::vector<double>& ref, std::size_t n) {
  double e2 = 0, r2 = 0;
  for (std::size_t i = 0; i <= n && i < ref.size(); ++i) {
    e2 += (a[i] - ref[i]) * (a[i] - ref[i]);
    r2 += ref[i] * ref[i];
  }
  return std::sqrt(e2 / r2);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string csv_path = "bench_clearance.csv";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv_path = argv[++i];
    else if (!std::strcmp(argv[i], "--profile") && i + 4 < argc) {
      const double e = std::atof(argv[i + 1]);
      const IntegratorKind kind = std::strcmp(argv[i + 2], "cvode") ? IntegratorKind::odeint : IntegratorKind::cvode;
      const double tol = std::atof(argv[i + 3]);
      const int n = std::atoi(argv[i + 4]);
      const Rig rig = thesis_rig();
      std::size_t steps = 0;
      double best = 1e300;
      for (int r = 0; r < n; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        steps = simulate(rig, e, kind, tol, false).steps;
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
      const Trial ref = simulate(rig, e, IntegratorKind::cvode, 1e-13, true);
      const double err = rel_rms(simulate(rig, e, kind, tol, true).alpha3, ref.alpha3, kSamplesPerTurn);
      std::printf("%d runs, %zu steps each, fastest %.3f ms/turn, alpha3 rel. RMS error over turn 1 %.2e\n", n, steps,
                  1e3 * best / 2, err);
      return 0;
    }
  }
  const Rig rig = thesis_rig();
  const std::vector<double> tols = quick ? std::vector<double>{1e-6, 1e-9}
                                         : std::vector<double>{1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  const int repeats = quick ? 2 : 5;
  const std::size_t short_n = kSamplesPerTurn / 12;  // 30° of crank

  std::ofstream csv(csv_path);
  csv << "restitution,integrator,tolerance,ms_per_rev,alpha3_rel_rms_turn,alpha3_rel_rms_30deg,impacts,steps\n";
  std::printf("thesis rig, 350 rpm, xi = 0.254 mm, smooth; error of alpha3 over turn 1 and its first 30 deg\n");
  std::printf("%-4s %-7s %-9s %12s %14s %14s %8s %8s\n", "e", "integr.", "tol", "ms/rev", "relRMS turn", "relRMS 30deg",
              "impacts", "steps");
  for (double e : {1.0, 0.5}) {
    const Trial ref = simulate(rig, e, IntegratorKind::cvode, 1e-13, true);
    const Trial ref2 = simulate(rig, e, IntegratorKind::odeint, 1e-13, true);
    std::printf("e = %.1f: reference CVODE 1e-13 (%zu impacts); odeint 1e-13 differs by %.2e (turn), %.2e (30 deg)\n", e,
                ref.impacts, rel_rms(ref2.alpha3, ref.alpha3, kSamplesPerTurn), rel_rms(ref2.alpha3, ref.alpha3, short_n));
    for (IntegratorKind kind : {IntegratorKind::cvode, IntegratorKind::odeint}) {
      for (double tol : tols) {
        const Trial t = simulate(rig, e, kind, tol, true);
        const double err = rel_rms(t.alpha3, ref.alpha3, kSamplesPerTurn);
        const double err_short = rel_rms(t.alpha3, ref.alpha3, short_n);
        const double ms = 1e3 * seconds_per_turn(rig, e, kind, tol, repeats);
        std::printf("%-4.1f %-7s %-9.0e %12.3f %14.3e %14.3e %8zu %8zu\n", e, to_string(kind), tol, ms, err, err_short,
                    t.impacts, t.steps);
        csv << e << "," << to_string(kind) << "," << tol << "," << ms << "," << err << "," << err_short << ","
            << t.impacts << "," << t.steps << "\n";
      }
    }
  }
  std::printf("wrote %s\n", csv_path.c_str());
  return 0;
}
