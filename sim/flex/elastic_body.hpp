#pragma once
// What an elastic link does in motion: the position, velocity and
// acceleration of a point on it, and its generalised inertia and elastic
// forces, as free functions of (const ElasticLink&, ElasticBodyData&, state).
//
// Body coordinates z = (R_x, R_y, θ, η_1 … η_n): frame origin, frame angle,
// modal coordinates. With A = A(θ), E the +90° turn, u = (s, 0) + Φ·η and
// s(η) = S0 + S̄·η, a point's acceleration is
//   r̈ = R̈ + θ̈·A·E·u − θ̇²·A·u + 2θ̇·A·E·Φ·η̇ + A·Φ·η̈,
// and the principle of virtual work, ∫μ δrᵀ·r̈ ds = δzᵀ·Q, gives
//   M(η) = [ m·I         A·E·s(η)                A·S̄          ]
//          [ ·           I0 + 2c_xᵀη + ηᵀM_ffη   c_yᵀ + ηᵀB    ]
//          [ ·           ·                       M_ff          ]
//   Q_v  = ( A·(θ̇²·s(η) − 2θ̇·E·S̄·η̇),
//            −2θ̇·(c_xᵀη̇ + ηᵀM_ff·η̇),
//            θ̇²·(c_x + M_ff·η) + 2θ̇·B·η̇ )
// (quadratic-velocity forces, on the right-hand side), and the elastic forces
// −K_ff·η (stiffness) and −D_ff·η̇ (modal damping), each kept apart so that an
// energy balance can book the damping's power −η̇ᵀD_ffη̇ as a loss.

#include <Eigen/Dense>

#include "mechanism/vec2.hpp"
#include "sim/flex/elastic_link.hpp"

namespace fourbar {

/// The floating frame's placement and its rates (second-order state).
struct FrameState {
  Vec2 origin_m;
  double angle_rad = 0;
  Vec2 velocity_m_s;
  double angular_velocity_rad_s = 0;
  Vec2 acceleration_m_s2;
  double angular_acceleration_rad_s2 = 0;
};

/// At most this many modes per link (the rig file's limit, mechanism/link_elasticity.cpp):
/// the per-call vectors and matrices below have fixed capacity and never touch the heap.
inline constexpr int kMaxModes = 16;
using ModalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxModes, 1>;
using BodyVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 + kMaxModes, 1>;
using BodyMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3 + kMaxModes, 3 + kMaxModes>;

/// Modal coordinates and rates (each of size link.modes()).
struct ModalState {
  ModalVector eta_m, eta_dot_m_s, eta_ddot_m_s2;
};

ModalState zero_modal_state(const ElasticLink& link);

/// The deflection Φ(s)·η in the frame (m) and the bending slope (rad) at s.
Vec2 deflection(const ElasticLink& link, double s_m, const ModalVector& eta);
double slope_rad(const ElasticLink& link, double s_m, const ModalVector& eta);

/// The deformed axis's unit tangent at s, in the plane: A·(1 + Φx'η, Φy'η)
/// normalised (' = d/ds). An accelerometer at s reads its acceleration minus
/// gravity projected on this (tangential) and on its +90° turn (normal).
Vec2 axis_tangent(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal);

/// A point at arc length s (0 … L) on the link's axis, deformed.
Vec2 point_position(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal);
Vec2 point_velocity(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal);
/// Uses the frame's and the modes' accelerations; with them zero it is the
/// bias (J̇·ż) of the point's acceleration.
Vec2 point_acceleration(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal);

/// The workspace of one elastic body, sized once from its link.
struct ElasticBodyData {
  BodyMatrix mass;             ///< M(η), (3+n)²
  BodyVector quadratic_force;  ///< Q_v, (3+n)
  BodyVector stiffness_force;  ///< (0, 0, 0, −K_ff·η)
  BodyVector damping_force;    ///< (0, 0, 0, −D_ff·η̇)
  Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, 3 + kMaxModes> point_jacobian;  ///< ∂r/∂z of the last point asked, 2×(3+n)

  explicit ElasticBodyData(const ElasticLink& link);
};

/// Fills mass, quadratic_force, stiffness_force and damping_force.
void body_terms(const ElasticLink& link, ElasticBodyData& data, const FrameState& frame, const ModalState& modal);

/// Fills data.point_jacobian = ∂r(s)/∂z.
void point_jacobian(const ElasticLink& link, ElasticBodyData& data, double s_m, const FrameState& frame,
                    const ModalState& modal);

/// Kinetic energy ½żᵀMż and strain energy ½ηᵀK_ffη (J).
double kinetic_energy(const ElasticLink& link, ElasticBodyData& data, const FrameState& frame, const ModalState& modal);
double strain_energy(const ElasticLink& link, const ModalState& modal);

}  // namespace fourbar
