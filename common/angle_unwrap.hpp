#pragma once
// Continuous (unwrapped) angle series from principal angles.

#include <cmath>

#include "common/units.hpp"

namespace fourbar::units {

/// `angle_rad` brought within π of `previous_rad` by whole turns: one step of
/// a continuous angle series from principal angles (atan2's).
inline double unwrap_rad(double angle_rad, double previous_rad) {
  return angle_rad - kTwoPi * std::round((angle_rad - previous_rad) / kTwoPi);
}

}  // namespace fourbar::units
