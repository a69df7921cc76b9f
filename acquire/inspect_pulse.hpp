#pragma once
// Pulse-train recognition for `fourbar inspect`: a Schmitt trigger at 30 %
// and 70 % of a channel's range, fed one sample at a time. A channel is a
// pulse train when ≥ 90 % of its samples sit within 20 % of the range from
// one of its two extremes (a sine spends 59 % there, noise far less), it has
// at least three leading edges and most intervals between them agree.

#include <cstdint>
#include <optional>
#include <vector>

#include "acquire/inspect.hpp"

namespace fourbar {

class PulseTrainDetector {
 public:
  PulseTrainDetector(double min, double max);
  void add(double x);
  /// The verdict after the last sample; nullopt when not a pulse train.
  std::optional<PulseTrainGuess> result(double sample_rate_hz) const;

 private:
  double min_, max_, low_, high_;
  bool state_high_ = false, started_ = false;
  std::uint64_t n_ = 0, near_extremes_ = 0, high_samples_ = 0;
  std::vector<std::uint64_t> rising_, falling_;
};

}  // namespace fourbar
