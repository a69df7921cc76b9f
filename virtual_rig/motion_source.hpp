#pragma once
// Where the virtual rig's motion comes from. A MotionSource gives the state
// of all three moving links at any time; the nominal mechanism driven by a
// (possibly fluctuating) crank is one, the clearance simulator will be
// another (it only has to implement `at`).

#include <memory>
#include <vector>

#include "mechanism/kinematics.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

/// Angles, rates and accelerations of crank, coupler and rocker at one time.
/// Angles are continuous only within what `at` guarantees; the sensor model
/// uses them through sin/cos.
struct LinkState {
  double time_s = 0;
  CrankState crank;                                        ///< θ2, ω2, α2
  double theta3_rad = 0, omega3_rad_s = 0, alpha3_rad_s2 = 0;
  double theta4_rad = 0, omega4_rad_s = 0, alpha4_rad_s2 = 0;
};

class MotionSource {
 public:
  virtual ~MotionSource() = default;
  /// The state at `time_s`; must accept times before 0 (the virtual rig runs
  /// AC-coupling filters in from a few time constants before the recording).
  virtual LinkState at(double time_s) const = 0;
};

/// The crank's prescribed motion: mean speed ω0 (sign = direction) with a
/// sinusoidal speed fluctuation of relative amplitude ε and period T:
///   ω2(t) = ω0·(1 + ε·sin(2πt/T)),  θ2(t) = θ0 + ω0·t + ε·ω0·T/(2π)·(1 − cos(2πt/T)).
struct CrankDrive {
  double start_angle_rad = 0;    ///< θ0
  double mean_speed_rad_s = 0;   ///< ω0, negative for clockwise
  double fluctuation = 0;        ///< ε (0.02 for ±2 %)
  double fluctuation_period_s = 1;
  /// Relative speed change at h = 1, 2, … times the mean turn rate ω0/2π
  /// (a speed change within the turn): ω2 += ω0·a_h·sin(h·ω0·t + h).
  std::vector<double> harmonics;

  CrankState at(double time_s) const;
  /// The time at which θ2 − θ0 = `turned_rad` (same sign as ω0), by Newton.
  double time_at_turned(double turned_rad) const;
};

/// The nominal (clearance-free) mechanism following a CrankDrive, in closed
/// form (thesis eq. 2.1-1 … 2.1-3 with α2 ≠ 0).
class NominalMotionSource final : public MotionSource {
 public:
  NominalMotionSource(std::shared_ptr<const Rig> rig, CrankDrive drive);
  LinkState at(double time_s) const override;
  const CrankDrive& drive() const { return drive_; }

 private:
  std::shared_ptr<const Rig> rig_;
  CrankDrive drive_;
};

}  // namespace fourbar
