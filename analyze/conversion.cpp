#include "analyze/conversion.hpp"

#include <cassert>
#include <cmath>
#include <sstream>

#include "analyze/ac_coupling.hpp"
#include "common/error.hpp"

namespace fourbar {

double sensor_reading(const Rig& rig, const ResolvedMount& mount, const SensedLinkMotion& k) {
  const Vec2 u = k.u, n = u.perp();
  const double w2 = k.omega_rad_s * k.omega_rad_s;
  // a_P = a_J + r(α·n − ω²·u) + h(−α·u − ω²·n); specific force f = a_P + g·ŷ.
  const Vec2 a = k.joint_accel_m_s2 + mount.r_m * (k.alpha_rad_s2 * n - w2 * u) +
                 mount.h_m * (-k.alpha_rad_s2 * u - w2 * n);
  const Vec2 f = a + Vec2{0.0, rig.gravity_m_s2};
  return mount.sign * dot(f, mount.axis == SensorAxis::tangential ? n : u);
}

double angular_acceleration_from_tangential(const Rig& rig, const ResolvedMount& mount, const SensedLinkMotion& k,
                                            double reading_m_s2) {
  assert(mount.axis == SensorAxis::tangential);
  const Vec2 n = k.u.perp();
  // α = (s·m − a_J·n + h·ω² − g·cos θ)/r, with cos θ = ŷ·n.
  return (mount.sign * reading_m_s2 - dot(k.joint_accel_m_s2, n) + mount.h_m * k.omega_rad_s * k.omega_rad_s -
          rig.gravity_m_s2 * n.y) /
         mount.r_m;
}

double angular_speed_squared_from_normal(const Rig& rig, const ResolvedMount& mount, const SensedLinkMotion& k,
                                         double reading_m_s2, double link_alpha_rad_s2) {
  assert(mount.axis == SensorAxis::normal);
  // ω² = (a_J·u − h·α + g·sin θ − s·m)/r, with sin θ = ŷ·u.
  return (dot(k.joint_accel_m_s2, k.u) - mount.h_m * link_alpha_rad_s2 + rig.gravity_m_s2 * k.u.y -
          mount.sign * reading_m_s2) /
         mount.r_m;
}

namespace {

void check_lengths(const AccelerometerMount& mount, std::size_t track, std::size_t reading, std::size_t out) {
  if (reading != track || out != track) {
    std::ostringstream os;
    os << "channel '" << mount.channel << "': " << reading << " samples but the crank track has " << track
       << "; every channel needs one crank state per sample";
    throw InputError(os.str());
  }
}

ResolvedMount resolve_axis(const Rig& rig, const AccelerometerMount& mount, SensorAxis want) {
  const ResolvedMount r = resolve_mount(rig, mount);
  if (r.axis != want) {
    std::ostringstream os;
    os << "channel '" << mount.channel << "' is a " << to_string(r.axis) << " accelerometer; this conversion needs a "
       << to_string(want) << " one";
    throw InputError(os.str());
  }
  return r;
}

// The whole-channel functions, for a nominal motion given per sample by
// `motion(i)` (a stored track or a table read).
template <class MotionAt>
void tangential(const Rig& rig, const AccelerometerMount& mount, std::size_t n, MotionAt motion,
                std::span<const double> reading, std::span<double> alpha) {
  const ResolvedMount r = resolve_axis(rig, mount, SensorAxis::tangential);
  check_lengths(mount, n, reading.size(), alpha.size());
  for (std::size_t i = 0; i < n; ++i) alpha[i] = angular_acceleration_from_tangential(rig, r, motion(i), reading[i]);
}

template <class MotionAt>
void normal(const Rig& rig, const AccelerometerMount& mount, std::size_t n, MotionAt motion,
            std::span<const double> reading, std::span<const double> link_alpha, std::span<double> omega_sq) {
  const ResolvedMount r = resolve_axis(rig, mount, SensorAxis::normal);
  check_lengths(mount, n, reading.size(), omega_sq.size());
  if (r.h_m != 0 && link_alpha.size() != reading.size()) {
    std::ostringstream os;
    os << "channel '" << mount.channel << "': the sensor is offset " << r.h_m * 1e3
       << " mm from the link line, so its normal reading needs the link's angular acceleration per sample";
    throw InputError(os.str());
  }
  for (std::size_t i = 0; i < n; ++i)
    omega_sq[i] =
        angular_speed_squared_from_normal(rig, r, motion(i), reading[i], link_alpha.empty() ? 0.0 : link_alpha[i]);
}

template <class MotionAt>
void restore(const Rig& rig, const AccelerometerMount& mount, std::size_t n, MotionAt motion, double sample_rate_hz,
             std::span<const double> reading, std::span<double> restored) {
  const ResolvedMount r = resolve_mount(rig, mount);
  check_lengths(mount, n, reading.size(), restored.size());
  if (reading.empty()) return;
  if (r.high_pass_corner_hz == 0) {
    if (restored.data() != reading.data()) std::copy(reading.begin(), reading.end(), restored.begin());
    return;
  }
  // Model mean of the reading: its known part at the nominal link motion with
  // α replaced by the record's mean α (periodic motion: ≈ 0).
  const SensedLinkMotion first = motion(0), last = motion(n - 1);
  // Sample mean of α: Σα_i = ∫α dt·fs + (α_0 + α_{n−1})/2 (trapezoid rule),
  // with ∫α dt = ω_end − ω_start.
  const double mean_alpha =
      ((last.omega_rad_s - first.omega_rad_s) * sample_rate_hz + 0.5 * (first.alpha_rad_s2 + last.alpha_rad_s2)) / n;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    SensedLinkMotion k = motion(i);
    if (r.axis == SensorAxis::tangential) k.alpha_rad_s2 = mean_alpha;
    sum += sensor_reading(rig, r, k);
  }
  undo_sensor_high_pass(reading, sample_rate_hz, r.high_pass_corner_hz, sum / n, restored);
}

auto from_track(std::span<const SensedLinkMotion> nominal) {
  return [nominal](std::size_t i) { return nominal[i]; };
}

void check_table(const AccelerometerMount& mount, const LinkTable& table) {
  if (table.link() != mount.link)
    throw InputError("channel '" + mount.channel + "' is on the " + to_string(mount.link) + " but the table is the " +
                     to_string(table.link()) + "'s");
}

}  // namespace

