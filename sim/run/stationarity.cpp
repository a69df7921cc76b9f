#include "sim/run/stationarity.hpp"

#include <algorithm>
#include <cmath>

namespace fourbar {

StationarityResult compare_windows(const std::vector<TurnQuantities>& turns, int window, double tolerance) {
  StationarityResult r;
  const std::size_t n = turns.size(), w = static_cast<std::size_t>(window);
  if (window < 1 || n < 2 * w) {
    r.worst_relative_difference = 1e300;
    return r;
  }
  for (std::size_t q = 0; q < TurnQuantities::kCount; ++q) {
    double a = 0, b = 0;
    for (std::size_t i = n - 2 * w; i < n - w; ++i) a += turns[i].values[q];
    for (std::size_t i = n - w; i < n; ++i) b += turns[i].values[q];
    a /= window;
    b /= window;
    r.earlier_mean[q] = a;
    r.later_mean[q] = b;
    const double scale = std::max(std::abs(a), std::abs(b));
    const double d = scale > 0 ? std::abs(a - b) / scale : 0.0;
    r.worst_relative_difference = std::max(r.worst_relative_difference, d);
    double ss = 0;
    for (std::size_t i = n - w; i < n; ++i) ss += (turns[i].values[q] - b) * (turns[i].values[q] - b);
    const double se = w > 1 ? std::sqrt(ss / (window - 1) / window) : 0.0;
    const double rel_se = se == 0 ? 0.0 : b != 0 ? se / std::abs(b) : 1e300;
    r.worst_relative_standard_error = std::max(r.worst_relative_standard_error, rel_se);
  }
  r.steady = r.worst_relative_difference <= tolerance && r.worst_relative_standard_error <= tolerance;
  return r;
}

}  // namespace fourbar
