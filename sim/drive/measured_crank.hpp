#pragma once
// A measured crank motion: θ2(t), ω2(t), α2(t) from a table of crank speeds,
// so the clearance model can run at the speed the rig really had (its
// fluctuation within and between revolutions) instead of a constant one.
//
// ω2(t) is the shape-preserving piecewise-cubic Hermite interpolant (PCHIP,
// Boost.Math slopes) of the samples: C¹, no overshoot between samples, so it
// keeps the samples' sign and θ2 stays monotone. α2 = dω2/dt and
// θ2 = θ0 + ∫ω2 dt are the exact derivative and integral of the same cubics,
// so θ2' = ω2 and ω2' = α2 hold to round-off. The end slopes are 0, and
// outside the table the speed stays at its first/last sample (α2 = 0), so
// α2 is continuous everywhere.

#include <vector>

#include "sim/drive/crank_motion.hpp"

namespace fourbar {

class MeasuredSpeedCrank final : public CrankMotion {
 public:
  /// Speed samples ω2(t_i): times strictly ascending, speeds finite, non-zero
  /// and of one sign; at least 2 samples. θ2(0) = start_angle_rad.
  /// InputError naming the bad sample otherwise.
  MeasuredSpeedCrank(double start_angle_rad, std::vector<double> times_s, std::vector<double> speeds_rad_s);

  /// From the mean speed of consecutive revolutions (e.g. 2π over the time
  /// between two crank pulses), the first starting at t = 0 at
  /// `start_angle_rad`: each mean speed is placed at its revolution's middle
  /// time. The interpolant's angle over a revolution then differs from 2π
  /// by the second-order effect of the speed's curvature (zero for a
  /// constant or linearly changing speed).
  static MeasuredSpeedCrank from_revolution_speeds(double start_angle_rad, const std::vector<double>& speeds_rad_s);

  CrankState at(double time_s) const override;
  /// As at(origin_s + tau_s), the time since the knot and the knot angle
  /// taken without the large absolute time and angle (see CrankMotion).
  CrankState at_local(double origin_s, double tau_s) const override;
  double time_at_angle(double angle_rad) const override;

 private:
  /// Angle gained from knot k over the time dt since it, inside piece k (or its extension).
  double angle_in_piece(std::size_t k, double dt) const;
  /// Speed and acceleration dt after knot k, angle = knot_angle + gain.
  CrankState state_in_piece(std::size_t k, double dt, double knot_angle) const;
  std::size_t piece(double t) const;

  std::vector<double> t_, w_, slope_;  // knots, speeds, dω/dt at the knots
  std::vector<double> theta_;         // θ2 at the knots
  std::vector<double> phase_;         // θ2 at the knots reduced modulo 2π (accumulated reduced)
  double direction_ = 1;              // sign of the speed
};

}  // namespace fourbar
