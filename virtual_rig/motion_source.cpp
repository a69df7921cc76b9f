#include "virtual_rig/motion_source.hpp"

#include <cmath>

#include "common/units.hpp"

namespace fourbar {

CrankState CrankDrive::at(double t) const {
  const double w0 = mean_speed_rad_s, e = fluctuation, T = fluctuation_period_s;
  const double arg = units::kTwoPi * t / T;
  CrankState s{start_angle_rad + w0 * t + e * w0 * T / units::kTwoPi * (1 - std::cos(arg)), w0 * (1 + e * std::sin(arg)),
               w0 * e * units::kTwoPi / T * std::cos(arg)};
  for (std::size_t i = 0; i < harmonics.size(); ++i) {
    const double h = static_cast<double>(i + 1), a = harmonics[i], x = h * w0 * t + h;
    s.angle_rad += a * (std::cos(h) - std::cos(x)) / h;
    s.speed_rad_s += w0 * a * std::sin(x);
    s.accel_rad_s2 += w0 * a * h * w0 * std::cos(x);
  }
  return s;
}

double CrankDrive::time_at_turned(double turned_rad) const {
  double t = turned_rad / mean_speed_rad_s;
  for (int i = 0; i < 50; ++i) {
    const CrankState s = at(t);
    const double step = (s.angle_rad - start_angle_rad - turned_rad) / s.speed_rad_s;
    t -= step;
    if (std::abs(step) < 1e-15 * std::max(1.0, std::abs(t))) break;
  }
  return t;
}

NominalMotionSource::NominalMotionSource(std::shared_ptr<const Rig> rig, CrankDrive drive)
    : rig_(std::move(rig)), drive_(drive) {}

LinkState NominalMotionSource::at(double time_s) const {
  NominalMotion m = solve_motion(*rig_, drive_.at(time_s));
  LinkState s;
  s.time_s = time_s;
  s.crank = m.crank;
  s.theta3_rad = m.pose.theta3_rad(), s.omega3_rad_s = m.omega3_rad_s, s.alpha3_rad_s2 = m.alpha3_rad_s2;
  s.theta4_rad = m.pose.theta4_rad(), s.omega4_rad_s = m.omega4_rad_s, s.alpha4_rad_s2 = m.alpha4_rad_s2;
  return s;
}

}  // namespace fourbar
