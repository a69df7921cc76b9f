#pragma once
// The mechanism with a radial clearance ξ in the coupler–rocker bearing:
// the quantities every mode needs, in closed form.
//
// Coordinates (DESIGN.md): A = l2·u2 crank pin, B = A + l3·u3 the pin on the
// coupler end, C = O4 + l4·u4 the bushing centre on the rocker end. The
// eccentricity e = B − C has |e| ≤ ξ; n = e/|e| points from the bushing centre
// to the pin (thesis angle η, eq. 5.1-3), t = n turned +90°. The gap is
// ξ − |e| ≥ 0 (zero in contact). Contact is a point pin against the bushing
// wall at B, as in the thesis (moment arm l4·cos(η−θ4) + ξ for the tangential
// impulse on the rocker, eq. 5.1.3-3).
//
// Generalised coordinates are q = (θ3, θ4); the crank is prescribed. Without
// contact (thesis ch. 4, corrected per THESIS-ERRATA):
//   I_A3·α3 = m3·l2·S3·[ω2²·sin(θ2−θ3) − α2·cos(θ2−θ3)] − m3·g·S3·cos θ3   (4.1-20)
//   I_O4·α4 = −m4·g·S4·cos θ4                                            (4.2-1)
// A contact force P on the pin (and −P on the rocker at B) adds the
// generalised forces Q3 = P·(l3·u3⊥), Q4 = −P·((B − O4)⊥).

#include "mechanism/kinematics.hpp"
#include "mechanism/rig.hpp"
#include "mechanism/vec2.hpp"
#include "sim/record/link_motion.hpp"

namespace fourbar {

/// The bearing's state at one instant.
struct BearingState {
  Vec2 eccentricity_m;      ///< e = B − C
  double gap_m = 0;         ///< ξ − |e|
  Vec2 normal;              ///< n = e/|e|
  double normal_speed_m_s = 0;      ///< n·(v_B3 − v_B4): > 0 closes the gap (−d gap/dt)
  double tangential_speed_m_s = 0;  ///< t·(v_B3 − v_B4): slip of pin over bushing
};

/// Coulomb friction of the pin sliding on the bushing wall in the following
/// mode (an extension of the thesis, whose following mode is frictionless).
/// The tangential force f on the pin (along t = n⊥, −f on the rocker at B)
/// opposes the slip speed v_t = t·(v_B3 − v_B4) = ξ·(η̇ − ω4):
///   sliding (slip = ±1 = sign of v_t): f = −slip·μ·N;
///   stuck (slip = 0): η̇ = ω4 is held, f is whatever that needs (|f| ≤ μ·N
///   is the simulator's business).
struct WallFriction {
  double mu = 0;  ///< μ; 0 = the thesis's frictionless following mode
  int slip = 1;   ///< +1 / −1 sliding with v_t of that sign, 0 stuck
};

/// Everything of the following mode at one instant (thesis ch. 3).
struct FollowingMotion {
  LinkMotion links;
  double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0;
  double eta_accel_rad_s2 = 0;  ///< η̈ of the clearance link
  double normal_force_N = 0;    ///< N ≥ 0 compressive: force on the pin is −N·n
  double tangential_force_N = 0;  ///< f: friction force on the pin along t = n⊥ (0 without friction)
  double slip_speed_m_s = 0;    ///< v_t = ξ·(η̇ − ω4): pin sliding over the bushing wall
  Vec2 normal;                  ///< n
  double crank_torque_Nm = 0;
  Vec2 pin_force() const { return -normal_force_N * normal + tangential_force_N * normal.perp(); }
};

class ClearanceModel {
 public:
  ClearanceModel(const Rig& rig, double clearance_m);

  const Rig& rig() const { return rig_; }
  double clearance_m() const { return xi_; }
  double inertia_coupler_about_A() const { return I3_; }  ///< I_A3
  double inertia_rocker_about_O4() const { return I4_; }  ///< I_O4

