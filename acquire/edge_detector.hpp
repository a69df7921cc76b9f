#pragma once
// Streaming Schmitt trigger on the crank-pulse channel: an edge is a pass
// from beyond one threshold to beyond the other in the chosen direction
// (hysteresis: noise inside the band cannot re-trigger). Its time is found to
// a fraction of a sample: where a straight line through the samples on the
// edge's ramp (10 %–90 % of the swing, least squares when there are three or
// more, else the two samples around mid-level) crosses mid-level.

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

  /// Edge times so far (s, recording time), increasing.
  const std::vector<double>& edges() const { return edges_; }
  /// Edges dropped because they followed the previous one within the debounce time.
  std::size_t debounced() const { return debounced_; }

 private:
  double edge_time(std::uint64_t fire) const;
  static constexpr std::size_t kRing = 1024;  // look-back for the ramp (samples)
  double sign_, arm_, fire_, mid_, band_lo_, band_hi_;
  double sample_rate_hz_, start_time_s_, debounce_s_;
  std::vector<double> ring_;
  std::uint64_t n_ = 0;  // samples seen
  bool armed_ = false;
  std::vector<double> edges_;
  std::size_t debounced_ = 0;
};

}  // namespace fourbar
