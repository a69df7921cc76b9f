#pragma once
// A parameter grid over a base clearance scene (clearance × rpm × e × μ), run
// on several threads; per grid point the per-turn impact statistics that the
// thesis plots against clearance and speed (Figs 7.10, 7.11): impacts per
// turn n, ΣF per turn, the index I_n = ΣF/n (normal impulse, THESIS-ERRATA).

#include <filesystem>
#include <vector>

#include "sim/scene.hpp"

namespace fourbar {

struct SweepGrid {
  std::vector<double> radial_clearance_m;
  std::vector<double> crank_speed_rad_s;
  std::vector<double> restitution;
  std::vector<double> friction_coefficient;  ///< one entry (the scene's) unless stick-slip
  int revolutions = 10;       ///< turns counted per point
  int skip_revolutions = 2;   ///< turns run first and not counted (start-up transient)
};

struct SweepPoint {
  double radial_clearance_m = 0, crank_speed_rad_s = 0, restitution = 0, friction_coefficient = 0;
  double impacts_per_rev = 0, sum_normal_impulse_per_rev_Ns = 0, impact_index_Ns = 0;
  double contact_losses_per_rev = 0, following_share = 0;
  double energy_residual_rel = 0, max_penetration_rel = 0;
};

/// Reads a sweep file: `scene` (a clearance scene, relative to the sweep
/// file), arrays `radial_mm`, `crank_speed_rpm`, `restitution`,
/// `friction_coefficient` (each optional: default the scene's value), and
/// `revolutions`, `skip_revolutions`. InputError naming file and key.
SweepGrid load_sweep(const std::filesystem::path& file, Scene& base);

/// Runs every grid point on `jobs` threads (clearance outer, then rpm, e, μ).
std::vector<SweepPoint> run_sweep(const Scene& base, const SweepGrid& grid, unsigned jobs);

}  // namespace fourbar
