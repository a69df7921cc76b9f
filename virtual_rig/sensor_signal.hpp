#pragma once
// What an accelerometer on the coupler or the rocker measures: the specific
// force (acceleration minus gravity) of its mounting point, projected on the
// link's tangential or normal axis (frame in acquire/manifest.hpp).
//
// Coupler point P = A + s·u3 + d·n3 (A the crank pin):
//   a_P = l2·(α2·n2 − ω2²·u2) + α3·(s·n3 − d·u3) − ω3²·(s·u3 + d·n3);
// rocker point P = O4 + s·u4 + d·n4:
//   a_P = α4·(s·n4 − d·u4) − ω4²·(s·u4 + d·n4);
// specific force f = a_P − g with g = (0, −gravity); tangential = f·n,
// normal = f·u. (Thesis eq. 7.2.1-1 … 7.2.1-6 and 7.2.2-1 use the same
// kinematics without gravity and for s = link length, d = 0.)

#include "acquire/manifest.hpp"
#include "mechanism/rig.hpp"
#include "virtual_rig/motion_source.hpp"

namespace fourbar {

/// Specific force along the role's link axis (m/s², axis sign not applied).
double specific_force(const Rig& rig, const LinkState& state, ChannelRole role, double position_m, double offset_m);

}  // namespace fourbar
