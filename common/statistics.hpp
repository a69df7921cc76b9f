#pragma once
// Small order and moment statistics shared by the stages: written once here.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace fourbar {

/// The median of `values` (by value: the copy is partially sorted). For an
/// even count the upper of the two middle values; 0 for no values.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

/// Root mean square; 0 for no values.
inline double rms(std::span<const double> values) {
  if (values.empty()) return 0;
  double sum_sq = 0;
  for (double v : values) sum_sq += v * v;
  return std::sqrt(sum_sq / static_cast<double>(values.size()));
}

/// A running sum with Neumaier's compensation: for books that add many small
/// terms to a growing total over long runs (energy balances).
struct CompensatedSum {
  double sum = 0, carry = 0;
  void add(double x) {
    const double s = sum + x;
    carry += std::abs(sum) >= std::abs(x) ? (sum - s) + x : (x - s) + sum;
    sum = s;
  }
  double value() const { return sum + carry; }
};

}  // namespace fourbar
