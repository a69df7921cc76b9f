#include "fit/objective_noise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fourbar {

namespace {

/// P(χ²₁ ≤ x).
double chi2_1_cdf(double x) { return x <= 0 ? 0.0 : std::erf(std::sqrt(0.5 * x)); }

/// P(D·X + Z ≤ t): the χ²₁ distribution function averaged over the
/// Gaussian Z (trapezoid rule over ±8 standard deviations).
double sum_cdf(double t, double dispersion, double sd) {
  if (sd <= 0) return chi2_1_cdf(t / dispersion);
  constexpr int kSteps = 800;
  const double lo = -8 * sd, h = 16 * sd / kSteps;
  double sum = 0;
  for (int i = 0; i <= kSteps; ++i) {
    const double z = lo + i * h;
    const double w = (i == 0 || i == kSteps) ? 0.5 : 1.0;
    sum += w * std::exp(-0.5 * (z / sd) * (z / sd)) * chi2_1_cdf((t - z) / dispersion);
  }
  return sum * h / (sd * std::sqrt(2 * M_PI));
}

}  // namespace

namespace {

/// Where the profile crosses `limit` between grid point i (inside) and its
/// neighbour j (outside). The profile is a bowl: a chord between the two
/// points lies above it and would cut the interval short, so the parabola
/// through i, j and i's other neighbour is used when it is curved upwards
/// and crosses between them; else the chord.
double crossing(const std::vector<double>& x, const std::vector<double>& y, std::size_t i, std::size_t j, double limit) {
  const double linear = x[i] + (x[j] - x[i]) * (limit - y[i]) / (y[j] - y[i]);
  const std::size_t k = j > i ? i - 1 : i + 1;  // i's other neighbour (callers make sure it exists)
  if ((j > i && i == 0) || (j < i && i + 1 >= x.size())) return linear;
  // Parabola through (x_k, y_k), (x_i, y_i), (x_j, y_j) in Newton form.
  const double d1 = (y[i] - y[k]) / (x[i] - x[k]), d2 = (y[j] - y[i]) / (x[j] - x[i]);
  const double a = (d2 - d1) / (x[j] - x[k]);
  if (!(a > 0)) return linear;
  // y(t) = y_i + b (t − x_i) + a (t − x_i)², b the slope at x_i.
  const double b = d2 - a * (x[j] - x[i]);
  const double c = y[i] - limit;  // ≤ 0: i is inside
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return linear;
  const double root = x[i] + (j > i ? (-b + std::sqrt(disc)) : (-b - std::sqrt(disc))) / (2 * a);
  const bool between = j > i ? (root >= x[i] && root <= x[j]) : (root <= x[i] && root >= x[j]);
  return between ? root : linear;
}

}  // namespace

std::pair<double, double> profile_interval(const std::vector<double>& x, const std::vector<double>& y, double value,
                                           double bottom, double delta, double box_lo, double box_hi) {
  const double limit = bottom + delta;
  double lo = value, hi = value;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (y[i] > limit) continue;
    double a = x[i], b = x[i];
    if (i > 0 && y[i - 1] > limit) a = crossing(x, y, i, i - 1, limit);
    else if (i > 0) a = x[i - 1];
    else a = box_lo;
    if (i + 1 < x.size() && y[i + 1] > limit) b = crossing(x, y, i, i + 1, limit);
    else if (i + 1 < x.size()) b = x[i + 1];
    else b = box_hi;
    lo = std::min(lo, a), hi = std::max(hi, b);
  }
  return {std::max(box_lo, lo), std::min(box_hi, hi)};
}

double profile_threshold(double dispersion, double noise_sd, double level) {
  if (!(level > 0 && level < 1)) throw std::invalid_argument("profile_threshold: level must lie in (0, 1)");
  double lo = 0, hi = 60 * dispersion + 10 * noise_sd;
  for (int i = 0; i < 100 && hi - lo > 1e-9 * (1 + hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    (sum_cdf(mid, dispersion, noise_sd) < level ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ObjectiveNoise objective_noise(std::span<const double> replicates, int terms, int parameters, double level) {
  if (replicates.size() < 2) throw std::invalid_argument("objective_noise: at least two replicates are needed");
  ObjectiveNoise n;
  n.replicates = static_cast<int>(replicates.size());
  n.level = level;
  for (double v : replicates) n.bottom += v;
  n.bottom /= n.replicates;
  double ss = 0;
  for (double v : replicates) ss += (v - n.bottom) * (v - n.bottom);
  n.noise_sd = std::sqrt(ss / (n.replicates - 1));
  const int dof = std::max(1, terms - parameters);
  n.dispersion = std::max(1.0, n.bottom / dof);
  n.delta = profile_threshold(n.dispersion, n.noise_sd * std::sqrt(1.0 + 1.0 / n.replicates), level);
  return n;
}

}  // namespace fourbar
