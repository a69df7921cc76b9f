#include "analyze/conversion.hpp"

#include <cassert>
#include <cmath>
#include <sstream>

#include "analyze/ac_coupling.hpp"
#include "common/error.hpp"

namespace fourbar {

namespace {

LinkMotion link_part(const Rig& rig, SensedLink link, const NominalMotion& m) {
  LinkMotion out;
  if (link == SensedLink::coupler) {
    // Crank pin: a_A = l2(α2·n2 − ω2²·u2).
    const double l2 = rig.crank.length_m, w2 = m.crank.speed_rad_s;
    out.u = m.pose.u3;
    out.omega_rad_s = m.omega3_rad_s;
    out.alpha_rad_s2 = m.alpha3_rad_s2;
    out.joint_accel_m_s2 = l2 * (m.crank.accel_rad_s2 * m.pose.u2.perp() - w2 * w2 * m.pose.u2);
  } else {
    out.u = m.pose.u4;
    out.omega_rad_s = m.omega4_rad_s;
    out.alpha_rad_s2 = m.alpha4_rad_s2;
  }
  return out;
}

void check_track(const CrankTrack& crank) {
  const std::size_t n = crank.size();
  if (crank.speed_rad_s.size() != n || crank.accel_rad_s2.size() != n) {
    std::ostringstream os;
    os << "crank track: " << n << " angles, " << crank.speed_rad_s.size() << " speeds, " << crank.accel_rad_s2.size()
       << " accelerations; give one crank state per sample";
    throw InputError(os.str());
  }
}

}  // namespace

LinkMotion nominal_link_motion(const Rig& rig, SensedLink link, const CrankState& crank) {
  return link_part(rig, link, solve_motion(rig, crank));
}

NominalTracks nominal_link_tracks(const Rig& rig, const CrankTrack& crank) {
  check_track(crank);
  NominalTracks t;
  t.coupler.resize(crank.size());
  t.rocker.resize(crank.size());
  for (std::size_t i = 0; i < crank.size(); ++i) {
    const NominalMotion m = solve_motion(rig, {crank.angle_rad[i], crank.speed_rad_s[i], crank.accel_rad_s2[i]});
    t.coupler[i] = link_part(rig, SensedLink::coupler, m);
    t.rocker[i] = link_part(rig, SensedLink::rocker, m);
  }
  return t;
}

double sensor_reading(const Rig& rig, const ResolvedMount& mount, const LinkMotion& k) {
  const Vec2 u = k.u, n = u.perp();
  const double w2 = k.omega_rad_s * k.omega_rad_s;
  // a_P = a_J + r(α·n − ω²·u) + h(−α·u − ω²·n); specific force f = a_P + g·ŷ.
  const Vec2 a = k.joint_accel_m_s2 + mount.r_m * (k.alpha_rad_s2 * n - w2 * u) +
                 mount.h_m * (-k.alpha_rad_s2 * u - w2 * n);
  const Vec2 f = a + Vec2{0.0, rig.gravity_m_s2};
  return mount.sign * dot(f, mount.axis == SensorAxis::tangential ? n : u);
}

double angular_acceleration_from_tangential(const Rig& rig, const ResolvedMount& mount, const LinkMotion& k,
                                            double reading_m_s2) {
  assert(mount.axis == SensorAxis::tangential);
  const Vec2 n = k.u.perp();
  // α = (s·m − a_J·n + h·ω² − g·cos θ)/r, with cos θ = ŷ·n.
  return (mount.sign * reading_m_s2 - dot(k.joint_accel_m_s2, n) + mount.h_m * k.omega_rad_s * k.omega_rad_s -
          rig.gravity_m_s2 * n.y) /
         mount.r_m;
}

double angular_speed_squared_from_normal(const Rig& rig, const ResolvedMount& mount, const LinkMotion& k,
                                         double reading_m_s2, double link_alpha_rad_s2) {
  assert(mount.axis == SensorAxis::normal);
  // ω² = (a_J·u − h·α + g·sin θ − s·m)/r, with sin θ = ŷ·u.
  return (dot(k.joint_accel_m_s2, k.u) - mount.h_m * link_alpha_rad_s2 + rig.gravity_m_s2 * k.u.y -
          mount.sign * reading_m_s2) /
         mount.r_m;
}

std::vector<LinkMotion> nominal_link_track(const Rig& rig, SensedLink link, const CrankTrack& crank) {
  check_track(crank);
  const std::size_t n = crank.size();
  std::vector<LinkMotion> track(n);
  for (std::size_t i = 0; i < n; ++i)
    track[i] = nominal_link_motion(rig, link, {crank.angle_rad[i], crank.speed_rad_s[i], crank.accel_rad_s2[i]});
  return track;
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

}  // namespace

void angular_acceleration_from_tangential(const Rig& rig, const AccelerometerMount& mount,
                                          std::span<const LinkMotion> nominal, std::span<const double> reading,
                                          std::span<double> alpha) {
  const ResolvedMount r = resolve_axis(rig, mount, SensorAxis::tangential);
  check_lengths(mount, nominal.size(), reading.size(), alpha.size());
  for (std::size_t i = 0; i < reading.size(); ++i)
    alpha[i] = angular_acceleration_from_tangential(rig, r, nominal[i], reading[i]);
}

void angular_speed_squared_from_normal(const Rig& rig, const AccelerometerMount& mount,
                                       std::span<const LinkMotion> nominal, std::span<const double> reading,
                                       std::span<const double> link_alpha, std::span<double> omega_sq) {
  const ResolvedMount r = resolve_axis(rig, mount, SensorAxis::normal);
  check_lengths(mount, nominal.size(), reading.size(), omega_sq.size());
  if (r.h_m != 0 && link_alpha.size() != reading.size()) {
    std::ostringstream os;
    os << "channel '" << mount.channel << "': the sensor is offset " << r.h_m * 1e3
       << " mm from the link line, so its normal reading needs the link's angular acceleration per sample";
    throw InputError(os.str());
  }
  for (std::size_t i = 0; i < reading.size(); ++i)
    omega_sq[i] = angular_speed_squared_from_normal(rig, r, nominal[i], reading[i],
                                                    link_alpha.empty() ? 0.0 : link_alpha[i]);
}

void restore_dc_coupled_reading(const Rig& rig, const AccelerometerMount& mount, std::span<const LinkMotion> nominal,
                                double sample_rate_hz, std::span<const double> reading, std::span<double> restored) {
  const ResolvedMount r = resolve_mount(rig, mount);
  check_lengths(mount, nominal.size(), reading.size(), restored.size());
  if (reading.empty()) return;
  if (r.high_pass_corner_hz == 0) {
    std::copy(reading.begin(), reading.end(), restored.begin());
    return;
  }
  // Model mean of the reading: its known part at the nominal link motion with
  // α replaced by the record's mean α (periodic motion: ≈ 0).
  const std::size_t n = reading.size();
  const LinkMotion& first = nominal.front();
  const LinkMotion& last = nominal.back();
  // Sample mean of α: Σα_i = ∫α dt·fs + (α_0 + α_{n−1})/2 (trapezoid rule),
  // with ∫α dt = ω_end − ω_start.
  const double mean_alpha =
      ((last.omega_rad_s - first.omega_rad_s) * sample_rate_hz + 0.5 * (first.alpha_rad_s2 + last.alpha_rad_s2)) / n;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    LinkMotion k = nominal[i];
    if (r.axis == SensorAxis::tangential) k.alpha_rad_s2 = mean_alpha;
    sum += sensor_reading(rig, r, k);
  }
  undo_sensor_high_pass(reading, sample_rate_hz, r.high_pass_corner_hz, sum / n, restored);
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
