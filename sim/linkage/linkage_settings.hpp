#pragma once
// The scene's [linkage] table (model = "linkage"): the clearance of each
// joint, the compliant contact law's keys (shared with [clearance]
// model = "compliant": sim/three_mode/compliant_settings.cpp reads them), the
// tolerance, and optionally a tabulated crank motion. Keys in
// docs/linkage-model.md.

#include <filesystem>
#include <optional>

#include "common/toml_section.hpp"
#include "mechanism/rig.hpp"
#include "sim/linkage/linkage_model.hpp"
#include "sim/linkage/linkage_sensor.hpp"

namespace fourbar {

struct LinkageSettings {
  LinkageSpec spec;
  /// `crank_motion`: a CSV time_s,crank_rad,crank_rad_s (resolved against the
  /// scene's folder); empty: the scene's constant crank speed.
  std::filesystem::path crank_table;
  /// `duration_s` with a crank table (default: the table's length).
  std::optional<double> duration_s;
  /// `coupler_sensors_mm`, `rocker_sensors_mm`: (distance from the link's
  /// first joint, lateral offset) pairs; each adds a tangential-reading column.
  std::vector<LinkSensor> sensors;
};

/// Reads and validates the section; InputError naming the key otherwise.
LinkageSettings read_linkage_settings(TomlSection& section, const Rig& rig);

}  // namespace fourbar
