#pragma once
// Minimal plane vector for closed-form mechanism formulas.

#include <cmath>

namespace fourbar {

struct Vec2 {
  double x = 0, y = 0;
  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  constexpr Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
  /// The vector turned +90°: the direction of motion of a point on a link
  /// rotating counter-clockwise.
  constexpr Vec2 perp() const { return {-y, x}; }
  double norm() const { return std::hypot(x, y); }
};

constexpr Vec2 operator*(double s, Vec2 v) { return v * s; }
constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z-component of the plane cross product a × b.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline Vec2 unit(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }

}  // namespace fourbar
