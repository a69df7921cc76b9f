#pragma once
// Kinetostatics of the nominal mechanism with gravity: the crank torque and
// the joint reactions that make the prescribed motion happen.
//
// Two independent formulations:
//  * `solve_loads` — Newton–Euler on each link, eliminated in closed form
//    (production path, no matrix solve);
//  * `solve_loads_lagrange` — Lagrange's equations in (θ2, θ3, θ4) with
//    multipliers for the crank drive and the loop closure (the thesis system
//    of eq. 3.3-7/3.3-8 with the clearance link removed), solved as a dense
//    5×5 system (reference path, used to check the first).

#include "mechanism/kinematics.hpp"

namespace fourbar {

/// Joint reactions and drive torque. Sign convention: every force is the
/// force ON the named link's neighbour side as stated, in N, global x/y.
struct JointLoads {
  double crank_torque_Nm = 0;  ///< motor torque on the crank (counter-clockwise positive)
  Vec2 bearing_N;              ///< coupler–rocker bearing: force of the rocker's bushing on the coupler's pin at B
  Vec2 crank_pin_N;            ///< crank–coupler joint A: force of the crank on the coupler
  Vec2 crank_pivot_N;          ///< ground on crank at O2
  Vec2 rocker_pivot_N;         ///< ground on rocker at O4
};

/// Newton–Euler, closed form. `m` must come from solve_motion.
JointLoads solve_loads(const Rig& rig, const NominalMotion& m);

/// Lagrange multipliers, dense solve. Fills crank_torque_Nm and bearing_N
/// (the multipliers) and recomputes α3, α4 into `alpha3`, `alpha4`.
struct LagrangeSolution {
  double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0;
  double crank_torque_Nm = 0;
  Vec2 bearing_N;
};
LagrangeSolution solve_loads_lagrange(const Rig& rig, const NominalMotion& m);

/// Kinetic energy of the three moving links.
double kinetic_energy_J(const Rig& rig, const NominalMotion& m);
/// Gravitational potential energy, zero at the ground line (y = 0).
double potential_energy_J(const Rig& rig, const Pose& pose);

}  // namespace fourbar
