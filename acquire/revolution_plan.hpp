#pragma once
// From the pulse train to the revolutions to build: the crank motion fitted
// through each segment's pulses (crank_angle.hpp) gives one RevolutionPlan
// per complete revolution; the typical revolution sets the crank-angle grid
// size N; and the speed statistics over the kept revolutions.

#include <cstddef>
#include <vector>

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
};

/// `grid_points_per_rev` 0: the smallest multiple of kGridPointsStep not
/// below frames_per_rev.
RevolutionSchedule plan_revolutions(const PulseTrain& train, double sample_rate_hz, int grid_points_per_rev);

/// Mean, standard deviation, min and max of the revolutions' speeds (rpm).
SpeedStats speed_stats(const std::vector<RevolutionPlan>& plan);

}  // namespace fourbar
