#include "acquire/revolution_plan.hpp"

#include <algorithm>
#include <cmath>

#include "acquire/crank_angle.hpp"

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

}  // namespace

RevolutionSchedule plan_revolutions(const PulseTrain& train, double sample_rate_hz, int grid_points_per_rev) {
  RevolutionSchedule schedule;
  for (std::size_t s = 0; s < train.segments.size(); ++s) plan_segment(train, s, schedule);
  schedule.frames_per_rev = train.typical_period_s * sample_rate_hz;
  schedule.grid_points_per_rev =
      grid_points_per_rev > 0
          ? grid_points_per_rev
          : kGridPointsStep * static_cast<int>(std::ceil(std::max(1.0, schedule.frames_per_rev) / kGridPointsStep));
  schedule.speed = speed_stats(schedule.plan);
  return schedule;
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
