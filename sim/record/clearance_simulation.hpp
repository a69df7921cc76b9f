#pragma once
// The interface both clearance simulators implement — the three-mode
// ClearanceSimulator (sim/three_mode/simulator.hpp) and the compliant
// CompliantSimulator (sim/compliant/compliant_simulator.hpp): start, ask for
// samples and turn records, advance, read the records. Callers take one from
// make_clearance_simulation (sim/run/clearance_simulation.hpp), which makes
// the model choice once (SIM-DESIGN-NOTES §3.3); each simulator's own
// extras (the three-mode start in the following mode, the compliant
// integrator's counters) stay on its class.

#include <vector>

#include "sim/record/link_motion.hpp"
#include "sim/record/run_records.hpp"

namespace fourbar {

class ClearanceSimulation {
 public:
  virtual ~ClearanceSimulation() = default;
  ClearanceSimulation(const ClearanceSimulation&) = delete;
  ClearanceSimulation& operator=(const ClearanceSimulation&) = delete;

  /// Starts at t0 from the nominal mechanism with the pin against the wall
  /// along the nominal bearing force (each model's own reading of that).
  virtual void start_nominal(double t0) = 0;
  /// Starts from a given link motion.
  virtual void start_free(double t0, const LinkMotion& links) = 0;

  /// Times at which samples are wanted (ascending, ≥ the start time); the
  /// samples appear in samples() as the run passes them.
  virtual void set_sample_times(std::vector<double> times) = 0;
  /// Revolution boundaries: crank angle where turn 0 starts (turns follow every 2π).
  virtual void set_revolution_origin(double crank_angle_rad) = 0;
  /// Per-turn RMS of α3 − α3,nominal from `samples_per_turn` samples per
  /// turn, uniform in crank angle (needs set_revolution_origin; 0 = off).
  virtual void set_revolution_statistics(int samples_per_turn) = 0;

  /// Runs until t_end (may be called again with a later time).
  virtual void advance_to(double t_end) = 0;

  virtual double time() const = 0;
  virtual ContactMode mode() const = 0;
  /// Link motion at the current time.
  virtual LinkMotion current_links() = 0;

  virtual const std::vector<ClearanceSample>& samples() const = 0;
  virtual const std::vector<ImpactRecord>& impacts() const = 0;
  virtual const std::vector<RevolutionRecord>& revolutions() const = 0;
  /// Diagnostics up to now (energy terms evaluated at the current time).
  virtual ClearanceDiagnostics diagnostics() = 0;

 protected:
  ClearanceSimulation() = default;
};

}  // namespace fourbar
