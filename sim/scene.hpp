#pragma once
// A scene: what to compute for which rig. Immutable once loaded.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <optional>

#include <toml++/toml.h>

#include "sim/three_mode/settings.hpp"
#include "sim/linkage/linkage_settings.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

enum class Model { nominal, clearance, linkage };

struct Scene {
  std::shared_ptr<const Rig> rig;
  std::filesystem::path source;       ///< the scene file (may be empty)
  Model model = Model::nominal;
  double crank_speed_rad_s = 0;       ///< ω2, constant (0 with a linkage crank table)
  double start_angle_rad = 0;         ///< θ2 at t = 0
  int revolutions = 1;
  int samples_per_revolution = 360;   ///< output sampling (rows per turn)
  std::vector<std::string> outputs;   ///< requested per-sample columns, in order
  /// `[clearance]` table (model = "clearance" only); the clearance used is
  /// `clearance.radial_clearance_m` or else the rig's.
  ClearanceSettings clearance;
  double clearance_m() const { return clearance.radial_clearance_m.value_or(rig->radial_clearance_m); }
  /// `[linkage]` table (model = "linkage" only).
  LinkageSettings linkage;
  /// The scene's `[recording]` table, kept unparsed: the virtual rig reads and
  /// validates it (sensors, noise, file format); `sim` ignores it.
  std::optional<toml::table> recording;
};

/// Reads a scene file (keys in docs/reference.md "Scene file"), loads its rig, and
/// validates every value; InputError naming file, key and value otherwise.
Scene load_scene(const std::filesystem::path& file);

}  // namespace fourbar
