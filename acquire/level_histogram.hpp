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
};

/// Thresholds half-way between the levels ± max(15 % of the swing, 4·noise),
/// kept 10 % inside the levels. Returns nullopt when the signal has no two
/// distinct levels (swing under 6 noise standard deviations): no pulses.
std::optional<PulseThresholds> automatic_thresholds(const LevelHistogram& histogram);

}  // namespace fourbar
