#include "acquire/angle_track.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include <Eigen/Sparse>

namespace fourbar {

namespace {

/// Solves the 4×4 symmetric system A·x = b (Gaussian elimination, partial pivoting).
std::array<double, 4> solve4(std::array<std::array<double, 4>, 4> a, std::array<double, 4> b) {
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    std::swap(a[c], a[p]), std::swap(b[c], b[p]);
    for (int r = c + 1; r < 4; ++r) {
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < 4; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  std::array<double, 4> x{};
  for (int c = 3; c >= 0; --c) {
    double s = b[c];
    for (int k = c + 1; k < 4; ++k) s -= a[c][k] * x[k];
    x[c] = s / a[c][c];
  }
  return x;
}

/// Quintic Hermite coefficients in τ ∈ [0, 1] from value, slope and
/// curvature (in τ units) at both ends.
void quintic(double d, double d0, double d1, double s0, double s1, double* c) {
  c[0] = 0;
  c[1] = d0;
  c[2] = s0 / 2;
  c[3] = 10 * d - 6 * d0 - 4 * d1 - (3 * s0 - s1) / 2;
  c[4] = -15 * d + 8 * d0 + 7 * d1 + (3 * s0 - 2 * s1) / 2;
  c[5] = 6 * d - 3 * d0 - 3 * d1 - (s0 - s1) / 2;
}

}  // namespace

std::array<double, 4> fit_cubic(std::span<const double> x, std::span<const double> y, double x0, double scale) {
  const double inv = 1.0 / scale;
  std::array<std::array<double, 4>, 4> a{};
  std::array<double, 4> b{};
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double s = (x[j] - x0) * inv;
    const double p[4] = {1, s, s * s, s * s * s};
    for (int r = 0; r < 4; ++r) {
      b[r] += p[r] * y[j];
      for (int c = 0; c < 4; ++c) a[r][c] += p[r] * p[c];
    }
  }
  return solve4(a, b);
}

namespace {

/// Uniform cubic B-spline weights at fraction u of an interval, and their
/// first and second derivatives (per interval).
void bspline(double u, double* b, double* d1, double* d2) {
  const double v = 1 - u, u2 = u * u, u3 = u2 * u;
  b[0] = v * v * v / 6, b[1] = (3 * u3 - 6 * u2 + 4) / 6, b[2] = (-3 * u3 + 3 * u2 + 3 * u + 1) / 6, b[3] = u3 / 6;
  d1[0] = -v * v / 2, d1[1] = (3 * u2 - 4 * u) / 2, d1[2] = (-3 * u2 + 2 * u + 1) / 2, d1[3] = u2 / 2;
  d2[0] = v, d2[1] = 3 * u - 2, d2[2] = -3 * u + 1, d2[3] = u;
}

}  // namespace

AngleTrack::AngleTrack(std::span<const double> times_s, std::span<const double> phases_rad, std::size_t knot_spacing) {
  const std::size_t n = times_s.size();
  assert(n >= 2 && phases_rad.size() == n && knot_spacing >= 2);
  knots_.resize(n);
  const double phi0 = phases_rad[0], span = phases_rad[n - 1] - phi0;
  const double slope = (times_s[n - 1] - times_s[0]) / span;  // mean dt/dφ
  if (n < 4) {  // too few for a curve: constant speed
    for (std::size_t k = 0; k < n; ++k) knots_[k] = {times_s[k], phases_rad[k], 1 / slope, 0.0};
    return;
  }
  // Least-squares cubic spline t(φ) with uniform knots `knot_spacing` mean
  // edge spacings apart (at least one interval), fitted to the time left
  // after the mean speed's straight line.
  const double edge_spacing = span / static_cast<double>(n - 1);
  const auto intervals = static_cast<std::size_t>(
      std::max(1.0, std::floor(span / (static_cast<double>(knot_spacing) * edge_spacing))));
  const double delta = span / static_cast<double>(intervals), inv_delta = 1 / delta;
  const std::size_t m = intervals + 3;
  coefficients_ = m;
  // Normal equations: banded (a B-spline coefficient meets only its three
  // neighbours on either side), kept as the lower band and solved by Eigen's
  // sparse LDLᵀ in natural order (no fill outside the band): O(edges).
  std::vector<std::array<double, 4>> band(m, std::array<double, 4>{});  // band[i][k] = A(i, i − k)
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
  auto locate = [&](double phi, std::size_t& i, double& u) {
    const double x = (phi - phi0) * inv_delta;
    i = std::min(intervals - 1, static_cast<std::size_t>(std::max(0.0, std::floor(x))));
    u = x - static_cast<double>(i);
  };
  double b[4], d1[4], d2[4];
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t i;
    double u;
    locate(phases_rad[k], i, u);
    bspline(u, b, d1, d2);
    const double y = times_s[k] - times_s[0] - slope * (phases_rad[k] - phi0);
    for (int r = 0; r < 4; ++r) {
      rhs[static_cast<Eigen::Index>(i) + r] += b[r] * y;
      for (int c = 0; c <= r; ++c) band[i + r][r - c] += b[r] * b[c];
    }
  }
  // A whisper of ridge keeps an interval without edges (a wide gap) solvable.
  double diag = 0;
  for (const auto& row : band) diag = std::max(diag, row[0]);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(4 * m);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t k = 0; k <= 3 && k <= i; ++k)
      entries.emplace_back(static_cast<int>(i), static_cast<int>(i - k), band[i][k] + (k == 0 ? 1e-12 * diag : 0.0));
  Eigen::SparseMatrix<double> normal(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  normal.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt(normal);
  assert(ldlt.info() == Eigen::Success);
  const Eigen::VectorXd coef = ldlt.solve(rhs);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t i;
    double u;
    locate(phases_rad[k], i, u);
    bspline(u, b, d1, d2);
    double t = 0, dt = 0, ddt = 0;
    for (int r = 0; r < 4; ++r) {
      const double c = coef[static_cast<Eigen::Index>(i) + r];
      t += c * b[r], dt += c * d1[r], ddt += c * d2[r];
    }
    dt = dt * inv_delta + slope, ddt *= inv_delta * inv_delta;
    knots_[k] = {times_s[0] + slope * (phases_rad[k] - phi0) + t, phases_rad[k], 1.0 / dt, -ddt / (dt * dt * dt)};
  }
}

