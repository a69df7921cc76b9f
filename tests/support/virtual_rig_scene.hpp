#pragma once
// Pieces of the virtual-rig scenes that the session tests (fit, report) record
// their recordings from, and the recording itself, as a user makes it.

#include <filesystem>
#include <string>

#include "support/run_command.hpp"

namespace fourbar::testing {

/// One `[[recording.sensor]]` table: a sensor NAME with ROLE at POSITION_MM
/// along its link, 2 mV per m/s².
inline std::string sensor_toml(const std::string& name, const std::string& role, double position_mm) {
  return "[[recording.sensor]]\nname = \"" + name + "\"\nrole = \"" + role + "\"\nposition_mm = " +
         std::to_string(position_mm) + "\nvolts_per_unit = 0.002\n";
}

/// The two tangential accelerometers of a session: `coupler_t` on the
/// coupler and `rocker_t` on the rocker.
inline std::string tangential_sensors_toml(double coupler_position_mm, double rocker_position_mm) {
  return sensor_toml("coupler_t", "coupler_tangential", coupler_position_mm) +
         sensor_toml("rocker_t", "rocker_tangential", rocker_position_mm);
}

/// `fourbar virtual-rig SCENE --no-truth --out RECORDING` (the recording and
/// its manifest, no truth files).
inline CommandResult record_virtual(const std::filesystem::path& scene, const std::filesystem::path& recording) {
  return run_fourbar("virtual-rig " + scene.string() + " --no-truth --out " + recording.string());
}

}  // namespace fourbar::testing
