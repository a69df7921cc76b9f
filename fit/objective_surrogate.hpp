#pragma once
// A smooth model of the fit's noisy objective. The clearance motion is
// chaotic, so χ² at two nearby parameter points differs by its own noise
// (≈ √(2ν) for ν compared statistics) — the lowest evaluated point is a
// lucky draw, not the optimum. A quadratic in the parameters (scaled to the
// box), fitted by least squares to the evaluated points near the bottom,
// averages that noise out: its minimum in the box is the estimate, and the
// range where it stays within Δ of that minimum is the interval (the
// profile: for e the minimum over μ, and vice versa). The scatter of the
// points about the quadratic is measured and widens Δ when it is larger
// than the expected noise.

#include <optional>
#include <vector>

namespace fourbar {

struct EvaluatedPoint {
  double restitution = 0, friction = 0, chi2 = 0;
};

struct SurrogateFit {
  bool ok = false;               ///< a quadratic with a minimum (positive definite) was fitted
  double restitution = 0, friction = 0, minimum = 0;
  double restitution_low = 0, restitution_high = 0, friction_low = 0, friction_high = 0;
  double residual_rms = 0;       ///< scatter of the points used about the quadratic
  double delta = 0;              ///< Δ used for the interval
  std::optional<double> correlation;  ///< of e and μ from the quadratic's curvature
  int points_used = 0;
};

/// `two_parameters`: e and μ, else e only (friction ignored). `noise_delta`:
/// the objective's expected noise (the points within 6× of the lowest are
/// fitted); Δ = max(interval_delta, residual_rms), interval_delta = noise_delta when 0.
SurrogateFit fit_surrogate(const std::vector<EvaluatedPoint>& points, double e_low, double e_high, double mu_low,
                           double mu_high, bool two_parameters, double noise_delta, double interval_delta = 0);

}  // namespace fourbar
