#include "acquire/tooth_spacing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "common/units.hpp"

namespace fourbar {

namespace {

constexpr std::size_t kLowTerms = 1 + 2 * kTurnLockedOrders;

double low_basis(std::size_t i, double phi) {
  if (i == 0) return 1.0;
  const double order = static_cast<double>((i + 1) / 2);
  return i % 2 ? std::cos(order * phi) : std::sin(order * phi);
}

/// Least squares of y on the basis functions f_i(x) (Gaussian elimination).
template <std::size_t n, class Basis>
std::array<double, n> least_squares(std::span<const double> at, std::span<const double> y, Basis basis) {
  double a[n][n] = {}, b[n] = {};
  std::array<double, n> fk{};
  for (std::size_t k = 0; k < at.size(); ++k) {
    for (std::size_t r = 0; r < n; ++r) fk[r] = basis(r, at[k]);
    for (std::size_t r = 0; r < n; ++r) {
      b[r] += fk[r] * y[k];
      for (std::size_t c = 0; c < n; ++c) a[r][c] += fk[r] * fk[c];
    }
  }
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    for (std::size_t k = 0; k < n; ++k) std::swap(a[c][k], a[p][k]);
    std::swap(b[c], b[p]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  std::array<double, n> x{};
  for (std::size_t c = n; c-- > 0;) {
    double s = b[c];
    for (std::size_t k = c + 1; k < n; ++k) s -= a[c][k] * x[k];
    x[c] = s / a[c][c];
  }
  return x;
}

std::array<double, kLowTerms> fit_low_orders(const std::vector<double>& phi, const std::vector<double>& y) {
  return least_squares<kLowTerms>(phi, y, low_basis);
}

/// Per-turn smooth model: a cubic in s = (φ − φ_mid)/scale for the slow
/// speed change, and the low orders of the turn, which change from turn to
/// turn when the speed change is not locked to the turn.
constexpr std::size_t kTurnTerms = 4 + 2 * kTurnLockedOrders;

}  // namespace

ToothSpacing estimate_tooth_spacing(const NumberedEdges& edges) {
  const auto P = static_cast<std::size_t>(edges.positions_per_rev);
  const double pitch = units::kTwoPi / static_cast<double>(P);
  std::vector<double> sum(P, 0.0), sum_sq(P, 0.0);
  std::vector<std::size_t> n(P, 0);
  ToothSpacing out;
  std::vector<double> phi;
  std::array<double, 2 * kTurnLockedOrders> turn_locked{};  // Σ over turns of the fitted orders, in angle
  for (const NumberedSegment& s : edges.segments) {
    phi.resize(s.time_s.size());
    for (std::size_t i = 0; i < phi.size(); ++i) phi[i] = pitch * static_cast<double>(s.position[i]);
    // Index of each turn's first edge in the segment.
    std::vector<std::size_t> starts;
    for (std::size_t i = 0; i < s.position.size(); ++i)
      if (s.position[i] % static_cast<std::int64_t>(P) == 0) starts.push_back(i);
    for (std::size_t j = 0; j + 1 < starts.size(); ++j) {
      const std::size_t lo = starts[j > 0 ? j - 1 : 0], hi = starts[std::min(j + 2, starts.size() - 1)];
      const double x0 = phi[starts[j]] + 0.5 * units::kTwoPi, scale = 0.5 * (phi[hi] - phi[lo]);
      const double t0 = s.time_s[starts[j]];
      std::vector<double> rel(hi - lo + 1);
      for (std::size_t i = lo; i <= hi; ++i) rel[i - lo] = s.time_s[i] - t0;
      auto basis = [&](std::size_t r, double ph) {
        const double x = (ph - x0) / scale;
        if (r < 4) return std::pow(x, static_cast<double>(r));
        return low_basis(r - 3, ph);
      };
      const auto q = least_squares<kTurnTerms>(std::span<const double>(phi).subspan(lo, hi - lo + 1), rel, basis);
      const double rad_per_s = scale / q[1];  // ω at the turn's middle
      for (std::size_t r = 0; r < turn_locked.size(); ++r) turn_locked[r] += q[4 + r] * rad_per_s;
      for (std::size_t i = starts[j]; i < starts[j + 1]; ++i) {
        const double x = (phi[i] - x0) / scale;
        double fit = 0;
        for (std::size_t r = 0; r < kTurnTerms; ++r) fit += q[r] * basis(r, phi[i]);
        const double dt_dphi = (q[1] + x * (2 * q[2] + x * 3 * q[3])) / scale;
        const double e = (rel[i - lo] - fit) / dt_dphi;  // late edge: the tooth sits further on
        const auto p = static_cast<std::size_t>(s.position[i] % static_cast<std::int64_t>(P));
        sum[p] += e, sum_sq[p] += e * e, ++n[p];
      }
      ++out.turns;
    }
  }
  // Average per position; the low orders of the turn apart.
  std::vector<double> at, mean;
  for (std::size_t p = 0; p < P; ++p)
    if (n[p] > 0) at.push_back(pitch * static_cast<double>(p)), mean.push_back(sum[p] / static_cast<double>(n[p]));
  out.error_rad.assign(P, NAN);
  if (at.size() < 2 * kLowTerms) return out;  // too few teeth to tell orders apart
  const auto low = fit_low_orders(at, mean);
  // The turn-locked pattern: the per-turn fits' low orders averaged over the
  // turns, plus what of them is left in the average residual.
  const double turns = static_cast<double>(std::max<std::size_t>(out.turns, 1));
  out.once_per_turn_rad = std::hypot(low[1] + turn_locked[0] / turns, low[2] + turn_locked[1] / turns);
  out.twice_per_turn_rad = std::hypot(low[3] + turn_locked[2] / turns, low[4] + turn_locked[3] / turns);
  double ref = 0, se2 = 0;
  for (std::size_t k = 0; k < at.size(); ++k) {
    double l = 0;
    for (std::size_t i = 0; i < kLowTerms; ++i) l += low[i] * low_basis(i, at[k]);
    const auto p = static_cast<std::size_t>(std::lround(at[k] / pitch));
    out.error_rad[p] = mean[k] - l;
    if (p == 0) ref = out.error_rad[p];
    const double m = sum[p] / static_cast<double>(n[p]);
    const double var = n[p] > 1 ? (sum_sq[p] / static_cast<double>(n[p]) - m * m) * static_cast<double>(n[p]) /
                                      static_cast<double>(n[p] - 1)
                                : 0.0;
    se2 += std::max(0.0, var) / static_cast<double>(n[p]);
  }
  // Position 0 is the reference angle (crank_offset_deg): its error is 0 by definition.
  double ss = 0;
  for (auto& e : out.error_rad)
    if (!std::isnan(e)) e -= ref, ss += e * e, out.max_abs_rad = std::max(out.max_abs_rad, std::abs(e));
  out.rms_rad = std::sqrt(ss / static_cast<double>(at.size()));
  out.standard_error_rad = std::sqrt(se2 / static_cast<double>(at.size()));
  return out;
}

}  // namespace fourbar
