// Work–precision of the linkage model with an elastic coupler AND rocker
// (issue 25's speed case; sim/flex pinned–pinned modes from
// data/rigs/thesis_elastic.toml: 25 × 4 mm steel, ζ = 2, 1.5, 1, 1 %): 350
// rpm, clearance 0.254 mm at B only, e = 0.5, K = 1e10 N/m^1.5, μ = 0, one
// turn from the nominal links with the pins centred and the modes at rest.
// Error: relative RMS of the coupler sensor's tangential acceleration (at
// mid-span, 154.5 mm, the elastic-coupler scene's first sensor) at 720 crank
// angles against the same model at tolerance 1e-12; the rocker's mid-span
// sensor and α3 are printed beside it. Time: CPU time per turn (user + sys of
// this single-threaded process, median of `repeats`) and wall time.
// Lines for 2 and 4 modes per link.
//
//   bench/elastic_linkage_work_precision [--method bdf|esdirk4|esdirk5|erk|adams] [repeats] [modes...]
//   bench/elastic_linkage_work_precision [--method M] --one MODES TOL [CSV]   (one run, for a
//     profiler; CSV gets the coupler and rocker sensor columns and α3)
//   bench/elastic_linkage_work_precision [--method M] --turns MODES TURNS TOL   (TURNS turns in one
//     run: CPU, steps and coupler-sensor error per turn against the reference run as long)
//   bench/elastic_linkage_work_precision [--method M] --steps MODES TURNS TOL [CSV]   (how many
//     steps each state component set, steps and median step per tenth of the run;
//     CSV: every step's end, size, order, weighted error and the component that set it)
//   bench/elastic_linkage_work_precision --share MODES SAMPLES [CSV]   (the
//     reference at tol 1e-12 sampled SAMPLES times a turn; per link and shape
//     its eigenfrequency and the RMS of its direct part Φy_k(L/2)·η̈_k of the
//     mid-span sensor over the sensor's RMS; CSV: the sensors and those parts,
//     for bench/elastic_mode_share.py's spectrum)

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "sim/flex/shape_function.hpp"
#include "sim/linkage/linkage_simulator.hpp"

using namespace fourbar;

namespace {

struct Result {
  std::vector<double> coupler, rocker, alpha3;
  std::vector<std::array<std::array<double, 4>, 2>> modal_accel;
  double cpu_s = 0, wall_s = 0;
  std::string counters;
};

double rel_rms(const std::vector<double>& a, const std::vector<double>& b) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < a.size(); ++i) num += (a[i] - b[i]) * (a[i] - b[i]), den += b[i] * b[i];
  return std::sqrt(num / den);
}

double rms(const std::vector<double>& a) {
  double s = 0;
  for (double x : a) s += x * x;
  return std::sqrt(s / static_cast<double>(a.size()));
}

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace

