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

#include "sim/nominal/kinematics.hpp"
#include "sim/rig.hpp"
#include "sim/vec2.hpp"

namespace fourbar {

/// Coupler and rocker directions and rates at one instant.
struct LinkMotion {
  Vec2 u3, u4;
  double omega3_rad_s = 0, omega4_rad_s = 0;
};

/// The bearing's state at one instant.
struct BearingState {
  Vec2 eccentricity_m;      ///< e = B − C
  double gap_m = 0;         ///< ξ − |e|
  Vec2 normal;              ///< n = e/|e|
  double normal_speed_m_s = 0;      ///< n·(v_B3 − v_B4): > 0 closes the gap (−d gap/dt)
  double tangential_speed_m_s = 0;  ///< t·(v_B3 − v_B4): slip of pin over bushing
};

/// Everything of the following mode at one instant (thesis ch. 3).
struct FollowingMotion {
  LinkMotion links;
  double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0;
  double eta_accel_rad_s2 = 0;  ///< η̈ of the clearance link
  double normal_force_N = 0;    ///< N ≥ 0 compressive: force on the pin is −N·n
  Vec2 normal;                  ///< n
  double crank_torque_Nm = 0;
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

  /// Motor torque that holds the prescribed crank motion, given the coupler
  /// acceleration and the contact force `pin_force_N` on the pin (zero in free flight).
  double crank_torque_Nm(const CrankState& crank, const LinkMotion& m, double alpha3, Vec2 pin_force_N) const;
  double crank_torque_Nm(const CrankState& crank, Vec2 u2, const LinkMotion& m, double alpha3, Vec2 pin_force_N) const;

  /// Following mode in its minimal coordinate: the clearance-link angle η
  /// (e = ξ·(cos η, sin η)). Positions solve the loop A + l3·u3 = O4 + ξ·n + l4·u4
  /// in closed form on the rig's assembly branch; rates and accelerations
  /// from its derivatives; η̈ from Lagrange's equations projected on the
  /// constraint manifold; N from the remaining (normal) component.
  FollowingMotion following(const CrankState& crank, double eta_rad, double eta_rate_rad_s) const;

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

  Rig rig_;
  double xi_;
  double l1_, l2_, l3_, l4_;
  double I2_, I3_, I4_;      // about O2, A, O4
  double m3_l2_S3_, m3_S3_g_, m4_S4_g_, crank_gravity_;  // m3·l2·S3, m3·g·S3, m4·g·S4, (m2·S2 + m3·l2)·g
  double branch_;
};

}  // namespace fourbar
