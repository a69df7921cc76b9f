#include "sim/run/clearance_simulation.hpp"

#include "sim/compliant/compliant_simulator.hpp"
#include "sim/three_mode/simulator.hpp"

namespace fourbar {

std::unique_ptr<ClearanceSimulation> make_clearance_simulation(const ClearanceModel& model, const CrankMotion& crank,
                                                               const ClearanceSettings& settings) {
  if (settings.model == ClearanceKind::compliant) return std::make_unique<CompliantSimulator>(model, crank, settings);
  return std::make_unique<ClearanceSimulator>(model, crank, settings);
}

}  // namespace fourbar
