#pragma once
// A record for the analyze tests and benches that work below acquire (plain
// samples with their crank state, no file): the virtual rig's crank drive
// (slow ±1 % speed wander by default) and nominal motion, its sensor model
// (virtual_rig/sensor_signal.hpp: specific force at the mounting point,
// a formulation independent of analyze's conversion) times the axis sign,
// an AC-coupled sensor as a first-order high-pass in steady state, white
// noise at a given SNR and mains hum. Seeded. End-to-end tests go through
// the virtual rig's recording files and acquire instead (virtual_session.hpp).

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "analyze/ac_coupling.hpp"
#include "analyze/conversion.hpp"
#include "analyze/filter_design.hpp"
#include "common/units.hpp"
#include "virtual_rig/motion_source.hpp"
#include "virtual_rig/sensor_signal.hpp"

namespace fourbar::testing {

struct SyntheticRig {
  Rig rig = thesis_rig();
  double speed_rpm = 350;
  double wobble = 0.01;               ///< crank speed ω0·(1 + wobble·sin(2πt/T_w))
  double wobble_period_revs = 17.3;   ///< T_w in mean revolutions
  double sample_rate_hz = 25600;
  double duration_s = 1;
  double start_angle_rad = 0.3;       ///< crank angle at t = 0
  double snr_db = 30;                 ///< channel RMS over white-noise RMS
  double hum_rms_fraction = 0.1;      ///< mains hum RMS over channel RMS (60 Hz, plus 1/3 of it at 180 Hz)
  double mains_hz = 60;
  double preroll_s = 20;              ///< lets the sensor high-pass settle
  unsigned seed = 1;

  double mean_speed_rad_s() const { return units::rpm_to_rad_s(speed_rpm); }
  double wobble_period_s() const { return wobble_period_revs * units::kTwoPi / mean_speed_rad_s(); }
  CrankDrive drive() const { return {start_angle_rad, mean_speed_rad_s(), wobble, wobble_period_s()}; }
  NominalMotionSource motion() const { return {std::make_shared<const Rig>(rig), drive()}; }
  CrankState crank_at(double t) const { return drive().at(t); }
  /// The time at which the crank reaches `angle`.
  double time_at(double angle) const { return drive().time_at_turned(angle - start_angle_rad); }
};

struct SyntheticChannel {
  AccelerometerMount mount;
  std::vector<double> clean;     ///< DC-coupled reading, no noise
  std::vector<double> recorded;  ///< through the sensor's high-pass, plus noise and hum
};

struct SyntheticRecording {
  std::vector<double> angle, speed, accel;  ///< per sample
  std::vector<SyntheticChannel> channels;
  CrankTrack crank() const { return {angle, speed, accel}; }
};

inline SyntheticRecording make_recording(const SyntheticRig& s, const std::vector<AccelerometerMount>& mounts) {
  const double fs = s.sample_rate_hz;
  const auto pre = static_cast<std::size_t>(s.preroll_s * fs);
  const auto n = static_cast<std::size_t>(s.duration_s * fs);
  const NominalMotionSource motion = s.motion();
  SyntheticRecording rec;
  rec.angle.resize(n), rec.speed.resize(n), rec.accel.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CrankState c = s.crank_at(i / fs);
    rec.angle[i] = c.angle_rad, rec.speed[i] = c.speed_rad_s, rec.accel[i] = c.accel_rad_s2;
  }
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> phase(0.0, units::kTwoPi);
  for (const AccelerometerMount& mount : mounts) {
    const ResolvedMount m = resolve_mount(s.rig, mount);
    const ChannelRole role = m.link == SensedLink::coupler
                                 ? (m.axis == SensorAxis::tangential ? ChannelRole::coupler_tangential
                                                                     : ChannelRole::coupler_normal)
                                 : (m.axis == SensorAxis::tangential ? ChannelRole::rocker_tangential
                                                                     : ChannelRole::rocker_normal);
    std::vector<double> x(pre + n), y(pre + n);
    for (std::size_t i = 0; i < pre + n; ++i) {
      const double t = (static_cast<double>(i) - static_cast<double>(pre)) / fs;
      x[i] = m.sign * specific_force(s.rig, motion.at(t), role, m.r_m, m.h_m);
    }
    if (m.high_pass_corner_hz > 0) apply_sensor_high_pass(x, fs, m.high_pass_corner_hz, 0.0, y);
    else y = x;
    SyntheticChannel ch;
    ch.mount = mount;
    ch.clean.assign(x.begin() + pre, x.end());
    ch.recorded.assign(y.begin() + pre, y.end());
    double ms = 0;
    for (double v : ch.recorded) ms += v * v;
    const double rms = std::sqrt(ms / n);
    const double sigma = rms * std::pow(10.0, -s.snr_db / 20.0);
    // Hum RMS: the 60 Hz tone and a third of it at 180 Hz.
    const double a1 = s.hum_rms_fraction * rms * std::sqrt(2.0) / std::sqrt(1.0 + 1.0 / 9.0), a3 = a1 / 3.0;
    const double p1 = phase(rng), p3 = phase(rng);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = i / fs;
      ch.recorded[i] += sigma * gauss(rng) + a1 * std::sin(units::kTwoPi * s.mains_hz * t + p1) +
                        a3 * std::sin(units::kTwoPi * 3 * s.mains_hz * t + p3);
    }
    rec.channels.push_back(std::move(ch));
  }
  return rec;
}

/// The sensors of the tests and benches: on the coupler–rocker bearing
/// housing, 20 mm inboard of the joint and 12 mm off the link line, AC-coupled
/// at 0.2 Hz: coupler tangential and normal, rocker tangential.
struct HousingMounts {
  AccelerometerMount coupler_t, coupler_n, rocker_t;
};
inline HousingMounts housing_mounts() {
  HousingMounts m;
  m.coupler_t.channel = "coupler_t";
  m.coupler_t.distance_m = 0.020;
  m.coupler_t.from = MeasuredFrom::far_joint;
  m.coupler_t.offset_m = 0.012;
  m.coupler_t.high_pass_corner_hz = 0.2;
  m.coupler_n = m.coupler_t;
  m.coupler_n.channel = "coupler_n";
  m.coupler_n.axis = SensorAxis::normal;
  m.rocker_t = m.coupler_t;
  m.rocker_t.channel = "rocker_t";
  m.rocker_t.link = SensedLink::rocker;
  return m;
}

/// The filter of the tests and benches at 350 rpm: band-pass from half the
/// crank frequency to 300 Hz, 60 Hz comb with 1 Hz notches, Kaiser β = 8,
/// 0.8 Hz transition.
inline FilterSpec band_pass_with_mains_comb() {
  return {BandType::bandpass, 2.9, 300, 60, 1.0, {WindowType::kaiser, 8.0}, 0.8};
}

/// True α and ω of `link` at crank angle `angle` of the synthetic motion.
struct LinkTruth {
  double alpha_rad_s2, omega_rad_s;
};
inline LinkTruth truth_at_angle(const SyntheticRig& s, SensedLink link, double angle) {
  const LinkState st = s.motion().at(s.time_at(angle));
  return link == SensedLink::coupler ? LinkTruth{st.alpha3_rad_s2, st.omega3_rad_s}
                                     : LinkTruth{st.alpha4_rad_s2, st.omega4_rad_s};
}

}  // namespace fourbar::testing
