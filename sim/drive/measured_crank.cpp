#include "sim/drive/measured_crank.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

// fpclassify first: Boost 1.74's pchip.hpp calls isnan unqualified.
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

/// ∫₀^s of the cubic Hermite basis with values y0, y1 and slopes m0, m1 on a
/// piece of length h, s ∈ [0, 1] the fraction of the piece: the angle gained.
double hermite_integral(double s, double h, double y0, double y1, double m0, double m1) {
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
  return h * (y0 * (0.5 * s4 - s3 + s) + h * m0 * (0.25 * s4 - 2.0 * s3 / 3.0 + 0.5 * s2) + y1 * (-0.5 * s4 + s3) +
              h * m1 * (0.25 * s4 - s3 / 3.0));
}

}  // namespace

MeasuredSpeedCrank::MeasuredSpeedCrank(double start_angle_rad, std::vector<double> times,
                                       std::vector<double> speeds) {
  if (times.size() != speeds.size())
    throw InputError("measured crank speed: " + std::to_string(times.size()) + " times but " +
                     std::to_string(speeds.size()) + " speeds; give one speed per time");
  if (times.size() < 2) throw InputError("measured crank speed: needs at least 2 samples; use a constant speed");
  direction_ = speeds[0] > 0 ? 1.0 : -1.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string where = "measured crank speed sample " + std::to_string(i);
    if (!std::isfinite(times[i]) || !std::isfinite(speeds[i]))
      throw InputError(where + ": time or speed is not finite; remove or repair the sample");
    if (!(speeds[i] * direction_ > 0))
      throw InputError(where + ": speed " + std::to_string(speeds[i]) +
                       " rad/s is zero or reverses the crank; the crank must keep turning one way");
    if (i > 0 && !(times[i] > times[i - 1]))
      throw InputError(where + ": time " + std::to_string(times[i]) + " s does not follow " +
                       std::to_string(times[i - 1]) + " s; sort the samples by time, without repeats");
  }
  // PCHIP needs four points: densify short tables linearly (keeps the shape).
  while (times.size() < 4) {
    std::vector<double> t2, w2;
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
      t2.insert(t2.end(), {times[i], 0.5 * (times[i] + times[i + 1])});
      w2.insert(w2.end(), {speeds[i], 0.5 * (speeds[i] + speeds[i + 1])});
    }
    t2.push_back(times.back());
    w2.push_back(speeds.back());
    times = std::move(t2);
    speeds = std::move(w2);
  }
  t_ = times;
  w_ = speeds;
  const boost::math::interpolators::pchip<std::vector<double>> spline(std::move(times), std::move(speeds), 0.0, 0.0);
  slope_.resize(t_.size());
  for (std::size_t k = 0; k < t_.size(); ++k) slope_[k] = spline.prime(t_[k]);
  // Angles at the knots, then shifted so that θ2(0) = start angle.
  // The reduced angles are accumulated reduced, so they keep ~1e-15 rad per knot.
  theta_.assign(t_.size(), 0.0);
  phase_.assign(t_.size(), 0.0);
  for (std::size_t k = 0; k + 1 < t_.size(); ++k) {
    const double gain = angle_in_piece(k, t_[k + 1] - t_[k]);
    theta_[k + 1] = theta_[k] + gain;
    phase_[k + 1] = reduce_angle(phase_[k] + gain);
  }
  const std::size_t k0 = piece(0.0);
  const double gain0 = angle_in_piece(k0, 0.0 - t_[k0]);
  const double offset = start_angle_rad - (theta_[k0] + gain0);
  const double phase_offset = start_angle_rad - (phase_[k0] + gain0);
  for (double& th : theta_) th += offset;
  for (double& ph : phase_) ph = reduce_angle(ph, phase_offset);
}

