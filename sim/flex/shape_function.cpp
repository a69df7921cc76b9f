#include "sim/flex/shape_function.hpp"

#include <cmath>
#include <numbers>

namespace fourbar {

ShapeValue evaluate(const ShapeFunction& f, double xi) {
  constexpr double pi = std::numbers::pi;
  ShapeValue v;
  switch (f.kind) {
    case ShapeKind::lateral_sine: {
      const double a = f.index * pi;
      v.y = std::sin(a * xi);
      v.dy = a * std::cos(a * xi);
      v.ddy = -a * a * v.y;
      break;
    }
    case ShapeKind::axial_sine: {
      const double a = (2 * f.index - 1) * pi / 2;
      v.x = std::sin(a * xi);
      v.dx = a * std::cos(a * xi);
      break;
    }
    case ShapeKind::axial_quadratic_mid:
      v.x = 4 * xi * (1 - xi);
      v.dx = 4 - 8 * xi;
      break;
    case ShapeKind::axial_quadratic_tip:
      v.x = xi * (2 * xi - 1);
      v.dx = 4 * xi - 1;
      break;
  }
  return v;
}

bool is_lateral(const ShapeFunction& f) { return f.kind == ShapeKind::lateral_sine; }

std::string describe(const ShapeFunction& f) {
  const std::string k = std::to_string(f.index);
  switch (f.kind) {
    case ShapeKind::lateral_sine:
      return "sin(" + k + "πξ) lateral";
    case ShapeKind::axial_sine:
      return "sin(" + std::to_string(2 * f.index - 1) + "πξ/2) axial";
    case ShapeKind::axial_quadratic_mid:
      return "4ξ(1−ξ) axial";
    case ShapeKind::axial_quadratic_tip:
      return "ξ(2ξ−1) axial";
  }
  return "?";
}

}  // namespace fourbar
