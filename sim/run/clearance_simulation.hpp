#pragma once
// The clearance simulator a scene or a theory asks for, chosen once
// (SIM-DESIGN-NOTES §3.3): the compliant model when settings.model is
// compliant (its stiffness resolved), else the three-mode model. The model
// and the crank motion must outlive the simulation.

#include <memory>

#include "sim/drive/crank_motion.hpp"
#include "sim/record/clearance_simulation.hpp"
#include "sim/three_mode/model.hpp"
#include "sim/three_mode/settings.hpp"

namespace fourbar {

std::unique_ptr<ClearanceSimulation> make_clearance_simulation(const ClearanceModel& model, const CrankMotion& crank,
                                                               const ClearanceSettings& settings);

}  // namespace fourbar
