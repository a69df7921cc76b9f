#include "acquire/revolution_plan.hpp"

#include <algorithm>
#include <cmath>

#include "acquire/crank_angle.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

/// One plan per revolution of one segment, on the crank motion through its pulses.
void plan_segment(const PulseTrain& train, std::size_t s, RevolutionSchedule& schedule) {
  const std::vector<Pulse>& pulses = train.segments[s];
  std::vector<double> times;
  for (const auto& p : pulses) times.push_back(p.time_s);
  const CrankAngleModel model(times);
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    RevolutionPlan r;
    r.segment = s;
    r.curve = model.revolution(k);
    r.t_start = times[k], r.t_end = times[k + 1];
    r.repaired = pulses[k].inserted || pulses[k + 1].inserted;
    schedule.revolutions_repaired += r.repaired;
    schedule.plan.push_back(r);
  }
}

/// The same on a spline smoothed across turns: revolutions run between the
/// fitted times of the pulses (where the fitted angle is a whole turn).
void plan_smoothed_segment(const PulseTrain& train, std::size_t s, std::size_t knot_spacing,
                           RevolutionSchedule& schedule) {
  const std::vector<Pulse>& pulses = train.segments[s];
  std::vector<double> times, phases;
  for (std::size_t k = 0; k < pulses.size(); ++k)
    times.push_back(pulses[k].time_s), phases.push_back(units::kTwoPi * static_cast<double>(k));
  const SmoothedSegment smooth = smooth_segment(times, phases, knot_spacing, 0);
  schedule.smoothing.add(smooth.fit);
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    RevolutionPlan r;
    r.segment = s;
    r.t_start = smooth.track->knot(k).time_s, r.t_end = smooth.track->knot(k + 1).time_s;
    r.curve.t0 = r.t_start, r.curve.h = r.t_end - r.t_start, r.curve.inv_h = 1 / r.curve.h;
    r.curve.phase0_rad = phases[k];
    r.track = smooth.track;
    r.repaired = pulses[k].inserted || pulses[k + 1].inserted;
    schedule.revolutions_repaired += r.repaired;
    schedule.plan.push_back(std::move(r));
  }
}

}  // namespace

RevolutionSchedule plan_revolutions(const PulseTrain& train, double sample_rate_hz, int grid_points_per_rev,
                                    double smoothing_period_turns) {
  RevolutionSchedule schedule;
  if (smoothing_period_turns > 0) {
    const std::size_t knots = smoothing_knot_spacing(smoothing_period_turns, 1);
    schedule.smoothing.period_turns = smoothing_period_turns;
    schedule.smoothing.knot_spacing_turns = static_cast<double>(knots);
    // A run of pulses too short to show its jitter (a piece between gaps) goes through every pulse.
    for (std::size_t s = 0; s < train.segments.size(); ++s)
      if (train.segments[s].size() >= kSmoothingMinBlockEdges) plan_smoothed_segment(train, s, knots, schedule);
      else plan_segment(train, s, schedule);
  } else {
    for (std::size_t s = 0; s < train.segments.size(); ++s) plan_segment(train, s, schedule);
  }
  finish_schedule(schedule, train.typical_period_s, sample_rate_hz, grid_points_per_rev);
  return schedule;
}

void finish_schedule(RevolutionSchedule& schedule, double typical_period_s, double sample_rate_hz,
                     int grid_points_per_rev) {
  schedule.frames_per_rev = typical_period_s * sample_rate_hz;
  schedule.grid_points_per_rev =
      grid_points_per_rev > 0
          ? grid_points_per_rev
          : kGridPointsStep * static_cast<int>(std::ceil(std::max(1.0, schedule.frames_per_rev) / kGridPointsStep));
  schedule.speed = speed_stats(schedule.plan);
}

SpeedStats speed_stats(const std::vector<RevolutionPlan>& plan) {
  double sum = 0, sum_sq = 0, mn = INFINITY, mx = 0;
  for (const auto& r : plan) {
    const double rpm = 60.0 / (r.t_end - r.t_start);
    sum += rpm, sum_sq += rpm * rpm, mn = std::min(mn, rpm), mx = std::max(mx, rpm);
  }
  const double n = static_cast<double>(plan.size());
  return {sum / n, std::sqrt(std::max(0.0, sum_sq / n - (sum / n) * (sum / n))), mn, mx};
}

}  // namespace fourbar
