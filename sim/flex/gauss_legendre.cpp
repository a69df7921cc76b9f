#include "sim/flex/gauss_legendre.hpp"

#include <cmath>
#include <numbers>

namespace fourbar {

QuadratureRule gauss_legendre_unit(int points, int panels) {
  // Nodes on [−1, 1]: roots of P_n by Newton from Chebyshev-like guesses.
  std::vector<double> x(points), w(points);
  for (int i = 0; i < points; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (points + 0.5));
    double dp = 0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= points; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (points == 1) p0 = 1;  // P_0
      dp = points * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
  QuadratureRule rule;
  const double h = 1.0 / panels;
  for (int p = 0; p < panels; ++p)
    for (int i = 0; i < points; ++i) {
      rule.nodes.push_back(h * (p + 0.5 * (x[i] + 1)));
      rule.weights.push_back(0.5 * h * w[i]);
    }
  return rule;
}

}  // namespace fourbar
