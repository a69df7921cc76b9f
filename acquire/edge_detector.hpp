#pragma once
// Streaming Schmitt trigger on the crank-pulse channel: an edge is a pass
// from beyond one threshold to beyond the other in the chosen direction
// (hysteresis: noise inside the band cannot re-trigger). Its time is found to
// a fraction of a sample: where a straight line through the samples on the
// edge's ramp (10 %–90 % of the swing, least squares when there are three or
// more, else the two samples around mid-level) crosses mid-level. The two
// levels are refined while streaming (mean of the plateau samples near each
// level; a sample whose neighbour jumps by more than the window is on a ramp),
// so that mid-level is exact to the noise, not to the histogram's bins; edge
// times are computed from the refined mid-level at the end.

#include <cstdint>
#include <vector>

#include "acquire/level_histogram.hpp"
#include "acquire/manifest.hpp"

namespace fourbar {

class EdgeDetector {
 public:
  EdgeDetector(const PulseThresholds& thresholds, PulsePolarity polarity, double sample_rate_hz,
               double start_time_s, double debounce_s);

  /// Feeds `frames` samples found at data[0], data[stride], …
  void push(const double* data, std::size_t frames, std::size_t stride);

  /// Edge times (s, recording time), increasing, at the refined mid-level.
  std::vector<double> edges() const;
  /// The refined mid-level (volts; between the levels, or the thresholds'
  /// middle when the levels are unknown).
  double mid_level() const;
  /// Each edge's pulse width (s): from the edge to the sample where the signal
  /// is back beyond the arming threshold; NaN when the recording ends first.
  const std::vector<double>& widths() const { return widths_; }
  /// Edges dropped because they followed the previous one within the debounce time.
  std::size_t debounced() const { return debounced_; }

 private:
  /// A line s = a + b·(k − first) through an edge's ramp, in samples.
  struct Ramp {
    double first, a, b;
  };
  Ramp edge_ramp(std::uint64_t fire) const;
  double time_of(const Ramp& r, double mid_s) const;
  static constexpr std::size_t kRing = 1024;  // look-back for the ramp (samples)
  double sign_, arm_, fire_, mid_, band_lo_, band_hi_;
  double sample_rate_hz_, start_time_s_, debounce_s_;
  std::vector<double> ring_;
  std::uint64_t n_ = 0;  // samples seen
  bool armed_ = false;
  std::vector<Ramp> ramps_;
  std::vector<double> widths_;
  std::uint64_t last_fire_ = 0;  // sample index at which the last kept edge fired
  double last_time_ = -1e300;
  std::size_t debounced_ = 0;
  // Level refinement (in s = sign·x): sums of the samples near each level.
  bool levels_known_ = false;
  double bottom_s_ = 0, top_s_ = 0, window_ = 0;
  double sum_bottom_ = 0, sum_top_ = 0;
  std::uint64_t n_bottom_ = 0, n_top_ = 0;
};

}  // namespace fourbar
