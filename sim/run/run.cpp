#include "sim/run/run.hpp"

#include <algorithm>
#include <cmath>

#include "common/progress.hpp"
#include "common/angle_unwrap.hpp"
#include "common/units.hpp"
#include "sim/run/clearance_simulation.hpp"
#include "sim/outputs.hpp"

namespace fourbar {

namespace {

/// α3-deviation samples per turn for the per-turn statistics (every 1°).
constexpr int kStatisticsPerTurn = 360;

/// Largest scaled difference between the turn-start states of turns a and b.
double state_difference(const RevolutionRecord& a, const RevolutionRecord& b) {
  if (a.start_mode != b.start_mode) return 1e300;
  double d = 0;
  for (std::size_t i = 0; i < a.start_state.size(); ++i) d = std::max(d, std::abs(a.start_state[i] - b.start_state[i]));
  return d;
}

}  // namespace

double clearance_column_value(const ClearanceOutputSpec& spec, const ClearanceSample& s, double theta3, double theta4,
                              double eta) {
  switch (spec.extra) {
    case ClearanceExtra::mode: return s.mode == ContactMode::following ? 1.0 : 0.0;
    case ClearanceExtra::gap: return units::m_to_mm(s.gap_m);
    case ClearanceExtra::eta: return units::rad_to_deg(eta);
    case ClearanceExtra::contact_force: return s.normal_force_N;
    case ClearanceExtra::penetration: return units::m_to_mm(s.penetration_m);
    case ClearanceExtra::none: break;
  }
  switch (spec.quantity) {
    case Quantity::time: return s.time_s;
    case Quantity::theta2: return s.crank.angle_rad;
    case Quantity::omega2: return s.crank.speed_rad_s;
    case Quantity::theta3: return theta3;
    case Quantity::theta4: return theta4;
    case Quantity::omega3: return s.links.omega3_rad_s;
    case Quantity::omega4: return s.links.omega4_rad_s;
    case Quantity::alpha3: return s.alpha3_rad_s2;
    case Quantity::alpha4: return s.alpha4_rad_s2;
    case Quantity::transmission: return units::rad_to_deg(std::acos(std::clamp(dot(s.links.u3, s.links.u4), -1.0, 1.0)));
    case Quantity::crank_torque: return s.crank_torque_Nm;
    case Quantity::bearing_fx: return s.bearing_force_N.x;
    case Quantity::bearing_fy: return s.bearing_force_N.y;
    case Quantity::kinetic_energy: return s.kinetic_energy_J;
    case Quantity::potential_energy: return s.potential_energy_J;
    default: return 0.0;  // not offered for the clearance model (scene validation)
  }
}

const char* to_string(SteadyFound f) {
  switch (f) {
    case SteadyFound::none: return "none";
    case SteadyFound::periodic: return "periodic";
    case SteadyFound::statistical: return "statistical";
  }
  return "?";
}

ClearanceRun run_clearance(const Scene& scene, bool progress, int warmup_revolutions) {
  return run_clearance(scene, ConstantSpeedCrank(scene.start_angle_rad, scene.crank_speed_rad_s), progress,
                       warmup_revolutions);
}

namespace {

/// Steady state (cs.steady_state): one turn at a time, at most
/// max_revolutions, until the turn-start state repeats (periodic) or the
/// windows' means agree (statistical). Fills out's steady-state entries;
/// returns the turns run.
template <class TurnTime>
int search_steady_state(const ClearanceSettings& cs, ClearanceSimulation& sim, const TurnTime& turn_time, bool progress,
                        ClearanceRun& out) {
  using Criterion = ClearanceSettings::SteadyCriterion;
  const bool statistical = cs.steady_criterion != Criterion::periodic;
  int first = 0;
  std::vector<TurnQuantities> turns;
  Progress bar("sim: steady-state search (at most " + std::to_string(cs.max_revolutions) + " turns)",
               static_cast<std::uint64_t>(cs.max_revolutions), progress);
  for (int n = 1; n <= cs.max_revolutions; ++n) {
    sim.advance_to(turn_time(n));
    bar.update(static_cast<std::uint64_t>(n));
    first = n;
    const auto& revs = sim.revolutions();
    if (static_cast<int>(revs.size()) <= n) continue;
    if (cs.steady_criterion != Criterion::statistical) {
      double best = 1e300;
      for (int k = 1; k <= cs.max_period && n - 2 * k + 1 >= 0; ++k) {
        // Converged when each of the last k turn starts repeats the one k turns earlier.
        double worst = 0;
        for (int j = 0; j < k; ++j) worst = std::max(worst, state_difference(revs[n - j], revs[n - j - k]));
        best = std::min(best, worst);
        if (worst <= cs.steady_tolerance) {
          out.steady_found = SteadyFound::periodic;
          out.steady_period = k;
          break;
        }
      }
      out.steady_difference = best;
      if (out.steady_found != SteadyFound::none) break;
    }
    if (statistical) {
      const RevolutionRecord& r = revs[n - 1];  // the turn just completed
      const double span = r.end_time_s - r.start_time_s;
      turns.push_back({{static_cast<double>(r.impacts), r.sum_normal_impulse_Ns, r.following_time_s / span,
                        r.alpha3_deviation_rms_rad_s2}});
      out.statistics = compare_windows(turns, cs.statistical_window, cs.statistical_tolerance);
      if (out.statistics.steady) {
        out.steady_found = SteadyFound::statistical;
        break;
      }
    }
  }
  return first;
}

/// The series table: crank_deg and the scene's outputs, the link and contact
/// angles made continuous from row to row.
SeriesTable clearance_series(const Scene& scene, const std::vector<ClearanceSample>& samples) {
  SeriesTable series;
  std::vector<const ClearanceOutputSpec*> specs;
  for (const auto& name : scene.outputs) specs.push_back(find_clearance_output(name));
  series.names.push_back("crank_deg");
  for (const auto& name : scene.outputs) series.names.push_back(name);
  series.columns.assign(series.names.size(), std::vector<double>(samples.size()));
  double th3 = 0, th4 = 0, eta = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ClearanceSample& s = samples[i];
    const double a3 = std::atan2(s.links.u3.y, s.links.u3.x), a4 = std::atan2(s.links.u4.y, s.links.u4.x);
    th3 = i ? units::unwrap_rad(a3, th3) : a3;
    th4 = i ? units::unwrap_rad(a4, th4) : a4;
    eta = i ? units::unwrap_rad(s.eta_rad, eta) : s.eta_rad;
    series.columns[0][i] = units::rad_to_deg(s.crank.angle_rad);
    for (std::size_t c = 0; c < specs.size(); ++c)
      series.columns[c + 1][i] = clearance_column_value(*specs[c], s, th3, th4, eta);
  }
  return series;
}

/// The run on either clearance simulator.
ClearanceRun run_with(const Scene& scene, const CrankMotion& crank, ClearanceSimulation& sim, bool progress, int warmup) {
  using Criterion = ClearanceSettings::SteadyCriterion;
  const ClearanceSettings& cs = scene.clearance;
  ClearanceRun out;
  out.clearance_m = scene.clearance_m();
  const CrankState c0 = crank.at(0.0);
  const double dir = c0.speed_rad_s > 0 ? 1.0 : -1.0;
  auto turn_time = [&](double turns) { return crank.time_at_angle(c0.angle_rad + dir * units::kTwoPi * turns); };

  sim.set_revolution_origin(c0.angle_rad);
  const bool statistical = cs.steady_state && cs.steady_criterion != Criterion::periodic;
  if (statistical || cs.write_revolutions) sim.set_revolution_statistics(kStatisticsPerTurn);
  sim.start_nominal(0.0);

  int first = 0;
  out.statistics.worst_relative_difference = 1e300;
  if (!cs.steady_state && warmup > 0) {  // warm-up turns, not output
    sim.advance_to(turn_time(warmup));
    first = warmup;
  }
  if (cs.steady_state) first = search_steady_state(cs, sim, turn_time, progress, out);
  out.steady_state_reached = out.steady_found != SteadyFound::none;
  out.first_output_revolution = first;

  // Output samples: revolutions × samples_per_revolution + 1, uniform in crank angle.
  const std::size_t n = static_cast<std::size_t>(scene.revolutions) * scene.samples_per_revolution + 1;
  std::vector<double> times(n);
  for (std::size_t i = 0; i < n; ++i) times[i] = turn_time(first + static_cast<double>(i) / scene.samples_per_revolution);
  times[0] = std::max(times[0], sim.time());
  sim.set_sample_times(times);
  sim.advance_to(turn_time(first + scene.revolutions));
  out.revolutions_simulated = first + scene.revolutions;

  out.series = clearance_series(scene, sim.samples());
  out.impacts = sim.impacts();
  out.revolutions = sim.revolutions();
  if (static_cast<int>(out.revolutions.size()) > out.revolutions_simulated)
    out.revolutions.resize(out.revolutions_simulated);
  out.diagnostics = sim.diagnostics();
  return out;
}

}  // namespace

ClearanceRun run_clearance(const Scene& scene, const CrankMotion& crank, bool progress, int warmup_revolutions) {
  const ClearanceModel model(*scene.rig, scene.clearance_m());
  const std::unique_ptr<ClearanceSimulation> sim = make_clearance_simulation(model, crank, scene.clearance);
  return run_with(scene, crank, *sim, progress, warmup_revolutions);
}

}  // namespace fourbar
