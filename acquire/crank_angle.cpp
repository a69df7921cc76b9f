#include "acquire/crank_angle.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>

#include <cassert>
#include <cmath>

#include "common/units.hpp"

namespace fourbar {

struct CrankAngleModel::Spline {
  boost::math::interpolators::cardinal_cubic_b_spline<double> t_of_turns;
};

CrankPoint RevolutionCurve::at_fraction(double u) const {
  const auto& b = t_of_u;
  const double t = b[0] + u * (b[1] + u * (b[2] + u * b[3]));
  const double dt = b[1] + u * (2 * b[2] + u * 3 * b[3]);  // dt/du, per turn
  const double ddt = 2 * b[2] + u * 6 * b[3];
  return {t0 + t, phase0_rad + units::kTwoPi * u, units::kTwoPi / dt, -units::kTwoPi * ddt / (dt * dt * dt)};
}

CrankAngleModel::CrankAngleModel(std::vector<double> pulse_times_s) : times_(std::move(pulse_times_s)) {
  assert(times_.size() >= 2);
  const std::size_t n = times_.size();
  if (n >= 3) {
    // End slopes by one-sided differences: fourth order from five pulses,
    // second order from three or four. (Boost 1.74 would estimate them
    // itself, but its right-end formula is the forward difference at x[n−4],
    // not the slope at x[n]; the angle then drifts by degrees over the last
    // revolutions of a segment whose speed varies.)
    const auto& t = times_;
    double left, right;
    if (n >= 5) {
      left = (-25 * t[0] + 48 * t[1] - 36 * t[2] + 16 * t[3] - 3 * t[4]) / 12;
      right = (25 * t[n - 1] - 48 * t[n - 2] + 36 * t[n - 3] - 16 * t[n - 4] + 3 * t[n - 5]) / 12;
    } else {
      left = (-3 * t[0] + 4 * t[1] - t[2]) / 2;
      right = (3 * t[n - 1] - 4 * t[n - 2] + t[n - 3]) / 2;
    }
    spline_ = std::make_unique<Spline>(Spline{{times_.data(), n, 0.0, 1.0, left, right}});
  }
}

CrankAngleModel::~CrankAngleModel() = default;
CrankAngleModel::CrankAngleModel(CrankAngleModel&&) noexcept = default;
CrankAngleModel& CrankAngleModel::operator=(CrankAngleModel&&) noexcept = default;

CrankPoint CrankAngleModel::at_turns(double turns) const {
  CrankPoint p;
  p.phase_rad = units::kTwoPi * turns;
  if (!spline_) {  // one revolution: constant speed
    const double h = times_[1] - times_[0];
    p.time_s = times_[0] + turns * h;
    p.speed_rad_s = units::kTwoPi / h;
    return p;
  }
  const auto& s = spline_->t_of_turns;
  // Exactly at a pulse the spline returns the pulse time up to rounding;
  // use the measured time itself so that revolutions start where they should.
  const double k = std::round(turns);
  p.time_s = std::abs(turns - k) < 1e-12 ? times_[static_cast<std::size_t>(k)] : s(turns);
  const double dt = s.prime(turns), ddt = s.double_prime(turns);
  p.speed_rad_s = units::kTwoPi / dt;
  p.accel_rad_s2 = -units::kTwoPi * ddt / (dt * dt * dt);
  return p;
}

RevolutionCurve CrankAngleModel::revolution(std::size_t k) const {
  const CrankPoint a = at_turns(static_cast<double>(k)), b = at_turns(static_cast<double>(k + 1));
  RevolutionCurve r;
  r.t0 = a.time_s;
  r.h = b.time_s - a.time_s;
  r.inv_h = 1.0 / r.h;
  r.phase0_rad = a.phase_rad;
  // Quintic Hermite: value, slope and curvature at both ends (in τ units).
  const double d = units::kTwoPi, d0 = a.speed_rad_s * r.h, d1 = b.speed_rad_s * r.h;
  const double s0 = a.accel_rad_s2 * r.h * r.h, s1 = b.accel_rad_s2 * r.h * r.h;
  r.c = {0.0,
         d0,
         s0 / 2,
         10 * d - 6 * d0 - 4 * d1 - (3 * s0 - s1) / 2,
         -15 * d + 8 * d0 + 7 * d1 + (3 * s0 - 2 * s1) / 2,
         6 * d - 3 * d0 - 3 * d1 - (s0 - s1) / 2};
  // The spline is a cubic in u on this interval: its Hermite form from the
  // end values and slopes (dt/du = 2π/ω) is exact.
  const double m0 = units::kTwoPi / a.speed_rad_s, m1 = units::kTwoPi / b.speed_rad_s;
  r.t_of_u = {0.0, m0, 3 * r.h - 2 * m0 - m1, -2 * r.h + m0 + m1};
  return r;
}

}  // namespace fourbar
