#pragma once
// An elastic link as a floating frame of reference plus assumed modes
// (Shabana's FFRF; Exudyn's ObjectFFRFreducedOrder, Chrono's modal body).
//
// A material point at s ∈ [0, L] on the link's axis sits, in the frame, at
//   u(s) = (s, 0) + Φ(ξ)·η,   ξ = s/L,
// with Φ = [Φ_1 … Φ_n] the 2×n shape functions (shape_function.hpp) and η the
// modal coordinates (m). The frame is placed in the plane by its origin R and
// angle θ (rotation A(θ)), so the point is at r = R + A·u.
//
// With μ the mass per length, the constant inertia integrals are (computed
// once, in build_elastic_link, by Gauss–Legendre quadrature):
//   m        = ∫μ ds                       mass
//   S0       = ∫μ (s, 0) ds                first moment of the undeformed link
//   S̄        = ∫μ Φ ds          (2×n)      first moment per mode
//   I0       = ∫μ s² ds (+ m·d²/12)        inertia about the frame origin
//   c_x      = ∫μ s·Φx ds       (n)        axial coupling  (the test set's c12)
//   c_y      = ∫μ s·Φy ds       (n)        bending coupling (its c21)
//   M_ff     = ∫μ ΦᵀΦ ds        (n×n)      modal mass
//   B        = ∫μ (Φxᵀ Φy − Φyᵀ Φx) ds     (n×n, antisymmetric) gyroscopic coupling
//   K_ff     = ∫EI Φy''ᵀΦy'' + ∫EA Φx'ᵀΦx'  modal stiffness (Euler–Bernoulli)
//   D_ff     = M_ff·Ψ·diag(2ζ_k·ω_k)·Ψᵀ·M_ff  modal damping
// where ω_k, Ψ solve K_ff·ψ = ω²·M_ff·ψ with Ψᵀ·M_ff·Ψ = I. The mass matrix and
// quadratic-velocity forces that use them are in elastic_body.hpp.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "sim/flex/shape_function.hpp"

namespace fourbar {

/// A uniform beam's section and material. For a rectangular bar of width w
/// (in the plane of motion) and thickness t: area = w·t, second moment for
/// in-plane bending = t·w³/12.
struct BeamSection {
  double youngs_modulus_Pa = 0;
  double density_kg_m3 = 0;
  double area_m2 = 0;
  double second_moment_m4 = 0;  ///< about the axis normal to the plane of motion
  double depth_m = 0;           ///< in-plane width, for the rotary inertia m·d²/12 (0: none)
};

/// The rigid-body inertia of the link when it is known better than the
/// uniform beam gives it (a rig file's measured mass, centre and inertia).
/// All inertia integrals (m, S0, I0 and the modal ones) then come from the
/// linear mass per length with this mass and centre, plus a rotary inertia
/// for the rest of I0 (build_elastic_link), so that M is some body's.
struct RigidInertia {
  double mass_kg = 0;
  double mass_centre_m = 0;         ///< along the axis from s = 0
  double inertia_origin_kg_m2 = 0;  ///< about the frame origin (s = 0)
};

struct ElasticLinkSpec {
  std::string name = "link";
  double length_m = 0;
  double mass_per_length_kg_m = 0;    ///< μ = ρ·A
  double bending_stiffness_N_m2 = 0;  ///< EI (0 only with measured_frequencies_Hz)
  double axial_stiffness_N = 0;       ///< EA (needed when an axial shape is used)
  double depth_m = 0;                 ///< see BeamSection::depth_m
  std::vector<ShapeFunction> shapes;
  /// ζ per eigenmode, lowest frequency first; empty: undamped; shorter than
  /// the modes: the last value repeats.
  std::vector<double> damping_ratios;
  /// Measured lateral frequencies (Hz), lowest first: replace EI's stiffness so
  /// that mode k rings at f_k (lateral_sine shapes only, one per shape).
  std::vector<double> measured_frequencies_Hz;
  std::optional<RigidInertia> rigid;
  /// Modal mass / stiffness from elsewhere (an FE reduction, a published
  /// benchmark's matrices): used in place of the computed ones everywhere.
  std::optional<Eigen::MatrixXd> modal_mass_override, modal_stiffness_override;
};

/// The spec of a uniform beam with n pinned–pinned bending modes.
ElasticLinkSpec pinned_pinned_link(double length_m, const BeamSection& section, int modes,
                                   std::vector<double> damping_ratios = {});

/// The immutable elastic link: build once, share as `const ElasticLink&`.
struct ElasticLink {
  std::string name;
  double length_m = 0;
  std::vector<ShapeFunction> shapes;
  double mass_kg = 0;
  Eigen::Vector2d first_moment_kg_m = Eigen::Vector2d::Zero();  ///< S0
  double inertia_origin_kg_m2 = 0;                              ///< I0
  Eigen::Matrix2Xd shape_moment;                                ///< S̄ (2×n), kg
  Eigen::VectorXd axial_coupling;                               ///< c_x (n), kg·m
  Eigen::VectorXd bending_coupling;                             ///< c_y (n), kg·m
  Eigen::MatrixXd modal_mass;                                   ///< M_ff, kg
  Eigen::MatrixXd gyroscopic;                                   ///< B, kg
  Eigen::MatrixXd modal_stiffness;                              ///< K_ff, N/m
  Eigen::MatrixXd modal_damping;                                ///< D_ff, N·s/m
  Eigen::VectorXd frequencies_rad_s;                            ///< ω_k, ascending
  Eigen::VectorXd damping_ratios;                               ///< ζ_k
  Eigen::MatrixXd mode_vectors;                                 ///< Ψ, mass-normalised (columns)

  int modes() const { return static_cast<int>(shapes.size()); }
};

/// Builds and checks the link; throws InputError naming `spec.name` and the
/// quantity (non-positive length, mass or stiffness, ζ outside [0, 1),
/// frequencies ≤ 0 or with the wrong count).
ElasticLink build_elastic_link(const ElasticLinkSpec& spec);

}  // namespace fourbar
