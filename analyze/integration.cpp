#include "analyze/integration.hpp"

#include <cassert>
#include <cmath>
#include <numeric>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {

void cumulative_trapezoid(std::span<const double> y, double step, double initial, std::span<double> out) {
  assert(out.size() == y.size());
  if (y.empty()) return;
  double acc = initial, prev = y[0];
  out[0] = initial;
  for (std::size_t i = 1; i < y.size(); ++i) {
    const double cur = y[i];
    acc += 0.5 * step * (prev + cur);
    prev = cur;
    out[i] = acc;
  }
}

int link_turns_per_crank_turn(const Rig& rig, SensedLink link) {
  constexpr int kSteps = 720;
  double total = 0, prev = 0;
  for (int i = 0; i <= kSteps; ++i) {
    const Pose p = solve_pose(rig, units::kTwoPi * i / kSteps);
    const double a = link == SensedLink::coupler ? p.theta3_rad() : p.theta4_rad();
    if (i > 0) total += std::remainder(a - prev, units::kTwoPi);
    prev = a;
  }
  return static_cast<int>(std::lround(total / units::kTwoPi));
}

PeriodicIntegrator::PeriodicIntegrator(std::size_t n) : n_(n), fft_(n), g_(n) { assert(n >= 4); }

void PeriodicIntegrator::integrate(PeriodicMethod method, std::span<const double> alpha,
                                   std::span<const double> crank_speed, double turns, std::span<double> omega,
                                   bool keep_slope) {
  assert(alpha.size() == n_ && crank_speed.size() == n_ && omega.size() == n_);
  const double dtheta = units::kTwoPi / n_;
  for (std::size_t k = 0; k < n_; ++k) g_[k] = alpha[k] / crank_speed[k];  // dω/dθ2
  if (method == PeriodicMethod::spectral) {
    auto t = fft_.time();
    std::copy(g_.begin(), g_.end(), t.begin());
    fft_.forward();
    auto s = fft_.spectrum();
    // ω_m = G_m/(j·m) in the angle variable (harmonic m per turn); the mean
    // and, for even N, the Nyquist harmonic (no defined derivative) are 0.
    const double slope = s[0].real() / double(n_);  // mean dω/dθ2 over the revolution
    s[0] = 0;
    for (std::size_t m = 1; m < s.size(); ++m) s[m] = s[m] / std::complex<double>(0.0, double(m)) / double(n_);
    if (n_ % 2 == 0) s[n_ / 2] = 0;
    fft_.inverse();
    std::copy(t.begin(), t.end(), omega.begin());
    if (keep_slope)
      for (std::size_t k = 0; k < n_; ++k) omega[k] += slope * dtheta * (double(k) - 0.5 * double(n_ - 1));
  } else {
    // Trapezoid round the closed revolution; the closing error (non-zero
    // only through noise and discretisation) spread linearly.
    double acc = 0;
    omega[0] = 0;
    for (std::size_t k = 1; k <= n_; ++k) {
      acc += 0.5 * dtheta * (g_[k - 1] + g_[k % n_]);
      if (k < n_) omega[k] = acc;
    }
    if (!keep_slope)
      for (std::size_t k = 0; k < n_; ++k) omega[k] -= acc * double(k) / n_;
  }
  // Constant: mean over the turn of ω/ω2 = turns.
  double mean_ratio = 0, mean_inv = 0;
  for (std::size_t k = 0; k < n_; ++k) {
    mean_ratio += omega[k] / crank_speed[k];
    mean_inv += 1.0 / crank_speed[k];
  }
  const double c = (turns - mean_ratio / n_) / (mean_inv / n_);
  for (double& w : omega) w += c;
}

double omega_offset_from_normal(std::span<const double> omega_zero_mean, std::span<const double> omega_sq_measured,
                                double sign_hint) {
  assert(omega_zero_mean.size() == omega_sq_measured.size() && !omega_zero_mean.empty());
  const double n = static_cast<double>(omega_zero_mean.size());
  const double mean_sq_measured = std::accumulate(omega_sq_measured.begin(), omega_sq_measured.end(), 0.0) / n;
  const double mean_int = std::accumulate(omega_zero_mean.begin(), omega_zero_mean.end(), 0.0) / n;
  double mean_sq_int = 0;
  for (double w : omega_zero_mean) mean_sq_int += (w - mean_int) * (w - mean_int);
  mean_sq_int /= n;
  const double c2 = mean_sq_measured - mean_sq_int;
  const double c = c2 > 0 ? std::sqrt(c2) : 0.0;
  return (sign_hint < 0 ? -c : c) - mean_int;
}

}  // namespace fourbar