void AngleTrack::Cursor::load(std::size_t k) {
  const Knot& a = track_->knots_[k];
  const Knot& b = track_->knots_[k + 1];
  const double h = b.time_s - a.time_s;
  k_ = k, t0_ = a.time_s, inv_h_ = 1.0 / h, phase0_ = a.phase_rad;
  quintic(b.phase_rad - a.phase_rad, a.speed_rad_s * h, b.speed_rad_s * h, a.accel_rad_s2 * h * h,
          b.accel_rad_s2 * h * h, c_);
}

CrankPoint AngleTrack::Cursor::at(double t) {
  const auto& kn = track_->knots_;
  const std::size_t last = kn.size() - 2;
  std::size_t k = k_;
  // Forward by a few intervals (samples in time order), else a search.
  if (k <= last && t >= kn[k].time_s)
    for (int step = 0; step < 4 && k < last && t >= kn[k + 1].time_s; ++step) ++k;
  if (k > last || t < kn[k].time_s || (k < last && t >= kn[k + 1].time_s)) {
    const auto it = std::upper_bound(kn.begin(), kn.end(), t, [](double v, const Knot& x) { return v < x.time_s; });
    k = std::min(last, it == kn.begin() ? 0 : static_cast<std::size_t>(it - kn.begin()) - 1);
  }
  if (k != k_) load(k);
  const double tau = (t - t0_) * inv_h_;
  const double* c = c_;
  const double p = c[0] + tau * (c[1] + tau * (c[2] + tau * (c[3] + tau * (c[4] + tau * c[5]))));
  const double dp = c[1] + tau * (2 * c[2] + tau * (3 * c[3] + tau * (4 * c[4] + tau * 5 * c[5])));
  const double ddp = 2 * c[2] + tau * (6 * c[3] + tau * (12 * c[4] + tau * 20 * c[5]));
  return {t, phase0_ + p, dp * inv_h_, ddp * inv_h_ * inv_h_};
}

CrankPoint AngleTrack::Cursor::at_phase(double phase) {
  const auto& kn = track_->knots_;
  const std::size_t last = kn.size() - 2;
  std::size_t k = k_;
  if (k <= last && phase >= kn[k].phase_rad)
    for (int step = 0; step < 4 && k < last && phase >= kn[k + 1].phase_rad; ++step) ++k;
  if (k > last || phase < kn[k].phase_rad || (k < last && phase >= kn[k + 1].phase_rad)) {
    const auto it = std::upper_bound(kn.begin(), kn.end(), phase,
                                     [](double v, const Knot& x) { return v < x.phase_rad; });
    k = std::min(last, it == kn.begin() ? 0 : static_cast<std::size_t>(it - kn.begin()) - 1);
  }
  if (k != k_) load(k);
  // Newton on τ from the straight line between the knots.
  const double target = phase - phase0_, d = kn[k + 1].phase_rad - phase0_;
  const double* c = c_;
  double tau = std::clamp(target / d, 0.0, 1.0);
  for (int i = 0; i < 8; ++i) {
    const double p = c[0] + tau * (c[1] + tau * (c[2] + tau * (c[3] + tau * (c[4] + tau * c[5]))));
    const double dp = c[1] + tau * (2 * c[2] + tau * (3 * c[3] + tau * (4 * c[4] + tau * 5 * c[5])));
    const double step = (p - target) / dp;
    tau = std::clamp(tau - step, 0.0, 1.0);
    if (std::abs(step) < 1e-14) break;
  }
  const double dp = c[1] + tau * (2 * c[2] + tau * (3 * c[3] + tau * (4 * c[4] + tau * 5 * c[5])));
  const double ddp = 2 * c[2] + tau * (6 * c[3] + tau * (12 * c[4] + tau * 20 * c[5]));
  return {t0_ + tau / inv_h_, phase, dp * inv_h_, ddp * inv_h_ * inv_h_};
}

}  // namespace fourbar
