#pragma once
// The pulse channel's two levels window by window, for pickups whose
// baseline wanders (a DC drift, a magnetic pickup's offset): each window of
// kLocalLevelWindow_s gets its own level histogram (level_histogram.hpp) and
// two levels where it holds a pulse; windows without one (a slow turn, a
// stall) take the mid-level interpolated between their neighbours. The edge
// detector then works on the signal minus that local mid-level, with one
// hysteresis band from the local swing and noise (automatic thresholds only;
// the manifest's thresholds are always used as given).

#include <cstdint>
#include <optional>
#include <vector>

#include "acquire/level_histogram.hpp"

namespace fourbar {

/// Window of the local levels (s): a few periods at working speed, short
/// against a drifting baseline.
inline constexpr double kLocalLevelWindow_s = 0.5;
/// The local levels look at one sample in every stride, the stride the
/// largest that keeps at least this rate (a 0.4 ms pulse still gives two
/// samples): a quarter of the scan pass's time at 25.6 kHz otherwise.
inline constexpr double kLocalLevelMinRate_hz = 5000;
/// Local mid-levels wandering more than this fraction of the swing make
/// acquire follow them (below it the global levels are used unchanged).
inline constexpr double kBaselineWanderOfSwing = 0.1;

class LocalLevels {
 public:
  explicit LocalLevels(double sample_rate_hz);
  void add(double v);
  /// Closes the last window; call once after the last add. Every sample is
  /// given to add (the window counts them); one in `stride` is looked at.
  void finish();

  struct Window {
    std::uint64_t centre = 0;  ///< sample index
    double bottom = 0, top = 0, noise = 0;
    std::uint64_t bottom_count = 0, top_count = 0;
  };
  /// Windows that hold two distinct levels, in time order.
  const std::vector<Window>& windows() const { return windows_; }

  /// Median swing and noise over the windows, and how far the mid-levels
  /// wander (max − min); nullopt with no window of two levels.
  struct Summary {
    double swing = 0, noise = 0, wander = 0;
    std::uint64_t bottom_count = 0, top_count = 0;
  };
  std::optional<Summary> summary() const;

  /// The mid-level at sample `index`: linear between window centres,
  /// constant beyond the first and last.
  double mid_at(std::uint64_t index) const;

 private:
  void close_window();
  std::uint64_t window_samples_, stride_;
  LevelHistogram current_{256};
  std::uint64_t n_ = 0, window_start_ = 0, until_next_ = 1;  // samples to the next one looked at
  std::vector<Window> windows_;
  mutable std::size_t cursor_ = 0;  // mid_at is called with increasing indices
};

}  // namespace fourbar
