#include "compare/metrics.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace fourbar {

double rms_difference(std::span<const double> a, std::span<const double> b) {
  assert(a.size() == b.size());
  if (a.empty()) return 0;
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / static_cast<double>(a.size()));
}

double correlation(std::span<const double> a, std::span<const double> b) {
  assert(a.size() == b.size());
  const double n = static_cast<double>(a.size());
  if (a.size() < 2) return 0;
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n, mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

double peak_ratio(std::span<const double> a, std::span<const double> b) {
  double pa = 0, pb = 0;
  for (double v : a) pa = std::max(pa, std::abs(v));
  for (double v : b) pb = std::max(pb, std::abs(v));
  return pb > 0 ? pa / pb : 0.0;
}

std::size_t circular_distance(std::size_t a, std::size_t b, std::size_t n) {
  const std::size_t d = a > b ? a - b : b - a;
  return std::min(d, n - d);
}

std::vector<std::size_t> largest_peaks(std::span<const double> x, std::size_t count, std::size_t min_separation) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return std::abs(x[i]) > std::abs(x[j]); });
  std::vector<std::size_t> peaks;
  for (std::size_t i : order) {
    if (peaks.size() == count) break;
    const bool apart = std::all_of(peaks.begin(), peaks.end(), [&](std::size_t p) {
      return circular_distance(i, p, x.size()) >= min_separation;
    });
    if (apart) peaks.push_back(i);
  }
  return peaks;
}

}  // namespace fourbar
