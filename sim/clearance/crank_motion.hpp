#pragma once
// The prescribed crank motion θ2(t), ω2(t), α2(t). The clearance model asks
// only through this interface, so a measured speed profile can replace the
// constant speed without touching the simulator.

#include "sim/nominal/kinematics.hpp"

namespace fourbar {

class CrankMotion {
 public:
  virtual ~CrankMotion() = default;
  /// Crank angle, speed and acceleration at time t (defined for every t).
  virtual CrankState at(double time_s) const = 0;
  /// The time at which the crank reaches `angle_rad` (monotone motion).
  virtual double time_at_angle(double angle_rad) const = 0;
};

/// Constant speed ω2 ≠ 0 from angle θ0 at t = 0 (thesis assumption, ch. 2).
class ConstantSpeedCrank final : public CrankMotion {
 public:
  ConstantSpeedCrank(double start_angle_rad, double speed_rad_s) : start_(start_angle_rad), speed_(speed_rad_s) {}
  CrankState at(double t) const override { return {start_ + speed_ * t, speed_, 0.0}; }
  double time_at_angle(double angle_rad) const override { return (angle_rad - start_) / speed_; }

 private:
  double start_, speed_;
};

}  // namespace fourbar
