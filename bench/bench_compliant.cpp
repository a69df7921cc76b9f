// Work–precision of the compliant contact model beside the three-mode model's
// (bench_clearance): thesis rig, 350 rpm, ξ = 0.254 mm, e = 0.5 (the impact
// regime), the default (calibrated) damping, no friction, stiffness K
// (default 1e10 N/m^1.5; --stiffness K). For each tolerance: the RMS error of
// α3 over turn 1 (360°–720°, 3600 samples) against a reference run at
// tolerance 1e-13, relative to the reference's RMS α3, over the whole turn
// and its first 30°, the run time per revolution (fastest of several runs of
// two turns without output sampling, in process CPU time: the machine is
// shared; the damping law's calibration is solved once per process before,
// and timed on its own), and the share of the simulated time in contact.
// The same table for the three-mode model (Odeint) with e = 0.5 is printed
// beside it. --integrators adds the compliant model under CVODE's Adams
// modes (fixed-point and Newton iteration, orders up to 12) beside BDF, at
// tolerances 1e-9 … 1e-11 (docs/compliant.md "Why BDF"; slow: the Adams
// modes need 10⁵–10⁶ steps), and the 3-stage Radau IIA (radau_integrator.hpp)
// at tolerances 1e-8 … 1e-15, all against the BDF reference.
//
//   bench_compliant [--quick] [--integrators] [--stiffness K] [--csv FILE]
//   bench_compliant --radau [--quick] [--stiffness K] [--csv FILE]   (BDF and Radau IIA only)
//   bench_compliant [--stiffness K] [--radau] --profile TOL N   (N runs of one case, for a profiler; prints
//                                                               the integrator's counters)

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include "common/units.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/three_mode/simulator.hpp"

using namespace fourbar;

namespace {

constexpr double kRpm = 350, kXi = 0.254e-3, kE = 0.5;
constexpr int kSamplesPerTurn = 3600;

struct Trial {
  std::vector<double> alpha3;
  std::size_t impacts = 0, steps = 0;
  double contact_share = 0;  ///< of the simulated time
  std::string counters;      ///< the compliant integrator's
};

struct Path {
  const char* name;
  bool compliant;
  StiffMethod method;
  bool own_reference;  ///< else the previous path's reference (the same model)
};

double period() { return units::kTwoPi / units::rpm_to_rad_s(kRpm); }

template <class Sim>
Trial run(Sim& sim, bool sample) {
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
  out.contact_share = d.time_following_s / (d.time_following_s + d.time_free_s);
  if constexpr (std::is_same_v<Sim, CompliantSimulator>) out.counters = sim.integrator_counters();
  return out;
}

Trial simulate(bool compliant, double stiffness, double tol, bool sample, StiffMethod method = StiffMethod::bdf) {
  const ClearanceModel model(thesis_rig(), kXi);
  const ConstantSpeedCrank crank(0.0, units::rpm_to_rad_s(kRpm));
  ClearanceSettings s;
  s.restitution = kE;
  s.tolerance = tol;
  if (compliant) {
    s.model = ClearanceKind::compliant;
    s.compliant.stiffness_N_per_m_n = stiffness;
    s.compliant.method = method;
    CompliantSimulator sim(model, crank, s);
    return run(sim, sample);
  }
  ClearanceSimulator sim(model, crank, s);
  return run(sim, sample);
}

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double ms_per_turn(const Path& p, double stiffness, double tol, int repeats) {
  simulate(p.compliant, stiffness, tol, false, p.method);
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = cpu_seconds();
    simulate(p.compliant, stiffness, tol, false, p.method);
    best = std::min(best, cpu_seconds() - t0);
  }
  return 1e3 * best / 2;
}

