#pragma once
// A virtual tap-test recording: the free decay of a few modes after a hammer
// tap, with white noise at a given SNR (the initial RMS of the ringing over
// the noise RMS), a DC offset, and quiet before the tap. Known truth for
// identify_tap_modes and `fourbar tap`.

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace fourbar::testing {

struct TapModeTruth {
  double frequency_Hz = 0;  ///< undamped natural frequency
  double damping_ratio = 0;
  double amplitude = 1;
  double phase_rad = 0;
};

struct TapRecording {
  std::vector<double> samples;
  double sample_rate_hz = 0;
};

/// The modes' free decay `t` seconds after a strike (0 before it).
inline double ringing(const std::vector<TapModeTruth>& modes, double t) {
  double v = 0;
  if (t >= 0)
    for (const auto& m : modes) {
      const double w = 2 * std::numbers::pi * m.frequency_Hz;
      const double wd = w * std::sqrt(1 - m.damping_ratio * m.damping_ratio);
      v += m.amplitude * std::exp(-m.damping_ratio * w * t) * std::sin(wd * t + m.phase_rad);
    }
  return v;
}

inline TapRecording virtual_tap(const std::vector<TapModeTruth>& modes, double snr_db, unsigned seed,
                                double sample_rate_hz = 25600, double duration_s = 1.0, double tap_time_s = 0.1) {
  TapRecording r;
  r.sample_rate_hz = sample_rate_hz;
  const auto n = static_cast<std::size_t>(duration_s * sample_rate_hz);
  double power = 0;
  for (const auto& m : modes) power += m.amplitude * m.amplitude / 2;
  const double noise = std::sqrt(power) / std::pow(10.0, snr_db / 20);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0, noise);
  r.samples.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / sample_rate_hz - tap_time_s;
    r.samples[i] = 0.3 + ringing(modes, t) + gauss(rng);  // 0.3: the accelerometer's offset
  }
  return r;
}

/// A later strike of the hammer (a bounce, another tap): the modes' free
/// decay from `strike_time_s` on, added without noise.
inline void add_strike(TapRecording& r, const std::vector<TapModeTruth>& modes, double strike_time_s) {
  for (std::size_t i = 0; i < r.samples.size(); ++i)
    r.samples[i] += ringing(modes, static_cast<double>(i) / r.sample_rate_hz - strike_time_s);
}

/// The recording as CSV text with a time column (`time_s,accel_m_s2`).
inline std::string tap_csv(const TapRecording& r) {
  std::string text = "time_s,accel_m_s2\n";
  char line[64];
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    std::snprintf(line, sizeof line, "%.8f,%.9g\n", static_cast<double>(i) / r.sample_rate_hz, r.samples[i]);
    text += line;
  }
  return text;
}

}  // namespace fourbar::testing