  /// Bearing geometry and relative velocity of pin and bushing.
  BearingState bearing(const CrankState& crank, const LinkMotion& m) const;
  /// The same with the crank direction u2 = (cos θ2, sin θ2) already known.
  BearingState bearing(const CrankState& crank, Vec2 u2, const LinkMotion& m) const;

  /// Free-flight angular accelerations (no contact force).
  void free_accelerations(const CrankState& crank, const LinkMotion& m, double& alpha3, double& alpha4) const;
  /// The same with the crank direction u2 = (cos θ2, sin θ2) already known.
  void free_accelerations(const CrankState& crank, Vec2 u2, const LinkMotion& m, double& alpha3, double& alpha4) const;

  /// Angular accelerations with a force `pin_force_N` on the pin at B (and
  /// its reaction on the rocker at B): free flight plus M⁻¹·(Q3, Q4) with
  /// Q3 = P·(l3·u3⊥), Q4 = −P·((B − O4)⊥) (the compliant contact model).
  void forced_accelerations(const CrankState& crank, Vec2 u2, const LinkMotion& m, Vec2 pin_force_N, double& alpha3,
                            double& alpha4) const;

  /// Motor torque that holds the prescribed crank motion, given the coupler
  /// acceleration and the contact force `pin_force_N` on the pin (zero in free flight).
  double crank_torque_Nm(const CrankState& crank, const LinkMotion& m, double alpha3, Vec2 pin_force_N) const;
  double crank_torque_Nm(const CrankState& crank, Vec2 u2, const LinkMotion& m, double alpha3, Vec2 pin_force_N) const;

  /// Following mode in its minimal coordinate: the clearance-link angle η
  /// (e = ξ·(cos η, sin η)). Positions solve the loop A + l3·u3 = O4 + ξ·n + l4·u4
  /// in closed form on the rig's assembly branch; rates and accelerations
  /// from its derivatives; η̈ from Lagrange's equations projected on the
  /// constraint manifold; N from the remaining (normal) component.
  /// With `friction.mu > 0` the wall friction enters both (η̈ and N from
  /// one 2×2 solve when sliding; η̈ = α4 and (N, f) from the link equations
  /// when stuck); RunError when sliding friction makes that solve singular or
  /// flips its sign (Painlevé's paradox: μ too large for this geometry).
  FollowingMotion following(const CrankState& crank, double eta_rad, double eta_rate_rad_s,
                            const WallFriction& friction = {}) const;

  /// Positions and rates only (no dynamics).
  LinkMotion following_links(const CrankState& crank, double eta_rad, double eta_rate_rad_s) const;

  /// Kinetic energy of the three links and potential energy (zero at the ground line).
  double kinetic_energy_J(const CrankState& crank, const LinkMotion& m) const;
  double potential_energy_J(const CrankState& crank, const LinkMotion& m) const;

  /// A force scale (N) and energy scale (J) of the rig at this crank speed,
  /// for tolerances and reported relative errors.
  double force_scale_N(double crank_speed_rad_s) const;
  double energy_scale_J(double crank_speed_rad_s) const;

 private:
  LinkMotion following_links(const CrankState& crank, Vec2 u2, Vec2 n, double eta_rate) const;
  void following_with_friction(const WallFriction& fr, const LinkMotion& m, Vec2 n, double G3, double G4, double k3,
                               double k4, double f3, double f4, double c3, double c4, FollowingMotion& f) const;

  Rig rig_;
  double xi_;
  double l1_, l2_, l3_, l4_;
  double I2_, I3_, I4_;      // about O2, A, O4
  double m3_l2_S3_, m3_S3_g_, m4_S4_g_, crank_gravity_;  // m3·l2·S3, m3·g·S3, m4·g·S4, (m2·S2 + m3·l2)·g
  double branch_;
};

}  // namespace fourbar
