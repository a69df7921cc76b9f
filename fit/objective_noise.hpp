#pragma once
// How far the fit's objective may rise above its bottom inside the reported
// interval: the measurement's noise plus the objective's own.
//
// The objective's own noise is measured, not assumed: the motion with impacts
// is chaotic, so χ² at points a hair apart (replicates: e nudged by 0.001 …
// far below any interval's resolution) comes from different trajectories and
// differs by the noise that every point of the profile carries. Their sample
// standard deviation is that noise, their mean the level of the bottom (the
// lowest evaluated point alone is a lucky draw).
//
// The measurement's noise: a point p belongs to a profile interval at level
// L when χ²(p) − χ²(bottom) ≤ the L-quantile of D·X + Z, X ~ χ²₁ (the
// profile-likelihood ratio of one parameter), Z ~ N(0, σ²(1 + 1/K)) (the
// objective's noise at p and at the mean of K replicates at the bottom), and
// D = max(1, χ²_bottom/(ν − parameters)) the dispersion: when the statistics
// scatter about the model by more than their standard errors say (χ² per
// degree of freedom above 1), the errors are scaled by it (Birge ratio).

#include <span>
#include <utility>
#include <vector>

namespace fourbar {

struct ObjectiveNoise {
  double bottom = 0;      ///< mean χ² of the replicates
  double noise_sd = 0;    ///< their sample standard deviation (the objective's own noise)
  int replicates = 0;
  double dispersion = 1;  ///< D
  double level = 0.95;
  double delta = 0;       ///< the threshold Δχ² above the bottom
};

/// From the χ² of `replicates` (≥ 2 values) at the bottom, ν compared
/// statistics and the number of fitted parameters. Throws std::invalid_argument
/// for fewer than two replicates or a level outside (0, 1).
ObjectiveNoise objective_noise(std::span<const double> replicates, int terms, int parameters, double level);

/// The interval of a profile (`chi2` at the grid values `at`, ascending):
/// where it stays within `delta` of `bottom`, ends interpolated to the
/// threshold between grid points (by the parabola through the three nearest
/// points where it is curved upwards: a bowl's chord cuts the interval short;
/// else linearly), out to the box where the first or last grid point is
/// inside; it always holds `value`.
std::pair<double, double> profile_interval(const std::vector<double>& at, const std::vector<double>& chi2, double value,
                                           double bottom, double delta, double box_low, double box_high);

/// The L-quantile of D·X + Z, X ~ χ²₁, Z ~ N(0, noise_sd²).
double profile_threshold(double dispersion, double noise_sd, double level);

}  // namespace fourbar
