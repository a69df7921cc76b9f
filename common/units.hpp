#pragma once
// Unit conversions between the files people edit (mm, kg·mm², rpm, degrees)
// and the SI values used everywhere inside the code.

#include <numbers>

namespace fourbar::units {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

constexpr double mm_to_m(double mm) { return mm * 1e-3; }
constexpr double m_to_mm(double m) { return m * 1e3; }
constexpr double kg_mm2_to_kg_m2(double v) { return v * 1e-6; }
constexpr double rpm_to_rad_s(double rpm) { return rpm * kTwoPi / 60.0; }
constexpr double rad_s_to_rpm(double w) { return w * 60.0 / kTwoPi; }
constexpr double deg_to_rad(double deg) { return deg * kPi / 180.0; }
constexpr double rad_to_deg(double rad) { return rad * 180.0 / kPi; }

}  // namespace fourbar::units
