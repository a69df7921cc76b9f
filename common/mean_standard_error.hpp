#pragma once
// The standard error of the mean of a series whose terms are correlated
// (per-turn counts of a chaotic motion: a turn with many impacts is often
// followed by another). The independent-terms formula s/√n understates it by
// √τ, τ the integrated autocorrelation time:
//   Var(x̄) ≈ σ²_∞/n,  σ²_∞ = γ0 + 2 Σ_{k≥1} γk = τ·γ0,
// with the autocovariances γk estimated from the series and the sum cut by
// Geyer's initial monotone positive sequence (Geyer 1992, "Practical Markov
// chain Monte Carlo", Stat. Sci. 7(4) §3.3): pairs Γm = γ2m + γ2m+1 are summed
// while they stay positive, each at most its predecessor.

#include <span>

namespace fourbar {

struct MeanStandardError {
  double mean = 0;
  double standard_error = 0;  ///< s/√n · √max(1, τ)
  double autocorrelation_time = 1;  ///< τ as estimated (before the floor at 1)
  double effective_count = 0;       ///< n / max(1, τ): the independent terms the series is worth
};

/// Mean and its standard error for a series in order (e.g. turn by turn).
/// τ below 1 (an alternating series) is estimated but not used: the error is
/// never smaller than the independent-terms s/√n. Fewer than 2 terms: error 0.
MeanStandardError mean_standard_error(std::span<const double> series);

}  // namespace fourbar
