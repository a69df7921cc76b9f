#pragma once
// From the pulse train to the revolutions to build: the crank motion fitted
// through each segment's pulses (crank_angle.hpp) gives one RevolutionPlan
// per complete revolution; the typical revolution sets the crank-angle grid
// size N; and the speed statistics over the kept revolutions.

#include <cstddef>
#include <vector>

#include "acquire/crank_smoothing.hpp"
#include "acquire/pulse_train.hpp"
#include "acquire/revolution_builder.hpp"

namespace fourbar {

struct SpeedStats {
  double mean_rpm = 0, std_rpm = 0, min_rpm = 0, max_rpm = 0;
};

/// N defaults to a whole number of degrees (a grid point on every degree).
inline constexpr int kGridPointsStep = 360;

struct RevolutionSchedule {
  std::vector<RevolutionPlan> plan;       ///< every complete revolution, time order
  std::size_t revolutions_repaired = 0;   ///< starting or ending at an inserted pulse
  double frames_per_rev = 0;              ///< recording frames in a typical revolution
  int grid_points_per_rev = 0;            ///< N
  SpeedStats speed;
  CrankSmoothingReport smoothing;         ///< crank_smoothing = "spline": how the fit meets the edges
};

/// `grid_points_per_rev` 0: the smallest multiple of kGridPointsStep not
/// below frames_per_rev. `smoothing_period_turns` > 0: each segment's crank
/// motion smoothed across turns (crank_smoothing.hpp) instead of through
/// every pulse; check schedule.smoothing with require_smoothing_fits.
RevolutionSchedule plan_revolutions(const PulseTrain& train, double sample_rate_hz, int grid_points_per_rev,
                                    double smoothing_period_turns = 0);

/// frames_per_rev, N and the speed statistics once the plan is made.
void finish_schedule(RevolutionSchedule& schedule, double typical_period_s, double sample_rate_hz,
                     int grid_points_per_rev);

/// Mean, standard deviation, min and max of the revolutions' speeds (rpm).
SpeedStats speed_stats(const std::vector<RevolutionPlan>& plan);

}  // namespace fourbar
