#pragma once
// Pipeline stage "clearance run": a scene with model = "clearance" through the
// three-mode simulator; the requested per-sample series (uniform in crank
// angle), the impact and revolution records, and the run's diagnostics.
// With steady_state, turns are simulated until the state at the start of a
// turn repeats that of k turns before (k ≤ max_period: periodic), or the
// per-turn quantities' means over two consecutive windows of W turns agree
// (statistical), as `steady_criterion` allows, at most max_revolutions turns;
// the `revolutions` requested are those that follow.

#include <vector>

#include "sim/three_mode/simulator.hpp"
#include "sim/run/stationarity.hpp"
#include "sim/nominal/run.hpp"
#include "sim/outputs.hpp"
#include "sim/scene.hpp"

namespace fourbar {

/// Which steady state ended the search, if any.
enum class SteadyFound { none, periodic, statistical };
const char* to_string(SteadyFound f);

struct ClearanceRun {
  SeriesTable series;
  std::vector<ImpactRecord> impacts;
  std::vector<RevolutionRecord> revolutions;
  ClearanceDiagnostics diagnostics;
  double clearance_m = 0;
  int revolutions_simulated = 0;
  int first_output_revolution = 0;  ///< turn index of the first output sample
  bool steady_state_reached = false;
  SteadyFound steady_found = SteadyFound::none;
  int steady_period = 0;            ///< k (turns), when periodic
  double steady_difference = 0;     ///< the scaled state difference found at the last check
  /// Statistical criterion at the last check: the two windows' means and
  /// their worst relative difference (1e300 before 2W turns).
  StationarityResult statistics;
};

/// `progress`: a progress line on stderr (a terminal only) through the
/// steady-state search, turn by turn; the results do not depend on it.
/// `warmup_revolutions`: without steady_state, turns run first and not
/// output (the report's matched theory runs 20); the output then starts at
/// first_output_revolution = warmup_revolutions. Ignored with steady_state
/// (the search decides where the output starts).
ClearanceRun run_clearance(const Scene& scene, bool progress = false, int warmup_revolutions = 0);
/// The same at a given crank motion (e.g. a MeasuredSpeedCrank) instead of
/// the scene's constant speed; turns count from the crank angle at t = 0.
ClearanceRun run_clearance(const Scene& scene, const CrankMotion& crank, bool progress = false,
                           int warmup_revolutions = 0);

/// Column value of one sample for a clearance output (see sim/outputs.hpp).
double clearance_column_value(const ClearanceOutputSpec& spec, const ClearanceSample& s, double theta3_cont,
                              double theta4_cont, double eta_cont);

}  // namespace fourbar
