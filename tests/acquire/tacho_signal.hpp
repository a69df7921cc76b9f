#pragma once
// Test support: an analytic once-per-turn tachometer signal. The crank phase
// is the integral of a speed law (closed form per piece), the pulse times are
// where it passes whole turns (solved to 1e-12 s), and the signal is sampled
// onto the recording's grid: 1 while the crank is within the mark's angular
// width of a whole turn, else 0 (a 0/1 pickup), optionally with a pickup's
// analog faults added.

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace fourbar::testing {

/// Crank speed as a function of time: piecewise linear in time (run-ups,
/// coast-downs, stalls, steps as steep ramps), given by its corners.
struct SpeedLaw {
  std::vector<double> time_s, rev_per_s;  // corners, time increasing

  /// Turns since t = time_s[0] (exact: trapezoids).
  double turns(double t) const {
    double n = 0;
    for (std::size_t i = 0; i + 1 < time_s.size() && t > time_s[i]; ++i) {
      const double t1 = std::min(t, time_s[i + 1]), h = t1 - time_s[i];
      const double slope = (rev_per_s[i + 1] - rev_per_s[i]) / (time_s[i + 1] - time_s[i]);
      n += rev_per_s[i] * h + 0.5 * slope * h * h;
    }
    return n;
  }
  double end_s() const { return time_s.back(); }
};

/// Times at which the crank passes turn `phase0 + k` (k = 1, 2, …) in [t0, t1].
inline std::vector<double> pass_times(const SpeedLaw& law, double phase0_turns, double t0, double t1) {
  std::vector<double> times;
  const double n0 = law.turns(t0), n1 = law.turns(t1);
  for (double k = std::ceil(n0 - phase0_turns); k + phase0_turns <= n1; ++k) {
    const double target = k + phase0_turns;
    if (target < n0) continue;
    double lo = t0, hi = t1;  // turns(t) is non-decreasing: bisection
    for (int it = 0; it < 200 && hi - lo > 1e-12; ++it) {
      const double mid = 0.5 * (lo + hi);
      (law.turns(mid) < target ? lo : hi) = mid;
    }
    times.push_back(hi);
  }
  return times;
}

struct TachoSignal {
  std::vector<double> volts;        ///< one sample per 1/fs from t = 0
  std::vector<double> pulse_times;  ///< true leading edges (crank at a whole turn + phase0)
};

/// 0/1 samples (× amplitude) of a mark `width_turns` wide, the crank at turn
/// phase0 at t = 0 … sampled at fs over [0, duration].
/// `width_s` > 0: a fixed-duration pulse after each pass instead (a tachometer
/// with a monostable output).
inline TachoSignal tacho_signal(const SpeedLaw& law, double fs, double width_turns, double phase0_turns = 0.0,
                                double width_s = 0.0) {
  const double amplitude_V = 1.0;
  TachoSignal s;
  const auto n = static_cast<std::size_t>(std::floor(law.end_s() * fs)) + 1;
  s.volts.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double turns = law.turns(static_cast<double>(i) / fs) + phase0_turns;
    const double frac = turns - std::floor(turns);
    s.volts[i] = frac < width_turns ? amplitude_V : 0.0;
  }
  s.pulse_times = pass_times(law, -phase0_turns, 0.0, law.end_s());
  // A pass at t = 0 exactly is no edge (nothing before it).
  if (!s.pulse_times.empty() && s.pulse_times.front() <= 0.5 / fs) s.pulse_times.erase(s.pulse_times.begin());
  if (width_s > 0) {
    std::fill(s.volts.begin(), s.volts.end(), 0.0);
    for (double t : s.pulse_times)
      for (auto i = static_cast<std::size_t>(std::ceil(t * fs)); i < n && i < (t + width_s) * fs; ++i)
        s.volts[i] = amplitude_V;
  }
  return s;
}

/// A pickup's analog faults on a 0/1 signal (levels 0 and 1, × swing_V).
struct PickupFaults {
  double swing_V = 5;
  double overshoot = 0;     ///< ringing: second-order response with this overshoot (0.5: 50 %)
  double ring_hz = 2000;    ///< its natural frequency
  double drift_of_swing = 0;  ///< baseline ± half this × swing, a slow sine (1.5 cycles over the record)
  double snr_db = 0;        ///< white noise, swing²/σ² in dB (0: none)
  unsigned seed = 1;
};

inline std::vector<double> with_faults(const std::vector<double>& clean, double fs, const PickupFaults& f) {
  std::vector<double> x(clean.size());
  // Second-order low-pass step response, overshoot OS = exp(−πζ/√(1−ζ²)).
  const double lnos = std::log(std::max(f.overshoot, 1e-9));
  const double zeta = f.overshoot > 0 ? -lnos / std::sqrt(M_PI * M_PI + lnos * lnos) : 1.0;
  const double wn = 2 * M_PI * f.ring_hz;
  constexpr int kSub = 32;
  const double dt = 1 / (fs * kSub);
  double y = clean.empty() ? 0 : clean[0], v = 0;
  std::mt19937_64 rng(f.seed);
  std::normal_distribution<double> noise(0, f.snr_db > 0 ? std::pow(10.0, -f.snr_db / 20) : 0.0);
  const double duration = static_cast<double>(clean.size()) / fs;
  for (std::size_t i = 0; i < clean.size(); ++i) {
    if (f.overshoot > 0) {
      for (int k = 0; k < kSub; ++k) {  // semi-implicit Euler
        v += dt * (wn * wn * (clean[i] - y) - 2 * zeta * wn * v);
        y += dt * v;
      }
    } else {
      y = clean[i];
    }
    const double t = static_cast<double>(i) / fs;
    const double drift = 0.5 * f.drift_of_swing * std::sin(2 * M_PI * 1.5 * t / duration);
    x[i] = f.swing_V * (y + drift + (f.snr_db > 0 ? noise(rng) : 0.0));
  }
  return x;
}

}  // namespace fourbar::testing
