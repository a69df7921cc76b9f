#pragma once
// The prescribed crank motion θ2(t), ω2(t), α2(t). The clearance model asks
// only through this interface, so a measured speed profile can replace the
// constant speed without touching the simulator.
//
// Long runs: the simulator measures time locally, as a segment origin t_o
// (a double) plus a small local time τ, and asks at_local(t_o, τ). That
// returns the crank angle reduced to about (−π, π] plus the angle gained
// over τ, computed without forming t_o + τ or the large absolute angle (at
// t = 1700 s one ulp of t is 2.3e-13 s, at θ2 = 6e4 rad one ulp of θ2 is
// 7e-12 rad: both would put round-off noise of ~1e-9·ξ into the bearing).

#include <cmath>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {

/// 2π − units::kTwoPi (the low part of 2π in double-double).
inline constexpr double kTwoPiLow = 2.4492935982947064e-16;

/// x reduced modulo 2π into [−π, π], with x = hi + lo given as two doubles
/// (|lo| ≪ |hi|): the reduction by the double kTwoPi is exact (std::remainder)
/// and the low part of 2π is added back, so the result keeps ~1e-15 rad.
inline double reduce_angle(double hi, double lo = 0.0) {
  const double r = std::remainder(hi, units::kTwoPi);
  const double turns = std::nearbyint((hi - r) / units::kTwoPi);
  return r + (lo - turns * kTwoPiLow);
}

class CrankMotion {
 public:
  virtual ~CrankMotion() = default;
  /// Crank angle, speed and acceleration at time t (defined for every t).
  virtual CrankState at(double time_s) const = 0;
  /// The state at t = origin_s + tau_s with the angle reduced modulo 2π
  /// (only its sine and cosine are meaningful). Exact to ~1e-15 rad for any
  /// origin in the motions below; this default forms the sum (as precise as at()).
  virtual CrankState at_local(double origin_s, double tau_s) const {
    CrankState c = at(origin_s + tau_s);
    c.angle_rad = reduce_angle(c.angle_rad);
    return c;
  }
  /// The time at which the crank reaches `angle_rad` (monotone motion).
  virtual double time_at_angle(double angle_rad) const = 0;
};

/// Constant speed ω2 ≠ 0 from angle θ0 at t = 0 (thesis assumption, ch. 2).
class ConstantSpeedCrank final : public CrankMotion {
 public:
  ConstantSpeedCrank(double start_angle_rad, double speed_rad_s) : start_(start_angle_rad), speed_(speed_rad_s) {}
  CrankState at(double t) const override { return {start_ + speed_ * t, speed_, 0.0}; }
  CrankState at_local(double origin_s, double tau_s) const override {
    // Within the first 16 turns the plain sum keeps ~1e-14 rad (and short
    // runs bit for bit as before); later ω2·t_o exactly as p + err (fma), p
    // reduced exactly, then θ0 and ω2·τ.
    const double p = speed_ * origin_s;
    if (std::abs(p) < 16 * units::kTwoPi) return at(origin_s + tau_s);
    const double err = std::fma(speed_, origin_s, -p);
    return {reduce_angle(p, err + start_) + speed_ * tau_s, speed_, 0.0};
  }
  double time_at_angle(double angle_rad) const override { return (angle_rad - start_) / speed_; }

 private:
  double start_, speed_;
};

}  // namespace fourbar
