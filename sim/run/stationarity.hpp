#pragma once
// Statistical steady state of a run that never repeats exactly (undamped or
// chaotic motion): per-turn quantities whose running means over two
// consecutive windows of W turns agree within a relative tolerance. Distinct
// from a periodic steady state (the turn-start state repeating after k turns).

#include <array>
#include <vector>

namespace fourbar {

/// The per-turn quantities compared (revolutions.csv columns).
struct TurnQuantities {
  static constexpr std::size_t kCount = 4;
  static constexpr std::array<const char*, kCount> kNames = {"impacts", "sum_normal_impulse_Ns", "following_share",
                                                             "alpha3_deviation_rms_rad_s2"};
  std::array<double, kCount> values{};  ///< n, ΣF, following share, RMS(α3 − α3,nominal)
};

struct StationarityResult {
  bool steady = false;
  std::array<double, TurnQuantities::kCount> earlier_mean{}, later_mean{};
  /// Largest |earlier − later| / max(|earlier|, |later|) over the quantities (0 when both are 0).
  double worst_relative_difference = 0;
  /// Largest standard error of the later window's mean, s/√W, relative to that mean.
  double worst_relative_standard_error = 0;
};

/// Compares the means over turns [n − 2W, n − W) and [n − W, n) of the last
/// n = turns.size() turns. Steady when, for every quantity, the two means
/// differ by at most `tolerance` relative to the larger, and the later mean
/// is known to that tolerance too (its standard error s/√W, s the per-turn
/// spread in the window, ≤ tolerance × mean): without the second condition
/// two noisy windows agree by chance now and then during a transient. Needs
/// n ≥ 2W. A quantity that is 0 in both windows agrees.
StationarityResult compare_windows(const std::vector<TurnQuantities>& turns, int window, double tolerance);

}  // namespace fourbar
