#pragma once
// A modelling choice without a physical counterpart (the settle speed that
// ends a chattering sequence, a rigid impulse against a contact that lasts
// 0.1–0.3 ms, how α is sampled) moves a statistic of the model by about the
// same factor at every operating point (docs/fit.md "Modelling choices").
// The fit carries it as a nuisance parameter: one shared log-offset η per
// statistic, with a Gaussian prior of width σ (the spread the choices cause,
// measured), added to every model value of that statistic and profiled out
// in closed form:
//
//   χ²(η) = Σ w_i (d_i − η)² + η²/σ²,   w_i = 1/var_i,  d_i = log model − log measured
//   η̂ = Σ w_i d_i / (Σ w_i + 1/σ²),     χ²(η̂) = Σ w_i d_i² − (Σ w_i d_i)² / (Σ w_i + 1/σ²)
//
// σ = 0 gives the plain χ²; σ → ∞ leaves only the statistic's variation
// between recordings and links (its level no longer carries a parameter).
// Unlike a σ² added to each term's variance, the shared offset is one
// systematic shift, not an independent error per recording, so adding
// recordings does not average it away.

#include <span>
#include <vector>

namespace fourbar {

struct ProfiledOffset {
  double eta = 0;                ///< η̂, the profiled log-offset
  double chi2 = 0;               ///< χ²(η̂), the prior's term included
  double prior_chi2 = 0;         ///< η̂²/σ² (part of chi2)
  std::vector<double> terms;     ///< w_i (d_i − η̂)², per residual (chi2 = Σ terms + prior_chi2)
};

/// `residuals` d_i and their variances var_i (> 0; a non-positive variance is
/// taken as 1e-12), `sigma` ≥ 0 the prior's width of η (log scale).
ProfiledOffset profile_shared_offset(std::span<const double> residuals, std::span<const double> variances, double sigma);

}  // namespace fourbar
