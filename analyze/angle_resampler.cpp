#include "analyze/angle_resampler.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "common/reused_vector.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

// 4-point Lagrange weights at x for nodes p0 … p3 (one division per weight).
void lagrange_weights(double x, double p0, double p1, double p2, double p3, double* w) {
  const double d0 = x - p0, d1 = x - p1, d2 = x - p2, d3 = x - p3;
  w[0] = d1 * d2 * d3 / ((p0 - p1) * (p0 - p2) * (p0 - p3));
  w[1] = d0 * d2 * d3 / ((p1 - p0) * (p1 - p2) * (p1 - p3));
  w[2] = d0 * d1 * d3 / ((p2 - p0) * (p2 - p1) * (p2 - p3));
  w[3] = d0 * d1 * d2 / ((p3 - p0) * (p3 - p1) * (p3 - p2));
}

}  // namespace

RevolutionResampler::RevolutionResampler(std::span<const double> angle, std::size_t n, double start,
                                         double direction)
    : n_(n), samples_(angle.size()), start_(start), direction_(direction < 0 ? -1.0 : 1.0) {
  if (n < 4) throw InputError("resampling: need at least 4 points per revolution, got " + std::to_string(n));
  plan(angle);
}

void RevolutionResampler::plan(std::span<const double> angle) {
  if (angle.size() < 4) throw InputError("resampling: need at least 4 samples");
  const std::size_t n = n_;
  samples_ = angle.size();
  // Work in ψ = direction·θ, increasing.
  const double d = direction_;
  for (std::size_t i = 0; i < angle.size(); ++i) {
    if (!std::isfinite(angle[i]) || (i > 0 && !(d * angle[i] > d * angle[i - 1]))) {
      std::ostringstream os;
      os << "resampling: crank angle at sample " << i << " is " << angle[i]
         << (i > 0 ? " after " + std::to_string(angle[i - 1]) : std::string()) << "; it must be finite and strictly "
         << (d > 0 ? "increasing" : "decreasing") << " (continuous, in the direction of rotation)";
      throw InputError(os.str());
    }
  }
  // Revolutions whose grid points lie within the samples, give or take one
  // sample step at either end.
  const std::size_t last = angle.size() - 1;
  const double front = d * angle[0] - d * (angle[1] - angle[0]);
  const double back = d * angle[last] + d * (angle[last] - angle[last - 1]);
  const double psi0 = d * start_;
  first_ = static_cast<long>(std::ceil((front - psi0) / units::kTwoPi));
  const long end =
      static_cast<long>(std::floor((back - psi0) / units::kTwoPi - static_cast<double>(n - 1) / static_cast<double>(n)));
  if (end < first_) throw InputError("resampling: the samples do not cover one whole crank revolution");
  revs_ = static_cast<std::size_t>(end - first_ + 1);
  resize_reusing(base_, revs_ * n_);
  resize_reusing(weights_, 4 * revs_ * n_);
  std::size_t j = 0;  // ψ[j] <= ψ_grid < ψ[j + 1]
  for (std::size_t g = 0; g < revs_ * n_; ++g) {
    const double psi = d * grid_angle_rad(g / n_, g % n_);
    while (j + 2 < angle.size() && d * angle[j + 1] <= psi) ++j;
    // Stencil j−1 … j+2, kept inside the record.
    const std::size_t b = std::min(j > 0 ? j - 1 : 0, angle.size() - 4);
    base_[g] = b;
    lagrange_weights(psi, d * angle[b], d * angle[b + 1], d * angle[b + 2], d * angle[b + 3], &weights_[4 * g]);
  }
}

double RevolutionResampler::grid_angle_rad(std::size_t r, std::size_t k) const {
  return start_ + direction_ * units::kTwoPi * (static_cast<double>(first_ + static_cast<long>(r)) + double(k) / n_);
}

std::vector<double> RevolutionResampler::resample(std::span<const double> channel) const {
  std::vector<double> out;
  resample(channel, out);
  return out;
}

void RevolutionResampler::resample(std::span<const double> channel, std::vector<double>& out) const {
  if (channel.size() != samples_) {
    std::ostringstream os;
    os << "resampling: channel has " << channel.size() << " samples, the crank-angle track " << samples_;
    throw InputError(os.str());
  }
  resize_reusing(out, base_.size());
  for (std::size_t g = 0; g < base_.size(); ++g) {
    const double* x = channel.data() + base_[g];
    const double* w = weights_.data() + 4 * g;
    out[g] = w[0] * x[0] + w[1] * x[1] + w[2] * x[2] + w[3] * x[3];
  }
}

namespace {

// 4-point Lagrange interpolation of `v` at ψ from the stencil around it (ψ
// increasing along the record; the stencil kept inside the record).
double lagrange_at(std::span<const double> psi, std::span<const double> v, double x) {
  const std::size_t n = psi.size();
  const auto it = std::upper_bound(psi.begin(), psi.end(), x);
  const std::size_t j = it == psi.begin() ? 0 : static_cast<std::size_t>(it - psi.begin()) - 1;
  const std::size_t b = std::min(j > 0 ? j - 1 : 0, n - 4);
  double w[4];
  lagrange_weights(x, psi[b], psi[b + 1], psi[b + 2], psi[b + 3], w);
  return w[0] * v[b] + w[1] * v[b + 1] + w[2] * v[b + 2] + w[3] * v[b + 3];
}

}  // namespace

std::vector<double> crank_periodic_extension(std::span<const double> angle, std::span<const double> values,
                                             std::size_t pad, double direction, bool before) {
  const std::size_t n = angle.size();
  if (n < 4 || values.size() != n)
    throw InputError("periodic extension: need at least 4 samples with one value each, got " + std::to_string(n) +
                     " angles and " + std::to_string(values.size()) + " values");
  const double d = direction < 0 ? -1.0 : 1.0;
  std::vector<double> psi(n);
  for (std::size_t i = 0; i < n; ++i) psi[i] = d * angle[i];
  std::vector<double> out(pad);
  if (before) {
    const double step = (psi[3] - psi[0]) / 3, first = psi[0];
    for (std::size_t m = 1; m <= pad; ++m) {
      const double x = first - static_cast<double>(m) * step;
      const double turns = std::ceil((first - x) / units::kTwoPi);
      out[pad - m] = lagrange_at(psi, values, x + turns * units::kTwoPi);
    }
  } else {
    const double step = (psi[n - 1] - psi[n - 4]) / 3, last = psi[n - 1];
    for (std::size_t m = 1; m <= pad; ++m) {
      const double x = last + static_cast<double>(m) * step;
      const double turns = std::ceil((x - last) / units::kTwoPi);
      out[m - 1] = lagrange_at(psi, values, x - turns * units::kTwoPi);
    }
  }
  return out;
}

}  // namespace fourbar
