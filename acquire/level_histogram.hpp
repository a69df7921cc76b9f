#pragma once
// The two levels of a pulse signal (idle and pulse), estimated from a
// streaming histogram of all its samples, and Schmitt-trigger thresholds set
// between them with a hysteresis wider than the noise.

#include <cstdint>
#include <optional>
#include <vector>

namespace fourbar {

/// Histogram with a fixed number of bins over a range that grows (by merging
/// neighbouring bins) to take every value: one pass, bounded memory.
class LevelHistogram {
 public:
  explicit LevelHistogram(std::size_t bins = 4096);
  void add(double v);
  std::uint64_t count() const { return count_; }

  struct Class {
    std::uint64_t count = 0;
    double median = 0;
    double noise = 0;  ///< robust standard deviation (1.4826·MAD)
  };
  struct Levels {
    Class low, high;   ///< the two classes split where Otsu's criterion is largest
  };
  /// nullopt when all samples fell in one bin (a flat signal).
  std::optional<Levels> two_levels() const;

 private:
  void grow_down();
  void grow_up();
  void update_range();
  double quantile(std::size_t from, std::size_t to, std::uint64_t n, double q) const;
  std::vector<std::uint64_t> bins_;
  double lo_ = 0, width_ = 0, inv_width_ = 0, hi_ = 0;
  std::uint64_t count_ = 0;
};

/// Schmitt-trigger thresholds of the pulse channel, in its units (volts). A
/// rising edge is one that goes from below `low` to above `high`; a falling
/// edge the reverse.
struct PulseThresholds {
  double bottom_level = 0, top_level = 0;  ///< the two signal levels (bottom < top)
  double low = 0, high = 0;                ///< the hysteresis band
  double noise = 0;                        ///< robust noise estimate of the levels
  bool automatic = true;
  bool hysteresis_widened = false;         ///< automatic, and the band was widened for the noise
  /// Automatic on a wandering baseline: levels and thresholds are relative
  /// to the local mid-level (local_levels.hpp), which the detector subtracts.
  bool follows_baseline = false;
};

// The automatic hysteresis band: half of it on each side of mid-level.
/// Half band on a clean signal, as a fraction of the swing: both thresholds on the edge's ramp, clear of hum.
inline constexpr double kHysteresisHalfBandOfSwing = 0.15;
/// Half band at least this many noise σ: noise must span 8σ to cross the band and re-trigger.
inline constexpr double kHysteresisNoiseSigmas = 4.0;
/// Half band at most this fraction of the swing: thresholds stay 10 % of the swing inside the levels.
inline constexpr double kHysteresisMaxHalfBandOfSwing = 0.4;
/// Levels closer than this many noise σ are no two levels (one level with noise).
inline constexpr double kLevelsMinSwingNoiseSigmas = 6.0;

/// Thresholds half-way between the levels ± max(kHysteresisHalfBandOfSwing·swing,
/// kHysteresisNoiseSigmas·noise), at most kHysteresisMaxHalfBandOfSwing·swing;
/// `hysteresis_widened` when the noise term is the larger (the one place
/// that decides it). Returns nullopt when the signal has no two distinct
/// levels (swing under kLevelsMinSwingNoiseSigmas noise σ): no pulses.
std::optional<PulseThresholds> automatic_thresholds(const LevelHistogram& histogram);

/// The same rule for given levels and noise (nullopt: no two distinct levels).
std::optional<PulseThresholds> thresholds_between(double bottom_level, double top_level, double noise);

}  // namespace fourbar