double rel_rms(const std::vector<double>& a, const std::vector<double>& ref, std::size_t n) {
  double e2 = 0, r2 = 0;
  for (std::size_t i = 0; i <= n && i < ref.size() && i < a.size(); ++i) {
    e2 += (a[i] - ref[i]) * (a[i] - ref[i]);
    r2 += ref[i] * ref[i];
  }
  return std::sqrt(e2 / r2);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, integrators = false, radau = false;
  double stiffness = 1e10;
  std::string csv_path = "bench_compliant.csv";
  double profile_tol = 0;
  int profile_runs = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--integrators")) integrators = true;
    else if (!std::strcmp(argv[i], "--radau")) radau = true;
    else if (!std::strcmp(argv[i], "--stiffness") && i + 1 < argc) stiffness = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv_path = argv[++i];
    else if (!std::strcmp(argv[i], "--profile") && i + 2 < argc) {
      profile_tol = std::atof(argv[i + 1]);
      profile_runs = std::atoi(argv[i + 2]);
      i += 2;
    }
  }
  if (profile_runs > 0) {
    const double c0 = cpu_seconds();
    Trial t;
    for (int r = 0; r < profile_runs; ++r) t = simulate(true, stiffness, profile_tol, false, radau ? StiffMethod::radau5 : StiffMethod::bdf);
    std::printf("%d runs of 2 turns, %zu steps each; %s; %.2f ms CPU per turn\n", profile_runs, t.steps,
                t.counters.c_str(), 1e3 * (cpu_seconds() - c0) / (2 * profile_runs));
    return 0;
  }
  const std::vector<double> tols =
      quick ? std::vector<double>{1e-6, 1e-8}
            : std::vector<double>{1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  const std::vector<double> adams_tols = quick ? std::vector<double>{1e-8} : std::vector<double>{1e-9, 1e-10, 1e-11};
  const std::vector<double> radau_tols =
      quick ? std::vector<double>{1e-8} : std::vector<double>{1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15};
  std::vector<Path> paths{{"compliant", true, StiffMethod::bdf, true}};
  if (integrators) {
    paths.push_back({"adams-fp", true, StiffMethod::adams_fixed_point, false});
    paths.push_back({"adams-newt", true, StiffMethod::adams_newton, false});
    paths.push_back({"radau5", true, StiffMethod::radau5, false});
  }
  if (radau && !integrators) paths.push_back({"radau5", true, StiffMethod::radau5, false});
  if (!radau) paths.push_back({"three-mode", false, StiffMethod::bdf, true});
  const int repeats = quick ? 1 : 3;
  const std::size_t short_n = kSamplesPerTurn / 12;
  std::ofstream csv(csv_path);
  csv << "model,stiffness_N_per_m_n,tolerance,ms_per_rev,alpha3_rel_rms_turn,alpha3_rel_rms_30deg,impacts,steps,"
         "contact_share,rhs\n";
  {
    const double t0 = cpu_seconds();
    (void)hysteresis_factor(DampingLaw::calibrated, kE, 1.5);
    std::printf("calibrated damping for e = %.2f: solved in %.1f ms CPU (once per process)\n", kE,
                1e3 * (cpu_seconds() - t0));
  }
  std::printf("thesis rig, 350 rpm, xi = 0.254 mm, e = 0.5, no friction, K = %.3g; alpha3 error over turn 1 and its "
              "first 30 deg\n", stiffness);
  std::printf("%-11s %-9s %10s %14s %14s %8s %8s %9s  %s\n", "model", "tol", "ms/rev", "relRMS turn",
              "relRMS 30deg", "impacts", "steps", "contact", "integrator (compliant)");
  Trial ref;
  for (const Path& p : paths) {
    // One reference per model: the compliant model's is BDF at 1e-13, for every CVODE mode.
    if (p.own_reference) {
      ref = simulate(p.compliant, stiffness, 1e-13, true);
      std::printf("%s: reference at tolerance 1e-13 (%zu impacts, %zu steps)\n", p.name, ref.impacts, ref.steps);
    }
    const bool adams = p.method == StiffMethod::adams_fixed_point || p.method == StiffMethod::adams_newton;
    const bool radau5 = p.method == StiffMethod::radau5;
    for (double tol : adams ? adams_tols : radau5 ? radau_tols : tols) {
      const Trial t = simulate(p.compliant, stiffness, tol, true, p.method);
      const double err = rel_rms(t.alpha3, ref.alpha3, kSamplesPerTurn);
      const double err_short = rel_rms(t.alpha3, ref.alpha3, short_n);
      const double ms = ms_per_turn(p, stiffness, tol, adams ? 1 : repeats);
      std::printf("%-11s %-9.0e %10.3f %14.3e %14.3e %8zu %8zu %8.1f%%  %s\n", p.name, tol, ms, err, err_short,
                  t.impacts, t.steps, 100 * t.contact_share, t.counters.c_str());
      csv << p.name << "," << (p.compliant ? stiffness : 0.0) << "," << tol << "," << ms << "," << err << ","
          << err_short << "," << t.impacts << "," << t.steps << "," << t.contact_share << ","
          << (t.counters.empty() ? std::string() : t.counters.substr(4, t.counters.find(',') - 4)) << "\n";
    }
  }
  std::printf("wrote %s\n", csv_path.c_str());
  return 0;
}
