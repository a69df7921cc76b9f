#pragma once
// The nominal motion of a sensed link (coupler or rocker) at the measured
// crank state: what the conversion (conversion.hpp) takes the link angle,
// the offset term's ω and the first joint's acceleration from.
//
// Exact per sample (nominal_link_motion: one closed-form solution, thesis
// eq. 2.1-1 … 2.1-3), or from a table over the crank angle (LinkTable): the
// link angle θ depends on θ2 alone, so with K(θ2) = dθ/dθ2 and
// K'(θ2) = d²θ/dθ2²
//   ω = ω2·K(θ2),   α = α2·K(θ2) + ω2²·K'(θ2),
// and the coupler's first joint (the crank pin) accelerates with
//   a_A = l2·(α2·n2 − ω2²·u2).
// K, K' (the link's ω and α at ω2 = 1, α2 = 0), cos θ, sin θ, cos θ2 and
// sin θ2 are tabulated once per rig at M crank angles and read by 4-point
// Lagrange interpolation: one table read per sample instead of one nominal
// solution, for any crank speed and acceleration.

#include <array>
#include <span>
#include <vector>

#include "analyze/sensor_mount.hpp"
#include "sim/nominal/kinematics.hpp"

namespace fourbar {

/// Crank state per sample, as measured (acquire): continuous angle, speed,
/// acceleration. All spans have the length of the channel.
struct CrankTrack {
  std::span<const double> angle_rad, speed_rad_s, accel_rad_s2;
  std::size_t size() const { return angle_rad.size(); }
  CrankState at(std::size_t i) const { return {angle_rad[i], speed_rad_s[i], accel_rad_s2[i]}; }
};

/// The motion of the sensed link at one instant.
struct SensedLinkMotion {
  Vec2 u;                 ///< link direction
  double omega_rad_s = 0;
  double alpha_rad_s2 = 0;
  Vec2 joint_accel_m_s2;  ///< a_J of the link's first joint
};

/// The nominal motion of the sensed link at one crank state (exact).
SensedLinkMotion nominal_link_motion(const Rig& rig, SensedLink link, const CrankState& crank);

/// The same for every sample of a crank track. Throws InputError when the
/// track's spans differ in length.
std::vector<SensedLinkMotion> nominal_link_track(const Rig& rig, SensedLink link, const CrankTrack& crank);

/// Throws InputError when the spans of `crank` differ in length.
void check_crank_track(const CrankTrack& crank);

/// The nominal motion of one link tabulated over the crank angle.
class LinkTable {
 public:
  /// Largest interpolation error accepted, relative to each tabulated
  /// function's largest magnitude, checked half-way between table points
  /// (where a 4-point interpolation errs most).
  static constexpr double kTolerance = 1e-11;

  /// Tabulates at 16384 crank angles, doubling up to 2^20 until the check
  /// passes; a rig that still fails (a mechanism close to a dead point,
  /// whose K varies too sharply) is served exactly, per sample.
  LinkTable(const Rig& rig, SensedLink link);

  SensedLink link() const { return link_; }
  /// The motion at one crank state (any speed and acceleration).
  SensedLinkMotion motion(const CrankState& crank) const;
  /// Points per crank turn; 0 when served exactly.
  std::size_t points() const { return m_; }
  /// The measured interpolation error (relative, as kTolerance).
  double max_error() const { return max_error_; }

 private:
  using Row = std::array<double, 6>;  // cos θ, sin θ, K, K', cos θ2, sin θ2
  Row exact_row(double theta2) const;
  Row interpolated_row(double theta2) const;
  bool build(std::size_t m);

  Rig rig_;
  SensedLink link_;
  double l2_;
  std::size_t m_ = 0;
  double scale_ = 0;        // m / 2π
  std::vector<Row> rows_;   // rows_[i + 1] at θ2 = 2πi/m, i = −1 … m + 1
  double max_error_ = 0;
};

}  // namespace fourbar
