#pragma once
// Test helpers: a clearance simulation at constant crank speed from the
// nominal start, for a number of turns, optionally sampled uniformly; a
// clearance scene of the thesis rig at 350 rpm.

#include <cmath>
#include <vector>

#include "common/units.hpp"
#include <memory>

#include "sim/three_mode/simulator.hpp"
#include "sim/scene.hpp"

namespace fourbar::testing {

struct RunResult {
  ClearanceDiagnostics d;
  std::vector<ImpactRecord> impacts;
  std::vector<ClearanceSample> samples;
  ContactMode final_mode;
};

inline RunResult run_turns(const Rig& rig, double xi, double rpm, double start_deg, double turns,
                           const ClearanceSettings& s, int samples_per_turn = 0) {
  const ClearanceModel model(rig, xi);
  const ConstantSpeedCrank crank(units::deg_to_rad(start_deg), units::rpm_to_rad_s(rpm));
  ClearanceSimulator sim(model, crank, s);
  const double period = units::kTwoPi / std::abs(units::rpm_to_rad_s(rpm));
  if (samples_per_turn > 0) {
    std::vector<double> t;
    for (int i = 0; i <= turns * samples_per_turn; ++i) t.push_back(i * period / samples_per_turn);
    sim.set_sample_times(t);
  }
  sim.start_nominal(0.0);
  sim.advance_to(turns * period);
  return {sim.diagnostics(), sim.impacts(), sim.samples(), sim.mode()};
}

/// Thesis rig, 350 rpm, one output turn of 36 samples of `outputs`, with `settings`.
inline Scene thesis_clearance_scene(const ClearanceSettings& settings, std::vector<std::string> outputs) {
  Scene s;
  s.rig = std::make_shared<const Rig>(thesis_rig());
  s.model = Model::clearance;
  s.crank_speed_rad_s = units::rpm_to_rad_s(350);
  s.revolutions = 1;
  s.samples_per_revolution = 36;
  s.outputs = std::move(outputs);
  s.clearance = settings;
  return s;
}

}  // namespace fourbar::testing
