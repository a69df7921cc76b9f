#include "compare/linkage_theory.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "analyze/conversion.hpp"
#include "analyze/link_motion.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/drive/crank_motion.hpp"
#include "sim/linkage/linkage_simulator.hpp"

namespace fourbar {

LinkageSpec bearing_clearance_spec(const Rig& rig, double clearance_m, double stiffness_N_per_m_n, double restitution,
                                   double friction_coefficient, double tolerance) {
  const CompliantSettings k;  // exponent 1.5, calibrated damping, the friction ramp's speeds
  LinkageSpec spec;
  spec.clearance_m = {0.0, clearance_m, 0.0};
  spec.law = {stiffness_N_per_m_n, k.exponent, k.damping, restitution};
  spec.friction = {friction_coefficient, k.friction_stick_speed_m_s, k.friction_slip_speed_m_s};
  spec.damping_floor_speed_m_s = k.damping_floor_speed_m_s;
  spec.elastic = {false, rig.coupler_elastic.has_value(), rig.rocker_elastic.has_value()};
  spec.tolerance = tolerance;
  return spec;
}

MatchedTheory simulate_linkage_theory(const LinkageModel& linkage, const LinkageTheoryRun& run) {
  const Rig& rig = linkage.rig();
  const CrankGrid& grid = run.grid;
  const std::size_t n = grid.grid_points_per_rev;
  const double w = run.crank_speed_rad_s;
  if (n == 0 || run.turns < 1 || run.warmup_turns < 0)
    throw RunError(run.name + ": the linkage theory needs a grid and at least one turn (internal error)");
  if (!(grid.direction * w > 0))
    throw RunError(run.name + ": the grid turns against the crank speed (internal error)");
  // Grid point k of the run is at t = 2πk/(N·|ω2|).
  const double step_s = units::kTwoPi / (static_cast<double>(n) * std::abs(w));
  const std::size_t first = static_cast<std::size_t>(run.warmup_turns) * n;
  const std::size_t rows = static_cast<std::size_t>(run.turns) * n;
  const std::size_t sub = static_cast<std::size_t>(std::max(run.sub_samples, 1));
  if (sub > 1 && run.warmup_turns < 1)
    throw RunError(run.name + ": cell means need a warm-up turn (internal error)");
  // Sample i: grid point i / sub (less half a cell for cell means).
  const std::size_t points = sub > 1 ? rows * sub + 1 : rows;
  const double shift = sub > 1 ? 0.5 : 0.0;
  std::vector<double> times(points);
  for (std::size_t i = 0; i < points; ++i)
    times[i] = (static_cast<double>(first) + static_cast<double>(i) / static_cast<double>(sub) - shift) * step_s;

  std::vector<LinkSensor> sensors;
  std::array<int, 2> sensor_index{-1, -1};
  for (std::size_t i = 0; i < 2; ++i)
    if (run.sensor[i]) {
      sensor_index[i] = static_cast<int>(sensors.size());
      sensors.push_back({i == 0 ? 1 : 2, run.sensor[i]->r_m, run.sensor[i]->h_m});
    }
  const ConstantSpeedCrank crank(grid.start_rad, w);
  LinkageSimulator sim(linkage, crank);
  sim.set_sample_times(times);
  sim.set_sensors(sensors);
  sim.start_centred(0.0);
  sim.advance_to(times.back());
  const std::vector<LinkageSample>& samples = sim.samples();
  if (samples.size() != points)
    throw RunError(run.name + ": the linkage model gave " + std::to_string(samples.size()) + " of " +
                   std::to_string(points) + " samples");

  MatchedTheory th;
  th.grid = grid;
  th.crank_speed_rad_s = w;
  th.clearance_m = run.clearance_m;
  for (TheorySeries& s : th.series) s.nominal.resize(n), s.clearance_revolutions.resize(rows);
  auto series = [&](LinkQuantity q) -> TheorySeries& { return th.series[index_of(q)]; };
  for (std::size_t k = 0; k < n; ++k) {
    const NominalMotion m = solve_motion(rig, CrankState{grid.angle_rad(static_cast<double>(k)), w, 0.0});
    series(LinkQuantity::omega3).nominal[k] = m.omega3_rad_s, series(LinkQuantity::omega4).nominal[k] = m.omega4_rad_s;
    series(LinkQuantity::alpha3).nominal[k] = m.alpha3_rad_s2, series(LinkQuantity::alpha4).nominal[k] = m.alpha4_rad_s2;
  }
  // Each link's α at a sample: what analyze makes of the reading there (the
  // nominal link at this crank state), else the rigid frame's.
  auto alpha_at = [&](const LinkageSample& s, std::size_t i) {
    if (sensor_index[i] < 0) return i == 0 ? s.alpha3_rad_s2 : s.alpha4_rad_s2;
    const SensedLink link = i == 0 ? SensedLink::coupler : SensedLink::rocker;
    const SensedLinkMotion nominal = nominal_link_motion(rig, link, s.crank);
    return angular_acceleration_from_tangential(rig, *run.sensor[i], nominal,
                                                s.sensor_m_s2[static_cast<std::size_t>(sensor_index[i])]);
  };
  for (std::size_t j = 0; j < rows; ++j) {
    if (sub == 1) {
      const LinkageSample& s = samples[j];
      series(LinkQuantity::omega3).clearance_revolutions[j] = s.omega3_rad_s;
      series(LinkQuantity::omega4).clearance_revolutions[j] = s.omega4_rad_s;
      series(LinkQuantity::alpha3).clearance_revolutions[j] = alpha_at(s, 0);
      series(LinkQuantity::alpha4).clearance_revolutions[j] = alpha_at(s, 1);
      continue;
    }
    // The cell's mean: ω at its point (its centre sample), α by the trapezoid rule.
    const LinkageSample& mid = samples[j * sub + sub / 2];
    series(LinkQuantity::omega3).clearance_revolutions[j] = mid.omega3_rad_s;
    series(LinkQuantity::omega4).clearance_revolutions[j] = mid.omega4_rad_s;
    for (std::size_t i = 0; i < 2; ++i) {
      double sum = 0;
      for (std::size_t m = 0; m <= sub; ++m) sum += (m == 0 || m == sub ? 0.5 : 1.0) * alpha_at(samples[j * sub + m], i);
      series(i == 0 ? LinkQuantity::alpha3 : LinkQuantity::alpha4).clearance_revolutions[j] = sum / static_cast<double>(sub);
    }
  }
  const double warm_s = static_cast<double>(first) * step_s;
  int impacts = 0;
  double impulse = 0;
  for (const LinkageContact& c : sim.contacts())
    if (c.impact && c.time_s >= warm_s) ++impacts, impulse += c.impact_impulse_Ns;
  th.severity.impacts_per_rev = impacts / static_cast<double>(run.turns);
  th.severity.sum_normal_impulse_per_rev_Ns = impulse / static_cast<double>(run.turns);
  return th;
}

}  // namespace fourbar
