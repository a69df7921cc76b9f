#pragma once
// Gauss–Legendre quadrature on [0, 1], composite over equal panels: the
// inertia integrals of an elastic link (elastic_link.cpp) are integrals of
// products of sines and polynomials, which it integrates to rounding.

#include <vector>

namespace fourbar {

struct QuadratureRule {
  std::vector<double> nodes;    ///< in [0, 1]
  std::vector<double> weights;  ///< sum to 1
};

/// `panels` equal panels of `points` Gauss–Legendre nodes each.
QuadratureRule gauss_legendre_unit(int points, int panels = 1);

}  // namespace fourbar
