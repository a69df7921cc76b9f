#include "acquire/inspect_pulse.hpp"

#include <algorithm>
#include <cmath>

#include "common/statistics.hpp"

namespace fourbar {

namespace {
constexpr std::size_t kMaxEdges = 10'000'000;  // a noise channel's edges are not kept beyond this
}

PulseTrainDetector::PulseTrainDetector(double min, double max)
    : min_(min), max_(max), low_(min + 0.3 * (max - min)), high_(min + 0.7 * (max - min)) {}

void PulseTrainDetector::add(double x) {
  const double band = 0.2 * (max_ - min_);
  near_extremes_ += (x <= min_ + band || x >= max_ - band);
  if (!started_) {
    state_high_ = x >= 0.5 * (low_ + high_);
    started_ = true;
  } else if (!state_high_ && x >= high_) {
    state_high_ = true;
    if (rising_.size() < kMaxEdges) rising_.push_back(n_);
  } else if (state_high_ && x <= low_) {
    state_high_ = false;
    if (falling_.size() < kMaxEdges) falling_.push_back(n_);
  }
  high_samples_ += state_high_;
  ++n_;
}

std::optional<PulseTrainGuess> PulseTrainDetector::result(double sample_rate_hz) const {
  if (n_ == 0 || !(max_ > min_) || static_cast<double>(near_extremes_) < 0.9 * static_cast<double>(n_)) return std::nullopt;
  PulseTrainGuess g;
  g.high_fraction = static_cast<double>(high_samples_) / static_cast<double>(n_);
  g.short_state_high = g.high_fraction <= 0.5;
  // The leading edge of the short state marks the pulse.
  const std::vector<std::uint64_t>& lead = g.short_state_high ? rising_ : falling_;
  if (lead.size() < 3) return std::nullopt;
  std::vector<double> intervals;
  for (std::size_t i = 1; i < lead.size(); ++i) intervals.push_back(static_cast<double>(lead[i] - lead[i - 1]));
  const double m = median(intervals);
  double regular_sum = 0;
  std::size_t regular = 0;
  for (double d : intervals)
    if (std::abs(d - m) <= 0.25 * m) regular_sum += d, ++regular;
  g.regular_fraction = static_cast<double>(regular) / static_cast<double>(intervals.size());
  if (g.regular_fraction < 0.6 || !(m > 0)) return std::nullopt;
  g.pulses = lead.size();
  g.rate_hz = sample_rate_hz * static_cast<double>(regular) / regular_sum;  // mean of the regular intervals
  g.rpm = 60.0 * g.rate_hz;
  g.low_level = min_, g.high_level = max_;
  return g;
}

}  // namespace fourbar