int main(int argc_in, char** argv_in) {
  // --method bdf|esdirk4|esdirk5|erk|adams (first), then the modes below.
  std::vector<char*> args(argv_in, argv_in + argc_in);
  LinkageMethod method = LinkageMethod::bdf;
  std::string method_name = "bdf";
  if (args.size() > 2 && std::string(args[1]) == "--method") {
    method_name = args[2];
    if (method_name == "esdirk4") method = LinkageMethod::esdirk4;
    else if (method_name == "esdirk5") method = LinkageMethod::esdirk5;
    else if (method_name == "erk") method = LinkageMethod::erk;
    else if (method_name == "adams") method = LinkageMethod::adams;
    else if (method_name != "bdf") {
      std::fprintf(stderr, "fourbar: --method %s: use bdf, esdirk4, esdirk5, erk or adams\n", method_name.c_str());
      return 2;
    }
    args.erase(args.begin() + 1, args.begin() + 3);
  }
  const int argc = static_cast<int>(args.size());
  char** argv = args.data();
  const bool one = (argc == 4 || argc == 5) && std::string(argv[1]) == "--one";
  const bool share = (argc == 4 || argc == 5) && std::string(argv[1]) == "--share";
  const bool turns_mode = argc == 5 && std::string(argv[1]) == "--turns";
  const bool steps_mode = (argc == 5 || argc == 6) && std::string(argv[1]) == "--steps";
  const int repeats = argc > 1 && !one && !share && !turns_mode && !steps_mode ? std::max(1, std::atoi(argv[1])) : 3;
  std::vector<int> mode_counts;
  for (int i = 2; i < argc && !one && !share && !turns_mode && !steps_mode; ++i) mode_counts.push_back(std::atoi(argv[i]));
  if (mode_counts.empty()) mode_counts = {2, 4};
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  std::vector<double> times;
  for (int i = 0; i <= 720; ++i) times.push_back(T * i / 720.0);
  auto spec = [&](int modes, double tol, LinkageMethod meth) {
    LinkageSpec s;
    s.clearance_m = {0, 0.254e-3, 0};
    s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
    s.friction = {0.0, 1e-4, 1e-3};
    s.tolerance = tol;
    s.elastic = {false, true, true};
    s.elastic_modes = modes;
    s.method = meth;
    return s;
  };
  auto run = [&](int modes, double tol, int reps, LinkageMethod meth) {
    const LinkageModel m = build_linkage(rig, spec(modes, tol, meth));
    Result r;
    std::vector<double> cpu, wall;
    for (int k = 0; k < reps; ++k) {
      const double c0 = cpu_seconds();
      const auto t0 = std::chrono::steady_clock::now();
      LinkageSimulator sim(m, crank);
      sim.set_sample_times(times);
      sim.set_sensors({{1, 0.5 * rig.coupler.length_m, 0.0}, {2, 0.5 * rig.rocker.length_m, 0.0}});
      sim.start_centred(0.0);
      sim.advance_to(T);
      cpu.push_back(cpu_seconds() - c0);
      wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      r.coupler.clear();
      r.rocker.clear();
      r.alpha3.clear();
      r.modal_accel.clear();
      for (const LinkageSample& x : sim.samples()) {
        r.coupler.push_back(x.sensor_m_s2[0]);
        r.rocker.push_back(x.sensor_m_s2[1]);
        r.alpha3.push_back(x.alpha3_rad_s2);
        r.modal_accel.push_back(x.modal_accel_m_s2);
      }
      r.counters = sim.integrator_counters() + ", steps " + std::to_string(sim.diagnostics().steps) + ", contacts " +
                   std::to_string(sim.contacts().size());
    }
    std::sort(cpu.begin(), cpu.end());
    std::sort(wall.begin(), wall.end());
    r.cpu_s = cpu[cpu.size() / 2];
    r.wall_s = wall[wall.size() / 2];
    return r;
  };
  if (share) {
    // Each mode's direct part of the sensors at the reference tolerance: the
    // lateral Φy_k(r)·η̈_k at the sensor, its RMS over the sensor's RMS.
    const int modes = std::atoi(argv[2]), count = std::atoi(argv[3]);
    times.clear();
    for (int i = 0; i <= count; ++i) times.push_back(T * i / count);
    const Result a = run(modes, 1e-12, 1, LinkageMethod::bdf);
    const LinkageModel m = build_linkage(rig, spec(modes, 1e-12, LinkageMethod::bdf));
    std::FILE* f = argc == 5 ? std::fopen(argv[4], "w") : nullptr;
    if (f) std::fprintf(f, "time_s,coupler_m_s2,rocker_m_s2");
    std::vector<std::vector<double>> parts;
    for (int b = 1; b <= 2; ++b) {
      const ElasticLink& link = *m.elastic(b);
      const double phi_scale = 0.5;  // both sensors at mid-span
      for (int k = 0; k < link.modes(); ++k) {
        const double phi = evaluate(link.shapes[static_cast<std::size_t>(k)], phi_scale).y;
        std::vector<double> p;
        for (const auto& acc : a.modal_accel) p.push_back(phi * acc[static_cast<std::size_t>(b - 1)][static_cast<std::size_t>(k)]);
        const std::vector<double>& sensor = b == 1 ? a.coupler : a.rocker;
        std::vector<double> antinode;
        for (const auto& acc : a.modal_accel) antinode.push_back(acc[static_cast<std::size_t>(b - 1)][static_cast<std::size_t>(k)]);
        std::printf("%s shape %d: eigenfrequency %7.1f Hz, direct share at mid-span %.3e (shape value %+.3f), "
                    "at its antinode %.3e\n",
                    b == 1 ? "coupler" : "rocker", k + 1, link.frequencies_rad_s(k) / units::kTwoPi,
                    rms(p) / rms(sensor), phi, rms(antinode) / rms(sensor));
        if (f) std::fprintf(f, ",%s_eta%d_part_m_s2", b == 1 ? "coupler" : "rocker", k + 1);
        parts.push_back(std::move(p));
      }
    }
    if (f) {
      std::fprintf(f, "\n");
      for (std::size_t i = 0; i < a.coupler.size(); ++i) {
        std::fprintf(f, "%.17g,%.17g,%.17g", times[i], a.coupler[i], a.rocker[i]);
        for (const auto& p : parts) std::fprintf(f, ",%.17g", p[i]);
        std::fprintf(f, "\n");
      }
      std::fclose(f);
    }
    std::printf("cpu %.3f s, %s\n", a.cpu_s, a.counters.c_str());
    return 0;
  }
  if (steps_mode) {
    // Which state component sets the step, and where in the turn the steps go.
    const int modes = std::atoi(argv[2]), n_turns = std::atoi(argv[3]);
    const double tol = std::atof(argv[4]), span = n_turns * T;
    const LinkageModel m = build_linkage(rig, spec(modes, tol, method));
    LinkageSimulator sim(m, crank);
    std::vector<LinkageStepTrace> trace;
    sim.trace_steps(&trace);
    sim.start_centred(0.0);
    sim.advance_to(span);
    std::printf("# %d modes per link, %s at tol %g, %d turns: %zu steps, %s, contacts %zu\n", modes,
                method_name.c_str(), tol, n_turns, trace.size(), sim.integrator_counters().c_str(),
                sim.contacts().size());
    std::vector<std::size_t> by_component;
    for (const LinkageStepTrace& r : trace) {
      if (r.limiting >= by_component.size()) by_component.resize(r.limiting + 1, 0);
      ++by_component[r.limiting];
    }
    std::printf("\n%-24s %7s %7s\n", "step set by", "steps", "share");
    for (std::size_t i = 0; i < by_component.size(); ++i)
      if (by_component[i] > 0)
        std::printf("%-24s %7zu %6.1f%%\n", sim.state_component(i).c_str(), by_component[i],
                    100.0 * static_cast<double>(by_component[i]) / static_cast<double>(trace.size()));
    std::printf("\n%-15s %7s %12s %9s\n", "turns", "steps", "median_h_us", "orders");
    for (int part = 0; part < 10; ++part) {
      std::vector<double> h;
      int lo = 99, hi = 0;
      for (const LinkageStepTrace& r : trace)
        if (r.end_time_s > span * part / 10.0 && r.end_time_s <= span * (part + 1) / 10.0) {
          h.push_back(r.step_s);
          lo = std::min(lo, r.order);
          hi = std::max(hi, r.order);
        }
      std::sort(h.begin(), h.end());
      std::printf("%4.1f-%-10.1f %7zu %12.2f %6d-%d\n", n_turns * part / 10.0, n_turns * (part + 1) / 10.0, h.size(),
                  h.empty() ? 0.0 : 1e6 * h[h.size() / 2], h.empty() ? 0 : lo, hi);
    }
    if (argc == 6)
      if (std::FILE* f = std::fopen(argv[5], "w")) {
        std::fprintf(f, "end_time_s,step_s,order,weighted_error,limiting\n");
        for (const LinkageStepTrace& r : trace)
          std::fprintf(f, "%.17g,%.17g,%d,%.6g,%s\n", r.end_time_s, r.step_s, r.order, r.weighted_error,
                       sim.state_component(r.limiting).c_str());
        std::fclose(f);
      }
    return 0;
  }
  if (turns_mode) {
    // Several turns in one run: the first turn holds the start's transient
    // (pins centred, modes at rest), the later ones are what a long run
    // costs per turn. Per turn: CPU, steps, and the error against the
    // reference run of the same length.
    const int modes = std::atoi(argv[2]), n_turns = std::atoi(argv[3]);
    const double tol = std::atof(argv[4]);
    times.clear();
    for (int i = 0; i <= 720 * n_turns; ++i) times.push_back(T * i / 720.0);
    auto turns_run = [&](double run_tol, LinkageMethod meth, std::vector<double>& cpu_turn, std::vector<std::size_t>& steps_turn) {
      const LinkageModel m = build_linkage(rig, spec(modes, run_tol, meth));
      Result r;
      LinkageSimulator sim(m, crank);
      sim.set_sample_times(times);
      sim.set_sensors({{1, 0.5 * rig.coupler.length_m, 0.0}, {2, 0.5 * rig.rocker.length_m, 0.0}});
      sim.start_centred(0.0);
      std::size_t steps0 = 0;
      for (int k = 1; k <= n_turns; ++k) {
        const double c0 = cpu_seconds();
        sim.advance_to(T * k);
        cpu_turn.push_back(cpu_seconds() - c0);
        const std::size_t steps = sim.diagnostics().steps;
        steps_turn.push_back(steps - steps0);
        steps0 = steps;
      }
      for (const LinkageSample& x : sim.samples()) r.coupler.push_back(x.sensor_m_s2[0]);
      r.counters = sim.integrator_counters() + ", contacts " + std::to_string(sim.contacts().size());
      return r;
    };
    std::vector<double> cpu_ref, cpu;
    std::vector<std::size_t> steps_ref, steps;
    const Result ref = turns_run(1e-12, LinkageMethod::bdf, cpu_ref, steps_ref);
    const Result a = turns_run(tol, method, cpu, steps);
    std::printf("# %d modes per link, %s at tol %g, %d turns; reference BDF at 1e-12 (%s)\n", modes,
                method_name.c_str(), tol, n_turns, ref.counters.c_str());
    std::printf("%-5s %9s %8s %11s %12s\n", "turn", "cpu_s", "steps", "err_sensor", "ref_steps");
    double later_cpu = 0;
    for (int k = 0; k < n_turns; ++k) {
      const std::vector<double> x(a.coupler.begin() + 720 * k, a.coupler.begin() + 720 * (k + 1));
      const std::vector<double> y(ref.coupler.begin() + 720 * k, ref.coupler.begin() + 720 * (k + 1));
      std::printf("%-5d %9.4f %8zu %11.3e %12zu\n", k + 1, cpu[static_cast<std::size_t>(k)],
                  steps[static_cast<std::size_t>(k)], rel_rms(x, y), steps_ref[static_cast<std::size_t>(k)]);
      if (k > 0) later_cpu += cpu[static_cast<std::size_t>(k)];
    }
    if (n_turns > 1) std::printf("turns 2..%d: %.4f s per turn\n", n_turns, later_cpu / (n_turns - 1));
    return 0;
  }
  if (one) {
    const Result a = run(std::atoi(argv[2]), std::atof(argv[3]), 1, method);
    std::printf("cpu %.4f s, wall %.4f s, %s\n", a.cpu_s, a.wall_s, a.counters.c_str());
    if (argc == 5)
      if (std::FILE* f = std::fopen(argv[4], "w")) {
        std::fprintf(f, "coupler_m_s2,rocker_m_s2,alpha3_rad_s2\n");
        for (std::size_t i = 0; i < a.coupler.size(); ++i)
          std::fprintf(f, "%.17g,%.17g,%.17g\n", a.coupler[i], a.rocker[i], a.alpha3[i]);
        std::fclose(f);
      }
    return 0;
  }
  std::printf("# one turn, thesis_elastic rig 350 rpm, clearance 0.254 mm at B, e = 0.5, K = 1e10, mu = 0;\n"
              "# elastic coupler and rocker; error = relative RMS against the same model at tol 1e-12 of the\n"
              "# coupler's mid-span sensor (tangential m/s^2), the rocker's, and alpha3; CPU and wall s per turn\n"
              "# method %s (the reference is BDF at tol 1e-12 whatever the method)\n", method_name.c_str());
  for (int modes : mode_counts) {
    const Result ref = run(modes, 1e-12, 1, LinkageMethod::bdf);
    std::printf("\n## %d modes per link; reference (tol 1e-12): cpu %.3f s, %s\n", modes, ref.cpu_s,
                ref.counters.c_str());
    std::printf("%-7s %9s %9s %11s %11s %11s  %s\n", "tol", "cpu_s", "wall_s", "err_sensor", "err_rocker",
                "err_alpha3", "counters");
    for (double tol : {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11}) {
      const Result a = run(modes, tol, repeats, method);
      std::printf("%-7.0e %9.4f %9.4f %11.3e %11.3e %11.3e  %s\n", tol, a.cpu_s, a.wall_s,
                  rel_rms(a.coupler, ref.coupler), rel_rms(a.rocker, ref.rocker), rel_rms(a.alpha3, ref.alpha3),
                  a.counters.c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
