#pragma once
// The coupler's and rocker's motion at one instant: what a clearance model
// has in place of the nominal θ3(θ2), θ4(θ2), and what its records carry
// (run_records.hpp, impact_result.hpp). Plain data.

#include "mechanism/vec2.hpp"

namespace fourbar {

/// Coupler and rocker directions and rates at one instant.
struct LinkMotion {
  Vec2 u3, u4;
  double omega3_rad_s = 0, omega4_rad_s = 0;
};

}  // namespace fourbar
