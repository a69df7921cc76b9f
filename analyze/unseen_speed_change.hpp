#pragma once
// What one crank pulse per turn cannot see: a crank-speed change that repeats
// every turn. The pulse times are the same with or without it, so acquire
// takes the speed as constant within the turn (α2 = 0) and the angle as
// uniform in time between pulses. The conversion (conversion.hpp) then uses
// the wrong crank-pin acceleration, and each sample lands at the wrong crank
// angle on the grid. Both errors repeat every turn: averaging keeps them.
//
// This file computes that error for a given rig, sensor and speed by the
// forward model, without linearising: for a true crank speed
//   ω2(θ2) = ω̄·(1 + Σ_k a_k·sin(k·θ2 + φ_k))
// the true time of every crank angle is t(θ2) = ∫ dθ2/ω2 from the turn's
// pulse; the analysis puts the sample taken at time t at the assumed angle
// θ2 = pulse angle + 360°·t/T (T the true turn time). At each grid angle the
// sensor reads the true motion (sensor_reading at the true angle, speed and
// α2 = ω2·dω2/dθ2); the analysis converts it with {assumed angle, ω̄, 0}.
// Error = converted − the link's true α at that grid angle (the virtual rig's
// truth). ω follows by integrating the error over the turn's time, its mean
// removed (the per-turn integration sets the mean).

#include <optional>
#include <span>
#include <vector>

#include "analyze/sensor_mount.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

/// One harmonic of the crank speed within the turn: relative amplitude
/// (0.005 = 0.5 %) at crank order `order`, phase in crank angle.
struct SpeedHarmonic {
  int order = 1;
  double amplitude = 0;
  double phase_rad = 0;
};

/// RMS of the averaged α (ω) error over the turn / RMS of the true α (ω).
struct UnseenSpeedError {
  double alpha_rel_rms = 0, omega_rel_rms = 0;
};

/// The error one pulse per turn leaves in the averaged α and ω of the link a
/// tangential sensor at `mount` measures, for a crank turning at the signed
/// mean speed `mean_speed_rad_s` (negative: clockwise) with these in-turn
/// harmonics; `pulse_angle_rad` is the crank angle at the pulse. `points`
/// grid angles per turn.
UnseenSpeedError unseen_speed_error(const Rig& rig, const AccelerometerMount& mount, double mean_speed_rad_s,
                                    double pulse_angle_rad, std::span<const SpeedHarmonic> harmonics,
                                    std::size_t points = 720);

/// The report's statement for a one-pulse recording: the worst error over the
/// phase of a once- and a twice-per-turn speed change of `amplitude` each.
struct UnseenSpeedSensitivity {
  double amplitude = 0.001;                ///< the change the figures are for (0.1 %)
  UnseenSpeedError once_per_turn, twice_per_turn;  ///< worst over the phase
};

UnseenSpeedSensitivity unseen_speed_sensitivity(const Rig& rig, const AccelerometerMount& mount,
                                                double mean_speed_rad_s, double pulse_angle_rad,
                                                double amplitude = 0.001);

}  // namespace fourbar