void angular_acceleration_from_tangential(const Rig& rig, const AccelerometerMount& mount,
                                          std::span<const SensedLinkMotion> nominal, std::span<const double> reading,
                                          std::span<double> alpha) {
  tangential(rig, mount, nominal.size(), from_track(nominal), reading, alpha);
}

void angular_speed_squared_from_normal(const Rig& rig, const AccelerometerMount& mount,
                                       std::span<const SensedLinkMotion> nominal, std::span<const double> reading,
                                       std::span<const double> link_alpha, std::span<double> omega_sq) {
  normal(rig, mount, nominal.size(), from_track(nominal), reading, link_alpha, omega_sq);
}

void restore_dc_coupled_reading(const Rig& rig, const AccelerometerMount& mount,
                                std::span<const SensedLinkMotion> nominal, double sample_rate_hz,
                                std::span<const double> reading, std::span<double> restored) {
  restore(rig, mount, nominal.size(), from_track(nominal), sample_rate_hz, reading, restored);
}

void convert_reading(const Rig& rig, const AccelerometerMount& mount, const LinkTable& table, const CrankTrack& crank,
                     double fs, std::span<const double> reading, std::span<const double> link_alpha,
                     std::span<double> out) {
  check_table(mount, table);
  check_crank_track(crank);
  const ResolvedMount r = resolve_mount(rig, mount);
  const std::size_t n = crank.size();
  check_lengths(mount, n, reading.size(), out.size());
  const bool tangential = r.axis == SensorAxis::tangential;
  if (!tangential && r.h_m != 0 && link_alpha.size() != n) {
    std::ostringstream os;
    os << "channel '" << mount.channel << "': the sensor is offset " << r.h_m * 1e3
       << " mm from the link line, so its normal reading needs the link's angular acceleration per sample";
    throw InputError(os.str());
  }
  if (n == 0) return;
  // AC-coupled: the sensor's high-pass undone with a zero mean first; the
  // model's mean (restore_dc_coupled_reading) is summed in the same pass.
  const bool ac = r.high_pass_corner_hz > 0;
  if (ac) undo_sensor_high_pass(reading, fs, r.high_pass_corner_hz, 0.0, out);
  const std::span<const double> x = ac ? std::span<const double>(out) : reading;
  const double s = r.sign, h = r.h_m, inv_r = 1.0 / r.r_m, g = rig.gravity_m_s2;
  // The formulas of angular_acceleration_from_tangential and
  // angular_speed_squared_from_normal, with the reading's known part c
  // shared by the conversion and the model of the reading.
  double model_sum = 0;
  if (tangential) {
    //   α = (s·m − c)/r, c = a_J·n − h·ω² + g·cos θ;  model m = s·(c + r·ᾱ).
    for (std::size_t i = 0; i < n; ++i) {
      const LinkTable::Tangential t = table.tangential(crank.angle_rad[i]);
      const double w2 = crank.speed_rad_s[i], w2sq = w2 * w2, a2 = crank.accel_rad_s2[i];
      const double c = a2 * t.p_n - w2sq * (t.q_n + h * t.k * t.k) + g * t.cos_theta;
      model_sum += c;
      out[i] = (s * x[i] - c) * inv_r;
    }
    if (ac) {
      const SensedLinkMotion first = table.motion(crank.at(0)), last = table.motion(crank.at(n - 1));
      const double mean_alpha =
          ((last.omega_rad_s - first.omega_rad_s) * fs + 0.5 * (first.alpha_rad_s2 + last.alpha_rad_s2)) / n;
      model_sum = s * (model_sum + r.r_m * mean_alpha * n);
    }
  } else {
    //   ω² = (d − h·α − s·m)/r, d = a_J·u + g·sin θ;  model m = s·(d − r·ω² − h·α) at the nominal ω, α.
    for (std::size_t i = 0; i < n; ++i) {
      const LinkTable::Normal t = table.normal(crank.angle_rad[i]);
      const double w2 = crank.speed_rad_s[i], w2sq = w2 * w2, a2 = crank.accel_rad_s2[i];
      const double d = a2 * t.p_u - w2sq * t.q_u + g * t.sin_theta;
      if (ac) model_sum += s * (d - r.r_m * w2sq * t.k * t.k - h * (a2 * t.k + w2sq * t.k_prime));
      out[i] = (d - h * (link_alpha.empty() ? 0.0 : link_alpha[i]) - s * x[i]) * inv_r;
    }
  }
  if (!ac) return;
  // The restored reading's constant (the model's mean), through the
  // conversion's slope ±s/r.
  const double shift = (tangential ? s : -s) * (model_sum / n) * inv_r;
  for (double& v : out) v += shift;
}

void thesis_angular_acceleration(const Rig& rig, SensedLink link, int axis_sign, double crank_speed_rad_s,
                                 std::span<const double> crank_angle_rad, std::span<const double> reading,
                                 std::span<double> alpha) {
  assert(crank_angle_rad.size() == reading.size() && alpha.size() == reading.size());
  const double l2 = rig.crank.length_m, w2sq = crank_speed_rad_s * crank_speed_rad_s;
  for (std::size_t i = 0; i < reading.size(); ++i) {
    if (link == SensedLink::rocker) {
      alpha[i] = axis_sign * reading[i] / rig.rocker.length_m;  // thesis eq. 7.2.2-1
      continue;
    }
    const Pose p = solve_pose(rig, crank_angle_rad[i]);
    const double sin23 = cross(p.u3, p.u2);  // sin(θ2 − θ3)
    alpha[i] = (axis_sign * reading[i] + l2 * w2sq * sin23) / rig.coupler.length_m;  // thesis eq. 7.2.1-6
  }
}

}  // namespace fourbar
