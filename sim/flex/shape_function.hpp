#pragma once
// Assumed shape functions of an elastic link in its floating frame.
//
// The frame's x axis runs from the link's first joint (s = 0) to its second
// (s = L) when the link is undeformed; ξ = s/L. A shape function moves the
// material point at ξ by (Φx(ξ), Φy(ξ)) in that frame per unit of its modal
// coordinate η (metres). Pinned–pinned bending modes, sin(kπξ), vanish at both
// joints, so the frame stays the chord through the two pins; axial shapes
// vanish at ξ = 0 only and move the second joint along the axis.
//
//   lateral_sine k       Φ = (0, sin(kπξ))             pinned–pinned bending, k = 1, 2, …
//   axial_sine k         Φ = (sin((2k−1)πξ/2), 0)      fixed–free bar, k = 1, 2, …
//   axial_quadratic_mid  Φ = (4ξ(1−ξ), 0)              quadratic element, node at ξ = 1/2
//   axial_quadratic_tip  Φ = (ξ(2ξ−1), 0)              quadratic element, node at ξ = 1
//
// The last two are the IVP test set's axial ansatz for the flexible
// slider-crank (benchmarks/flexible-slider-crank.md).

#include <string>

namespace fourbar {

enum class ShapeKind { lateral_sine, axial_sine, axial_quadratic_mid, axial_quadratic_tip };

struct ShapeFunction {
  ShapeKind kind = ShapeKind::lateral_sine;
  int index = 1;  ///< k for the sine shapes (>= 1); unused by the quadratic ones
};

/// One shape function's value and ξ-derivatives at a point (per unit η).
struct ShapeValue {
  double x = 0, y = 0;    ///< Φx, Φy
  double dx = 0, dy = 0;  ///< dΦ/dξ
  double ddy = 0;         ///< d²Φy/dξ² (bending curvature ×L²)
};

ShapeValue evaluate(const ShapeFunction& f, double xi);

bool is_lateral(const ShapeFunction& f);

/// "sin(2πξ) lateral", for messages and docs.
std::string describe(const ShapeFunction& f);

}  // namespace fourbar
