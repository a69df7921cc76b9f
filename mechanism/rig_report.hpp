#pragma once
// What a technician wants to know about a rig before running it.

#include <nlohmann/json.hpp>

#include "mechanism/rig.hpp"

namespace fourbar {

struct RigReport {
  GrashofClass grashof;
  double transmission_min_deg = 0, transmission_max_deg = 0;  ///< over a full crank turn
  double transmission_min_at_crank_deg = 0, transmission_max_at_crank_deg = 0;
  double rocker_swing_deg = 0;  ///< rocker range of motion
};

/// Evaluates the rig over a full crank turn at 0.1° steps.
RigReport report_rig(const Rig& rig);

nlohmann::json to_json(const Rig& rig, const RigReport& report);

}  // namespace fourbar
