#pragma once
// A parameter grid over a base clearance scene (clearance × rpm × e × μ); per
// grid point the per-turn impact statistics that the thesis plots against
// clearance and speed (Figs 7.10, 7.11): impacts per turn n, ΣF per turn, the
// index I_n = ΣF/n (normal impulse, THESIS-ERRATA). The points are
// independent: cli/sweep_command.cpp spreads them over threads or MPI ranks
// (cluster/case_queue.hpp) and journals them (sweep_journal.hpp).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "sim/scene.hpp"

namespace fourbar {

struct SweepGrid {
  std::vector<double> radial_clearance_m;
  std::vector<double> crank_speed_rad_s;
  std::vector<double> restitution;
  std::vector<double> friction_coefficient;  ///< one entry (the scene's) unless stick-slip
  int revolutions = 20;       ///< turns counted per point (the report's matched theory averages 20)
  int skip_revolutions = 20;  ///< turns run first and not counted (start-up transient; the report's warm-up)
};

struct SweepPoint {
  double radial_clearance_m = 0, crank_speed_rad_s = 0, restitution = 0, friction_coefficient = 0;
  double impacts_per_rev = 0, sum_normal_impulse_per_rev_Ns = 0, impact_index_Ns = 0;
  /// Standard errors of the two per-turn means: the spread over the counted
  /// turns / √turns times √τ, τ the turns' integrated autocorrelation time
  /// (common/mean_standard_error.hpp; never below the independent-turns value).
  double impacts_per_rev_standard_error = 0, sum_normal_impulse_per_rev_standard_error_Ns = 0;
  double contact_losses_per_rev = 0, following_share = 0;
  double energy_residual_rel = 0, max_penetration_rel = 0;
  std::string error;  ///< empty: computed; else why this point could not be (the others go on)
  bool failed() const { return !error.empty(); }
};

/// Reads a sweep file: `scene` (a clearance scene, relative to the sweep
/// file), arrays `radial_mm`, `crank_speed_rpm`, `restitution`,
/// `friction_coefficient` (each optional: default the scene's value), and
/// `revolutions`, `skip_revolutions`. InputError naming file and key.
SweepGrid load_sweep(const std::filesystem::path& file, Scene& base);

/// The grid's points in table order (clearance outer, then rpm, e, μ), with
/// their parameters set and no statistics yet.
std::vector<SweepPoint> sweep_points(const SweepGrid& grid);

/// Simulates one point and fills in its statistics. A point the simulator
/// cannot run (RunError: events piling up, the integrator stalling) gets
/// `error` instead; it does not throw for that.
void compute_sweep_point(const Scene& base, const SweepGrid& grid, SweepPoint& point);

/// A computed point's statistics (or its error) as one line of text that
/// decodes to the same bits (hexadecimal floating point): what travels
/// between MPI ranks and what the journal keeps.
std::string encode_sweep_result(const SweepPoint& point);
/// Sets `point`'s statistics (or error) from encode_sweep_result's text;
/// false if the text is not such a line (a torn journal line).
bool decode_sweep_result(std::string_view text, SweepPoint& point);

}  // namespace fourbar
