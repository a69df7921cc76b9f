#pragma once
// The linkage model (sim/linkage) as a matched theory: a run at constant
// crank speed from centred pins, sampled at the points of a crank-angle grid
// over `turns` turns after `warmup`, each link's α as the recording's
// tangential accelerometer would give it — the reading there (rigid frame +
// elastic deflection, sim/linkage/linkage_sensor.hpp) turned into α by
// analyze's own conversion (analyze/conversion.hpp) with the nominal link
// motion, as analyze does with a measured channel. A link without a sensor
// gets the model's rigid-frame α. Point values or cell means (sub_samples).
// The nominal series are the rigid mechanism's (thesis eq. 3.14–3.17).
//
// Used by the fit's elastic model (fit/linkage_statistics.hpp) and by the
// comparison's link-vibration check (compare/link_vibration.hpp).

#include <array>
#include <optional>
#include <string>

#include "analyze/sensor_mount.hpp"
#include "compare/matched_theory.hpp"
#include "sim/linkage/linkage_model.hpp"

namespace fourbar {

/// Sub-samples per grid cell for cell means (the trapezoid is within 0.73 %
/// RMS of the exact cell mean Δω3/cell with impacts in the cells, thesis rig
/// at 350 rpm, 180 points a turn: tests/compare/test_linkage_theory.cpp).
inline constexpr int kCellMeanSubSamples = 8;

struct LinkageTheoryRun {
  CrankGrid grid;                ///< the samples' grid (N per turn, start, direction)
  double crank_speed_rad_s = 0;  ///< ω2, same sign as grid.direction
  double clearance_m = 0;        ///< written into the theory (the model's own clearances are in its spec)
  int warmup_turns = 0, turns = 0;
  /// The coupler's [0] and rocker's [1] tangential accelerometer; absent: rigid-frame α.
  std::array<std::optional<ResolvedMount>, 2> sensor;
  std::string name;  ///< named in run errors (a recording)
  /// 1: α at each grid point; K > 1: α as the mean over each grid cell
  /// (centred on its point; K + 1 samples, trapezoid rule), as the three-mode
  /// theory's cell means: a point sample folds the contact's energy above
  /// the grid's Nyquist order into the checked orders (measured on the thesis
  /// rig at 0.254 mm: 5x the band energy over 500–900 Hz). Needs warmup_turns ≥ 1.
  int sub_samples = 1;
};

/// The linkage model's spec with the rig's elastic links (those it has
/// modal data for), a compliant contact at the coupler–rocker joint of
/// radial clearance `clearance_m`, stiffness K, restitution e and Coulomb μ,
/// the compliant law's other keys at their defaults (CompliantSettings).
/// Used by the fit's elastic model and the report's elastic-link reference.
LinkageSpec bearing_clearance_spec(const Rig& rig, double clearance_m, double stiffness_N_per_m_n, double restitution,
                                   double friction_coefficient, double tolerance);

/// Series of α3, α4, ω3, ω4 (nominal: N; clearance_revolutions: turns × N)
/// and the impact severity over the kept turns. RunError when the model fails.
MatchedTheory simulate_linkage_theory(const LinkageModel& linkage, const LinkageTheoryRun& run);

}  // namespace fourbar