MeasuredSpeedCrank MeasuredSpeedCrank::from_revolution_speeds(double start_angle_rad,
                                                              const std::vector<double>& speeds) {
  std::vector<double> times;
  double t = 0;
  for (std::size_t k = 0; k < speeds.size(); ++k) {
    if (!std::isfinite(speeds[k]) || speeds[k] == 0)
      throw InputError("measured crank speed of revolution " + std::to_string(k) +
                       " is zero or not finite; repair or drop that revolution");
    const double period = units::kTwoPi / std::abs(speeds[k]);
    times.push_back(t + 0.5 * period);
    t += period;
  }
  return MeasuredSpeedCrank(start_angle_rad, std::move(times), speeds);
}

std::size_t MeasuredSpeedCrank::piece(double t) const {
  // Index of the knot at or before t; 0 before the table, last knot after it.
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return it == t_.begin() ? 0 : static_cast<std::size_t>(it - t_.begin()) - 1;
}

double MeasuredSpeedCrank::angle_in_piece(std::size_t k, double dt) const {
  if ((k == 0 && dt < 0) || k + 1 == t_.size()) return w_[k] * dt;  // constant outside the table
  const double h = t_[k + 1] - t_[k];
  return hermite_integral(dt / h, h, w_[k], w_[k + 1], slope_[k], slope_[k + 1]);
}

CrankState MeasuredSpeedCrank::at(double t) const {
  const std::size_t k = piece(t);
  return state_in_piece(k, t - t_[k], theta_[k]);
}

CrankState MeasuredSpeedCrank::at_local(double origin, double tau) const {
  const std::size_t k = piece(origin + tau);
  return state_in_piece(k, (origin - t_[k]) + tau, phase_[k]);
}

CrankState MeasuredSpeedCrank::state_in_piece(std::size_t k, double dt, double knot_angle) const {
  CrankState c;
  c.angle_rad = knot_angle + angle_in_piece(k, dt);
  if ((k == 0 && dt < 0) || k + 1 == t_.size()) {
    c.speed_rad_s = w_[k];
    c.accel_rad_s2 = 0;
    return c;
  }
  // Cubic Hermite value and derivative on the piece.
  const double h = t_[k + 1] - t_[k], s = dt / h, s2 = s * s, s3 = s2 * s;
  const double y0 = w_[k], y1 = w_[k + 1], m0 = slope_[k], m1 = slope_[k + 1];
  c.speed_rad_s = y0 * (2 * s3 - 3 * s2 + 1) + h * m0 * (s3 - 2 * s2 + s) + y1 * (-2 * s3 + 3 * s2) + h * m1 * (s3 - s2);
  c.accel_rad_s2 = (y0 * (6 * s2 - 6 * s) + y1 * (6 * s - 6 * s2)) / h + m0 * (3 * s2 - 4 * s + 1) + m1 * (3 * s2 - 2 * s);
  return c;
}

double MeasuredSpeedCrank::time_at_angle(double angle) const {
  // θ2 is monotone: find the piece by the knot angles, then the root in it.
  const double a = angle * direction_;
  std::size_t k = 0;
  if (a <= theta_.front() * direction_) {
    return t_.front() + (angle - theta_.front()) / w_.front();
  }
  if (a >= theta_.back() * direction_) return t_.back() + (angle - theta_.back()) / w_.back();
  const auto it = std::upper_bound(theta_.begin(), theta_.end(), a,
                                   [this](double x, double th) { return x < th * direction_; });
  k = static_cast<std::size_t>(it - theta_.begin()) - 1;
  auto f = [&](double t) { return theta_[k] + angle_in_piece(k, t - t_[k]) - angle; };
  double lo = t_[k], hi = t_[k + 1];
  const double flo = f(lo), fhi = f(hi);
  if (flo == 0) return lo;
  if (fhi == 0) return hi;
  std::uintmax_t iters = 100;
  const auto r = boost::math::tools::toms748_solve(
      f, lo, hi, flo, fhi, [](double x, double y) { return std::abs(y - x) <= 4e-16 * std::max(1.0, std::abs(x)); },
      iters);
  return 0.5 * (r.first + r.second);
}

}  // namespace fourbar
