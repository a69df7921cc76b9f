#include "analyze/unseen_speed_change.hpp"

#include <algorithm>
#include <cmath>

#include "analyze/conversion.hpp"
#include "analyze/link_motion.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

/// The relative speed change and its derivative along the crank angle.
struct Profile {
  std::span<const SpeedHarmonic> harmonics;
  double rel(double theta) const {
    double r = 0;
    for (const SpeedHarmonic& h : harmonics) r += h.amplitude * std::sin(h.order * theta + h.phase_rad);
    return r;
  }
  double rel_slope(double theta) const {
    double r = 0;
    for (const SpeedHarmonic& h : harmonics) r += h.amplitude * h.order * std::cos(h.order * theta + h.phase_rad);
    return r;
  }
};

/// Fine steps of the true-time table per grid step: cubic Hermite between
/// them (exact slopes) keeps the angle error far below 1e-9 rad.
constexpr std::size_t kTableStepsPerPoint = 8;

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : std::sqrt(s / static_cast<double>(v.size()));
}

/// v minus its least-squares line over the index.
void detrend(std::vector<double>& v) {
  const double n = static_cast<double>(v.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double x = static_cast<double>(i);
    sx += x, sy += v[i], sxx += x * x, sxy += x * v[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), icpt = (sy - slope * sx) / n;
  for (std::size_t i = 0; i < v.size(); ++i) v[i] -= icpt + slope * static_cast<double>(i);
}

}  // namespace

UnseenSpeedError unseen_speed_error(const Rig& rig, const AccelerometerMount& mount, double mean_speed_rad_s,
                                    double pulse_angle_rad, std::span<const SpeedHarmonic> harmonics,
                                    std::size_t points) {
  const Profile p{harmonics};
  const double dir = mean_speed_rad_s < 0 ? -1.0 : 1.0, w = std::abs(mean_speed_rad_s);
  const ResolvedMount rm = resolve_mount(rig, mount);
  // True time t(s) of the turned angle s from the pulse, s ∈ [0, 2π]: Simpson
  // per fine step of ∫ ds / (w·(1 + rel)).
  const std::size_t M = points * kTableStepsPerPoint;
  const double ds = units::kTwoPi / static_cast<double>(M);
  auto speed_at = [&](double s) { return w * (1 + p.rel(pulse_angle_rad + dir * s)); };  // |ω2| at turned s
  std::vector<double> t(M + 1, 0.0);
  for (std::size_t j = 0; j < M; ++j) {
    const double s = static_cast<double>(j) * ds;
    t[j + 1] = t[j] + ds / 6 * (1 / speed_at(s) + 4 / speed_at(s + ds / 2) + 1 / speed_at(s + ds));
  }
  const double T = t[M];
  const double assumed_speed = dir * units::kTwoPi / T;  // what the pulses give
  // Turned angle at true time `time` (cubic Hermite on the table, slopes ds/dt = speed).
  auto turned_at = [&](double time) {
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    const std::size_t j = std::min<std::size_t>(M - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - t.begin() - 1)));
    const double h = t[j + 1] - t[j], u = (time - t[j]) / h, s0 = static_cast<double>(j) * ds, s1 = s0 + ds;
    const double m0 = speed_at(s0) * h, m1 = speed_at(s1) * h;
    const double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * s0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * s1 + (u3 - u2) * m1;
  };
  auto true_crank = [&](double theta) {
    const double r = p.rel(theta), speed = dir * w * (1 + r);
    return CrankState{theta, speed, w * w * (1 + r) * p.rel_slope(theta)};  // α2 = ω2·dω2/dθ2
  };
  std::vector<double> alpha_conv(points), alpha_err(points), alpha_true(points), omega_err(points), omega_true(points);
  const double dt = T / static_cast<double>(points);
  for (std::size_t i = 0; i < points; ++i) {
    const double s_assumed = units::kTwoPi * static_cast<double>(i) / static_cast<double>(points);
    const double theta_assumed = pulse_angle_rad + dir * s_assumed;
    const double theta_sample = pulse_angle_rad + dir * turned_at(T * s_assumed / units::kTwoPi);
    const double reading = sensor_reading(rig, rm, nominal_link_motion(rig, mount.link, true_crank(theta_sample)));
    const SensedLinkMotion assumed = nominal_link_motion(rig, mount.link, {theta_assumed, assumed_speed, 0.0});
    alpha_conv[i] = angular_acceleration_from_tangential(rig, rm, assumed, reading);
    const SensedLinkMotion truth = nominal_link_motion(rig, mount.link, true_crank(theta_assumed));
    alpha_true[i] = truth.alpha_rad_s2;
    alpha_err[i] = alpha_conv[i] - truth.alpha_rad_s2;
    omega_true[i] = truth.omega_rad_s;
  }
  // ω: the converted α integrated over the assumed (uniform) time, trapezoid;
  // the integration constant and any drift are removed by the detrend below.
  double omega_conv = 0;
  for (std::size_t i = 0; i < points; ++i) {
    omega_err[i] = omega_conv - omega_true[i];
    if (i + 1 < points) omega_conv += 0.5 * (alpha_conv[i] + alpha_conv[i + 1]) * dt;
  }
  detrend(omega_err);
  const double mean_omega = [&] {
    double s = 0;
    for (double v : omega_true) s += v;
    return s / static_cast<double>(points);
  }();
  for (double& v : omega_true) v -= mean_omega;
  return {rms(alpha_err) / rms(alpha_true), rms(omega_err) / rms(omega_true)};
}

UnseenSpeedSensitivity unseen_speed_sensitivity(const Rig& rig, const AccelerometerMount& mount,
                                                double mean_speed_rad_s, double pulse_angle_rad, double amplitude) {
  UnseenSpeedSensitivity s;
  s.amplitude = amplitude;
  constexpr int kPhases = 24;
  for (int order : {1, 2}) {
    UnseenSpeedError& worst = order == 1 ? s.once_per_turn : s.twice_per_turn;
    for (int k = 0; k < kPhases; ++k) {
      const SpeedHarmonic h{order, amplitude, units::kTwoPi * k / kPhases};
      const UnseenSpeedError e = unseen_speed_error(rig, mount, mean_speed_rad_s, pulse_angle_rad, {&h, 1}, 360);
      worst.alpha_rel_rms = std::max(worst.alpha_rel_rms, e.alpha_rel_rms);
      worst.omega_rel_rms = std::max(worst.omega_rel_rms, e.omega_rel_rms);
    }
  }
  return s;
}

}  // namespace fourbar
