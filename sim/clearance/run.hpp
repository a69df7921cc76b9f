#pragma once
// Pipeline stage "clearance run": a scene with model = "clearance" through the
// three-mode simulator; the requested per-sample series (uniform in crank
// angle), the impact and revolution records, and the run's diagnostics.
// With steady_state, turns are simulated until the state at the start of a
// turn repeats that of k turns before (k ≤ max_period), and the `revolutions`
// requested are those that follow.

#include <vector>

#include "sim/clearance/simulator.hpp"
#include "sim/nominal/run.hpp"
#include "sim/outputs.hpp"
#include "sim/scene.hpp"

namespace fourbar {

struct ClearanceRun {
  SeriesTable series;
  std::vector<ImpactRecord> impacts;
  std::vector<RevolutionRecord> revolutions;
  ClearanceDiagnostics diagnostics;
  double clearance_m = 0;
  int revolutions_simulated = 0;
  int first_output_revolution = 0;  ///< turn index of the first output sample
  bool steady_state_reached = false;
  int steady_period = 0;            ///< k (turns), when reached
  double steady_difference = 0;     ///< the scaled state difference found at the last check
};

ClearanceRun run_clearance(const Scene& scene);

/// Column value of one sample for a clearance output (see sim/outputs.hpp).
double clearance_column_value(const ClearanceOutputSpec& spec, const ClearanceSample& s, double theta3_cont,
                              double theta4_cont, double eta_cont);

}  // namespace fourbar
