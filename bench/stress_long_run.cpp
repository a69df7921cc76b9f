// Long runs of the clearance simulator (issue 7): the base scene (thesis
// rig, 350 rpm, ξ = 0.254 mm, e = 0.5, smooth, tolerance 1e-10) for many
// revolutions, turn by turn.
//
//  * Residuals: the energy residual (ΔE − work + losses, relative to the
//    energy scale) after each turn and its change per turn, and the drift
//    per turn (contact-circle error in following mode, penetration in free
//    flight, relative to ξ, at 36 samples per turn and every event witness
//    the simulator monitors), compared over the first and the last 100 turns.
//  * Steady state: the smallest scaled difference between a turn-start state
//    and that of k ≤ 8 turns before (what `steady_state = true` tests
//    against 1e-6), and the per-turn statistics n (impacts) and ΣF over the
//    first and last 100 turns.
//  * Start angles: the same scene from 0°, 90°, 180°, 270° for --starts-turns
//    turns each; n and ΣF per turn averaged over the second half of each run.
//
//   stress_long_run [--turns N] [--starts-turns M]     (defaults 10000, 2000)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "common/units.hpp"
#include "sim/three_mode/simulator.hpp"

using namespace fourbar;

namespace {

constexpr double kXi = 0.254e-3, kRpm = 350;

struct TurnStats {
  double residual = 0;  ///< energy residual / scale at the end of the turn (signed)
  double drift = 0;     ///< max drift / ξ over the turn's samples
  int impacts = 0;
  double sum_F = 0;
  double repeat = 0;    ///< min over k of the scaled start-state difference to k turns before
};

struct Run {
  std::vector<TurnStats> turns;
  double seconds = 0;
  double max_circle = 0, max_penetration = 0, max_residual = 0;
};

double state_difference(const RevolutionRecord& a, const RevolutionRecord& b) {
  if (a.start_mode != b.start_mode) return 1e300;
  double d = 0;
  for (std::size_t i = 0; i < a.start_state.size(); ++i) d = std::max(d, std::abs(a.start_state[i] - b.start_state[i]));
  return d;
}

Run run(double start_deg, int turns) {
  const auto t0 = std::chrono::steady_clock::now();
  const Rig rig = thesis_rig();
  const ClearanceModel model(rig, kXi);
  const double w = units::rpm_to_rad_s(kRpm), period = units::kTwoPi / w;
  const ConstantSpeedCrank crank(units::deg_to_rad(start_deg), w);
  ClearanceSettings s;
  s.restitution = 0.5;
  ClearanceSimulator sim(model, crank, s);
  std::vector<double> times;
  for (int i = 0; i <= 36 * turns; ++i) times.push_back(period * i / 36.0);
  sim.set_sample_times(times);
  sim.set_revolution_origin(units::deg_to_rad(start_deg));
  sim.start_nominal(0.0);
  Run out;
  std::size_t next_sample = 0;
  for (int k = 1; k <= turns; ++k) {
    sim.advance_to(times[static_cast<std::size_t>(36 * k)]);
    const ClearanceDiagnostics d = sim.diagnostics();
    TurnStats st;
    st.residual = d.energy_residual_J / d.energy_scale_J;
    const auto& samples = sim.samples();
    for (; next_sample < samples.size(); ++next_sample) {
      const ClearanceSample& x = samples[next_sample];
      st.drift = std::max(st.drift, x.mode == ContactMode::following ? std::abs(x.gap_m) / kXi : -x.gap_m / kXi);
    }
    const auto& revs = sim.revolutions();
    const RevolutionRecord& r = revs[static_cast<std::size_t>(k - 1)];
    st.impacts = r.impacts;
    st.sum_F = r.sum_normal_impulse_Ns;
    st.repeat = 1e300;
    if (static_cast<int>(revs.size()) > k)
      for (int p = 1; p <= 8 && k - p >= 0; ++p) st.repeat = std::min(st.repeat, state_difference(revs[k], revs[k - p]));
    out.turns.push_back(st);
    out.max_circle = d.max_contact_circle_error;
    out.max_penetration = d.max_penetration;
    out.max_residual = d.max_energy_residual_J / d.energy_scale_J;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

struct Window {
  double residual_abs_max = 0, step_rms = 0, drift_max = 0, n_mean = 0, n_sd = 0, F_mean = 0, F_sd = 0,
         repeat_min = 1e300;
};

Window window(const Run& r, std::size_t from, std::size_t to) {
  Window w;
  double n2 = 0, F2 = 0;
  const double count = static_cast<double>(to - from);
  for (std::size_t i = from; i < to; ++i) {
    const TurnStats& t = r.turns[i];
    w.residual_abs_max = std::max(w.residual_abs_max, std::abs(t.residual));
    const double step = t.residual - (i ? r.turns[i - 1].residual : 0.0);
    w.step_rms += step * step;
    w.drift_max = std::max(w.drift_max, t.drift);
    w.n_mean += t.impacts;
    n2 += static_cast<double>(t.impacts) * t.impacts;
    w.F_mean += t.sum_F;
    F2 += t.sum_F * t.sum_F;
    w.repeat_min = std::min(w.repeat_min, t.repeat);
  }
  w.step_rms = std::sqrt(w.step_rms / count);
  w.n_mean /= count;
  w.F_mean /= count;
  w.n_sd = std::sqrt(std::max(0.0, n2 / count - w.n_mean * w.n_mean));
  w.F_sd = std::sqrt(std::max(0.0, F2 / count - w.F_mean * w.F_mean));
  return w;
}

void print_window(const char* name, const Window& w) {
  std::printf("%-18s | %9.2e | %9.2e | %9.2e | %6.1f ± %5.1f | %7.4f ± %6.4f | %9.2e\n", name, w.residual_abs_max,
              w.step_rms, w.drift_max, w.n_mean, w.n_sd, w.F_mean, w.F_sd, w.repeat_min);
}

}  // namespace

int main(int argc, char** argv) {
  int turns = 10000, start_turns = 2000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--turns") && i + 1 < argc) turns = std::max(200, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--starts-turns") && i + 1 < argc) start_turns = std::max(0, std::atoi(argv[++i]));
    else {
      std::fprintf(stderr, "usage: stress_long_run [--turns N] [--starts-turns M]\n");
      return 2;
    }
  }
  std::printf("base scene: thesis rig, %g rpm, xi = %g mm, e = 0.5, smooth, tolerance 1e-10\n\n", kRpm,
              units::m_to_mm(kXi));
  const Run r = run(0, turns);
  std::printf("%d turns from 0° in %.1f s (%.2f ms/turn)\n", turns, r.seconds, 1e3 * r.seconds / turns);
  std::printf("%-18s | %9s | %9s | %9s | %14s | %16s | %9s\n", "turns", "|res| max", "res/turn", "drift max",
              "n per turn", "sum F per turn Ns", "repeat min");
  print_window("first 100", window(r, 0, 100));
  print_window("last 100", window(r, r.turns.size() - 100, r.turns.size()));
  print_window("all", window(r, 0, r.turns.size()));
  std::printf("run max: contact-circle error %.2e, penetration %.2e, energy residual %.2e (bounds 1e-9, 1e-9, 1e-8)\n",
              r.max_circle, r.max_penetration, r.max_residual);
  std::printf("(res: energy residual / energy scale after each turn; res/turn: RMS of its change per turn;\n"
              " repeat: smallest scaled difference of a turn-start state to one of the 8 before — steady_state\n"
              " needs <= 1e-6)\n");

  if (start_turns > 0) {
    std::printf("\nsame scene from four start angles, %d turns each; n and sum F per turn over turns %d-%d:\n",
                start_turns, start_turns / 2, start_turns);
    std::printf("%-10s | %14s | %16s | %9s | %9s\n", "start", "n per turn", "sum F per turn Ns", "|res| max", "seconds");
    for (double a : {0.0, 90.0, 180.0, 270.0}) {
      const Run s = run(a, start_turns);
      const Window w = window(s, s.turns.size() / 2, s.turns.size());
      std::printf("%8.0f° | %6.2f ± %5.2f | %7.4f ± %6.4f | %9.2e | %9.1f\n", a, w.n_mean, w.n_sd, w.F_mean, w.F_sd,
                  window(s, 0, s.turns.size()).residual_abs_max, s.seconds);
    }
    std::printf("(± : standard deviation over the turns, not the error of the mean)\n");
  }
  return 0;
}
