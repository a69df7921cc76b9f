#include "common/mean_standard_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace fourbar {

MeanStandardError mean_standard_error(std::span<const double> x) {
  MeanStandardError r;
  const std::size_t n = x.size();
  if (n == 0) return r;
  double sum = 0;
  for (double v : x) sum += v;
  r.mean = sum / static_cast<double>(n);
  r.effective_count = static_cast<double>(n);
  if (n < 2) return r;
  // Autocovariance at lag k, the biased (1/n) estimate: a positive definite sequence.
  auto gamma = [&](std::size_t k) {
    double s = 0;
    for (std::size_t i = 0; i + k < n; ++i) s += (x[i] - r.mean) * (x[i + k] - r.mean);
    return s / static_cast<double>(n);
  };
  const double g0 = gamma(0);
  if (!(g0 > 0)) return r;  // a constant series: no spread, no error
  // Initial monotone positive sequence: σ²_∞ = −γ0 + 2 Σ_{m=0}^{M} Γm.
  double sum_pairs = 0, previous = 0;
  for (std::size_t m = 0; 2 * m + 1 < n; ++m) {
    double pair = gamma(2 * m) + gamma(2 * m + 1);
    if (!(pair > 0)) break;
    if (m > 0) pair = std::min(pair, previous);
    sum_pairs += pair;
    previous = pair;
  }
  const double sigma2 = -g0 + 2 * sum_pairs;
  r.autocorrelation_time = sigma2 / g0;
  const double tau = std::max(1.0, r.autocorrelation_time);
  const double nd = static_cast<double>(n);
  const double s2 = g0 * nd / (nd - 1);  // the sample variance
  r.standard_error = std::sqrt(s2 / nd * tau);
  r.effective_count = nd / tau;
  return r;
}

}  // namespace fourbar
