#pragma once
// Values of the thesis rig that tests share (mechanism/rig.hpp's thesis_rig()
// holds the rig itself).

#include <cmath>
#include <cstddef>
#include <vector>

namespace fourbar::testing {

/// The thesis rig's radial clearance ξ (Table 6.1): 0.254 mm.
inline constexpr double kXi = 0.254e-3;

/// √(Σ(a−b)² / Σb²) over the samples from index `from` on: the relative RMS
/// difference of a series `a` from a reference `b` of the same length.
inline double relative_rms(const std::vector<double>& a, const std::vector<double>& b, std::size_t from = 0) {
  double num = 0, den = 0;
  for (std::size_t i = from; i < a.size(); ++i) {
    num += (a[i] - b[i]) * (a[i] - b[i]);
    den += b[i] * b[i];
  }
  return std::sqrt(num / den);
}

}  // namespace fourbar::testing
