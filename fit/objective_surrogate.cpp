#include "fit/objective_surrogate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace fourbar {

namespace {

constexpr int kProfileSteps = 201;  // resolution of the interval search over each parameter

}  // namespace

SurrogateFit fit_surrogate(const std::vector<EvaluatedPoint>& all, double e_lo, double e_hi, double mu_lo,
                           double mu_hi, bool two, double noise_delta, double interval_delta) {
  SurrogateFit out;
  const int features = two ? 6 : 3;
  if (all.empty()) return out;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : all) best = std::min(best, p.chi2);
  auto u = [&](double e) { return (e - e_lo) / (e_hi - e_lo); };
  auto v = [&](double m) { return two ? (m - mu_lo) / (mu_hi - mu_lo) : 0.0; };
  auto row = [&](double x, double y) {
    Eigen::VectorXd f(features);
    if (two) f << 1, x, y, x * x, x * y, y * y;
    else f << 1, x, x * x;
    return f;
  };
  // The points near the bottom: within a window that grows until enough
  // distinct points are in it (at least twice the coefficients).
  std::vector<EvaluatedPoint> used;
  for (double window = 6 * noise_delta; used.size() < static_cast<std::size_t>(2 * features); window *= 2) {
    used.clear();
    for (const auto& p : all)
      if (p.chi2 <= best + window) used.push_back(p);
    if (window > 1e6 * std::max(1.0, best)) break;
  }
  if (used.size() < static_cast<std::size_t>(features + 1)) return out;
  Eigen::MatrixXd A(used.size(), features);
  Eigen::VectorXd b(used.size());
  for (std::size_t i = 0; i < used.size(); ++i)
    A.row(static_cast<Eigen::Index>(i)) = row(u(used[i].restitution), v(used[i].friction)).transpose(),
    b(static_cast<Eigen::Index>(i)) = used[i].chi2;
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  const Eigen::VectorXd r = A * c - b;
  out.residual_rms = std::sqrt(r.squaredNorm() / static_cast<double>(used.size()));
  out.points_used = static_cast<int>(used.size());
  out.delta = std::max(interval_delta > 0 ? interval_delta : noise_delta, out.residual_rms);
  // Curvature: positive definite?
  if (two) {
    const double hxx = 2 * c(3), hyy = 2 * c(5), hxy = c(4);
    if (hxx > 0 && hyy > 0 && hxx * hyy - hxy * hxy > 0) out.correlation = -hxy / std::sqrt(hxx * hyy);
  }
  // The quadratic on a fine grid of the box: minimum and profiles. Its
  // minimum is looked for only within the points it was fitted to (their
  // bounding box): outside it the quadratic extrapolates.
  auto q = [&](double x, double y) { return row(x, y).dot(c); };
  double x_lo = 1, x_hi = 0, y_lo = 1, y_hi = 0;
  for (const auto& p : used)
    x_lo = std::min(x_lo, u(p.restitution)), x_hi = std::max(x_hi, u(p.restitution)),
    y_lo = std::min(y_lo, v(p.friction)), y_hi = std::max(y_hi, v(p.friction));
  const double tiny = 1e-9;
  const int ny = two ? kProfileSteps : 1;
  std::vector<double> prof_e(kProfileSteps, std::numeric_limits<double>::infinity()), prof_m(ny, std::numeric_limits<double>::infinity());
  double qmin = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kProfileSteps; ++i)
    for (int j = 0; j < ny; ++j) {
      const double x = i / double(kProfileSteps - 1), y = two ? j / double(kProfileSteps - 1) : 0.0;
      const double val = q(x, y);
      prof_e[i] = std::min(prof_e[i], val), prof_m[j] = std::min(prof_m[j], val);
      const bool inside = x >= x_lo - tiny && x <= x_hi + tiny && (!two || (y >= y_lo - tiny && y <= y_hi + tiny));
      if (inside && val < qmin) qmin = val, out.restitution = e_lo + x * (e_hi - e_lo), out.friction = two ? mu_lo + y * (mu_hi - mu_lo) : 0.0;
    }
  out.minimum = qmin;
  auto range = [&](const std::vector<double>& prof, double lo, double hi, double& a, double& b_) {
    int first = -1, last = -1;
    for (int i = 0; i < static_cast<int>(prof.size()); ++i)
      if (prof[i] <= qmin + out.delta) first = first < 0 ? i : first, last = i;
    const double step = prof.size() > 1 ? (hi - lo) / double(prof.size() - 1) : 0.0;
    a = lo + first * step, b_ = lo + last * step;
  };
  range(prof_e, e_lo, e_hi, out.restitution_low, out.restitution_high);
  if (two) range(prof_m, mu_lo, mu_hi, out.friction_low, out.friction_high);
  // A quadratic that is not curved upwards (positive definite) does not bound anything.
  const bool curved = two ? out.correlation.has_value() : c(2) > 0;
  out.ok = curved && std::isfinite(qmin);
  return out;
}

}  // namespace fourbar
