#pragma once
// The linkage model's stages at one instant, as free functions of the model
// and a workspace (Pinocchio's f(model, data, …), MuJoCo's mj_fwdPosition /
// mj_fwdVelocity / mj_fwdAcceleration): positions and Jacobians of every
// body, the clearance pairs' geometry and relative velocity, the pair forces
// (the shared compliant laws of sim/contact/contact_force.hpp and
// film_force.hpp), then M·z̈ = Q with the crank's row giving the motor torque.
//
// Full coordinates z = (q, θ2): the crank angle is z[n], so the drive's
// inertia enters M like any coordinate and the motor torque is
// τ = M[n,:]·z̈ − Q[n] once q̈ is solved from the first n rows with z̈[n] = α2.
// Bias accelerations J̇·ż come from the same kinematics pass with z̈ = 0.
// Every pair force lands in its own power entries (contact damping,
// friction, film) so the energy books read each source (MuJoCo's qfrc_*).

#include <array>

#include <Eigen/Dense>

#include "mechanism/kinematics.hpp"
#include "sim/flex/elastic_body.hpp"
#include "sim/linkage/block_cholesky.hpp"
#include "sim/linkage/full_vectors.hpp"
#include "sim/linkage/linkage_model.hpp"

namespace fourbar {

/// Positions and rates of the coordinates at one instant.
struct LinkageCoordinates {
  CrankState crank;
  Vec2 u2;                   ///< (cos θ2, sin θ2)
  std::array<Vec2, 2> u;     ///< coupler and rocker directions (u3, u4)
  ZVec q_offsets;            ///< size n: the offsets d and the modal η at their indices (angle entries unused)
  ZVec z_rate;               ///< size n + 1: q̇ and ω2
  /// An all-ideal linkage's prescribed θ̈3, θ̈4 and velocity ratios dθ3/dθ2, dθ4/dθ2.
  struct Prescribed {
    double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0, ratio3 = 0, ratio4 = 0;
  } prescribed;
};

/// A body frame: origin p, direction u, rates; linear in ż with biases.
struct BodyFrame {
  Vec2 u, p;
  double omega = 0;
  ZRow Jw;        ///< ω = Jw·ż
  ZJac Jp;        ///< ṗ = Jp·ż
  Vec2 a_bias;    ///< p̈ at z̈ = 0
  double alpha_bias = 0;
};

/// One clearance joint at one instant.
struct PairState {
  int joint = 0;
  Vec2 eccentricity_m;   ///< e = pin − bushing centre
  double gap_m = 0;      ///< ξ − |e|
  double penetration_m = 0;  ///< |e| − ξ
  Vec2 normal;           ///< e/|e|
  double normal_speed_m_s = 0, tangential_speed_m_s = 0;  ///< n·v, t·v, v = v_pin − v_bushing at the pin
  double omega_pin_rad_s = 0, omega_bushing_rad_s = 0;
  ZJac J_rel;            ///< v = J_rel·ż
  // forces (pair_forces)
  double normal_force_N = 0, friction_force_N = 0;
  FilmForce film;
  Vec2 pin_force_N;      ///< on the pin's body (−this on the bushing's)
  double damping_power_W = 0, friction_power_W = 0, film_power_W = 0;  ///< dissipated (≥ 0 for contact, friction)
  double elastic_energy_J = 0;
};

struct LinkageWorkspace {
  // position and velocity stage
  std::array<BodyFrame, kBodies> body;
  std::array<PairState, kJoints> pair;  ///< valid for the clearance joints
  ZVec z_rate_cache;                    ///< ż of the last forward_kinematics
  // acceleration stage
  ZMat M;
  ZVec Q, z_accel;
  BlockProfile mass_profile;  ///< the mass matrix's blocks, kept from one solve to the next
  double crank_torque_Nm = 0;
  /// Elastic links (solve_accelerations): strain energy ½ηᵀKη and the modal
  /// damping's dissipated power η̇ᵀDη̇ (≥ 0), summed over the elastic bodies.
  double strain_energy_J = 0, modal_damping_power_W = 0;
};

/// The bodies' orientations u and frame origins p (crank, coupler, rocker):
/// the position part of forward_kinematics, which uses it.
struct BodyPoses {
  std::array<Vec2, kBodies> u, p;
};
BodyPoses body_poses(const LinkageModel& m, const LinkageCoordinates& c);

/// A clearance joint's eccentricity e = pin − bushing centre (from its
/// offsets when it places a body, else from the poses).
Vec2 pair_eccentricity(const LinkageModel& m, const LinkageCoordinates& c, const BodyPoses& poses, int joint);

/// |e| − ξ of each clearance joint (m, by joint; 0 elsewhere) from positions
/// alone: the bits forward_kinematics gives as penetration_m, without its
/// Jacobians and velocities (the witnesses, evaluated after every step).
std::array<double, kJoints> pair_penetrations(const LinkageModel& m, const LinkageCoordinates& c);

/// The clearance pairs' geometry and relative velocities (w.pair, all but
/// J_rel) from the bodies' poses and rates alone, without the frames'
/// Jacobians: what the contact books need between the right-hand sides
/// (the same values as forward_kinematics to rounding).
void pair_kinematics(const LinkageModel& m, const LinkageCoordinates& c, LinkageWorkspace& w);

/// Frames of all bodies, the pairs' geometry and relative velocities.
void forward_kinematics(const LinkageModel& m, const LinkageCoordinates& c, LinkageWorkspace& w);

/// World position, Jacobian and bias acceleration of a site.
Vec2 site_position(const LinkageWorkspace& w, const Site& s);

/// Pair forces for the clearance joints; `chi` is each contact's damping
/// coefficient χ = c(e)/v⁻ (s/m), by joint.
void pair_forces(const LinkageModel& m, const std::array<double, kJoints>& chi, LinkageWorkspace& w);

/// M, Q (gravity, pair forces, biases), z̈ with z̈[n] = α2, the motor torque.
void solve_accelerations(const LinkageModel& m, const LinkageCoordinates& c, LinkageWorkspace& w);

/// ½·żᵀ·M·ż (needs solve_accelerations' M) and the potential energy of gravity
/// (an elastic body's mass centre moves with its modes).
double kinetic_energy_J(const LinkageWorkspace& w, const LinkageCoordinates& c);
double potential_energy_J(const LinkageModel& m, const LinkageWorkspace& w, const LinkageCoordinates& c);

/// An elastic body's frame and modes as sim/flex's states (accelerations from
/// w.z_accel when `with_accel`, else zero).
FrameState frame_state(const LinkageWorkspace& w, int body, bool with_accel);
ModalState modal_state(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w, int body,
                       bool with_accel);

}  // namespace fourbar
