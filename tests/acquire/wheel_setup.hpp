#pragma once
// Test support: virtual recordings with a tooth wheel or an encoder on the
// crank, and a crank whose speed changes within the turn — the lab case of a
// loaded four-bar: 1 % slow drift (period ten turns), 0.5 % once-per-turn
// and 0.3 % twice-per-turn speed change, 30 dB SNR on every channel.

#include <string>
#include <vector>

#include "acquire/revolution.hpp"
#include "acquire/virtual_recording.hpp"

namespace fourbar::testing {

enum class WheelKind { teeth_with_index, missing_teeth, encoder };

inline void in_turn_speed_change(VirtualSetup& v) {
  v.spec.speed_fluctuation = 0.01;
  v.spec.speed_harmonics = {0.005, 0.003};
  v.spec.noise_snr_db = 30;
  // 30 dB below the RMS of a 0/5 V square wave about its mean (2.5 V).
  v.spec.pulse.noise_V = 2.5 / 31.62;
}

/// 60 teeth + index, a 60-2 wheel, or a 1024-line encoder (sampled at
/// 409.6 kHz: at 25.6 kHz its quarter lines at 350 rpm would be one sample).
inline void fit_wheel(VirtualSetup& v, WheelKind kind) {
  WheelSpec& w = v.spec.wheel;
  switch (kind) {
    case WheelKind::teeth_with_index: w.teeth = 60, w.index = true; break;
    case WheelKind::missing_teeth: w.teeth = 60, w.missing_teeth = 2; break;
    case WheelKind::encoder:
      w.encoder_lines = 1024, w.index = true;
      v.spec.sample_rate_hz = 409600;
      v.spec.pulse.rise_s = 2.0 / v.spec.sample_rate_hz;
      break;
  }
}

/// Keeps the crank motion of every sample acquire delivers.
struct Crank : AcquisitionSink {
  std::vector<double> time, crank, omega, alpha;
  void on_samples(const SampleBlock& b) override {
    time.insert(time.end(), b.time_s.begin(), b.time_s.end());
    crank.insert(crank.end(), b.crank_rad.begin(), b.crank_rad.end());
    omega.insert(omega.end(), b.omega2_rad_s.begin(), b.omega2_rad_s.end());
    alpha.insert(alpha.end(), b.alpha2_rad_s2.begin(), b.alpha2_rad_s2.end());
  }
};

inline const char* wheel_name(WheelKind kind) {
  switch (kind) {
    case WheelKind::teeth_with_index: return "60 teeth + index";
    case WheelKind::missing_teeth: return "60-2 wheel";
    case WheelKind::encoder: return "1024-line encoder + Z";
  }
  return "";
}

}  // namespace fourbar::testing
