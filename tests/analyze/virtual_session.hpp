#pragma once
// Test and bench support: a recording of the thesis rig made by the virtual
// rig (virtual_rig/), and the truth on analyze's crank-angle grid, from
// the same crank drive and nominal mechanism that made the recording.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "acquire/virtual_recording.hpp"
#include "analyze/pipeline.hpp"

namespace fourbar::testing {

/// The sensors of the analyze tests: on the coupler–rocker bearing housing,
/// 20 mm inboard of the joint and off the link line; the coupler's
/// tangential and normal sensors AC-coupled (piezo, 0.5 Hz), the rocker's
/// mounted on the other side of its link and pointing the other way.
inline void housing_sensors(VirtualSetup& v) {
  v.spec.sensors.clear();
  ChannelSpec& ct = v.add_sensor("coupler_t", ChannelRole::coupler_tangential, 289, 1);
  ct.offset_m = 0.012, ct.ac_coupled = true, ct.highpass_hz = 0.5;
  ChannelSpec& cn = v.add_sensor("coupler_n", ChannelRole::coupler_normal, 289, -1);
  cn.offset_m = 0.012;
  ChannelSpec& rt = v.add_sensor("rocker_t", ChannelRole::rocker_tangential, 292, -1);
  rt.offset_m = -0.010;
}

/// The lab's conditions of the issue: 30 dB SNR white noise, 60 Hz mains hum
/// (with a third harmonic) at about 10 % of the coupler channel's RMS, the
/// crank speed held to ±1 %.
inline void noisy_lab(VirtualSetup& v) {
  v.spec.noise_snr_db = 30;
  v.spec.hum_frequency_hz = 60;
  v.spec.hum_V = 0.09;
  v.spec.hum_harmonics = {1.0, 0.0, 0.33};
  v.spec.speed_fluctuation = 0.01;
  v.spec.speed_fluctuation_period_s = 4.0;
}

/// True α and ω of both links at every grid point of the analysed
/// revolutions (acquire's revolution r starts at the r-th pulse written).
struct GridTruth {
  std::vector<double> alpha3, omega3, alpha4, omega4;  // revolutions × N
};
inline GridTruth grid_truth(const VirtualSetup& v, const VirtualRigResult& written, const RecordingAnalysis& a,
                            const std::vector<std::size_t>& revolutions) {
  const CrankDrive drive = v.drive();
  const NominalMotionSource motion(v.scene.rig, drive);
  const double dir = drive.mean_speed_rad_s > 0 ? 1.0 : -1.0;
  const double base = std::fmod(
      std::fmod(dir * (v.spec.pulse.angle_rad - drive.start_angle_rad), units::kTwoPi) + units::kTwoPi, units::kTwoPi);
  // The first pulse acquire kept is the first one written.
  const double first = a.acquisition.pulses.segments.front().front().time_s;
  if (std::abs(first - written.pulse_times_s.front()) > 1e-4)
    std::printf("  warning: acquire's first pulse %.6f s is not the first written %.6f s\n", first,
                written.pulse_times_s.front());
  GridTruth t;
  const std::size_t N = a.grid_points_per_rev;
  for (std::size_t r : revolutions)
    for (std::size_t k = 0; k < N; ++k) {
      const double turned = base + units::kTwoPi * (static_cast<double>(r) + static_cast<double>(k) / N);
      const LinkState s = motion.at(drive.time_at_turned(dir * turned));
      t.alpha3.push_back(s.alpha3_rad_s2), t.omega3.push_back(s.omega3_rad_s);
      t.alpha4.push_back(s.alpha4_rad_s2), t.omega4.push_back(s.omega4_rad_s);
    }
  return t;
}

/// Mean over the revolutions (rows of N) per grid angle.
inline std::vector<double> row_mean(const std::vector<double>& rows, std::size_t N) {
  std::vector<double> m(N, 0.0);
  const std::size_t revs = rows.size() / N;
  for (std::size_t i = 0; i < rows.size(); ++i) m[i % N] += rows[i] / static_cast<double>(revs);
  return m;
}

/// RMS of (estimate − truth) over RMS of truth.
inline double rel_rms_error(const std::vector<double>& est, const std::vector<double>& truth) {
  double e = 0, t = 0;
  for (std::size_t k = 0; k < est.size(); ++k) {
    e += (est[k] - truth[k]) * (est[k] - truth[k]);
    t += truth[k] * truth[k];
  }
  return std::sqrt(e / t);
}

}  // namespace fourbar::testing
