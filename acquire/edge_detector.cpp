#include "acquire/edge_detector.hpp"

#include <algorithm>

namespace fourbar {

EdgeDetector::EdgeDetector(const PulseThresholds& t, PulsePolarity polarity, double sample_rate_hz,
                           double start_time_s, double debounce_s)
    : sign_(polarity == PulsePolarity::rising ? 1.0 : -1.0),
      sample_rate_hz_(sample_rate_hz),
      start_time_s_(start_time_s),
      debounce_s_(debounce_s),
      ring_(kRing, 0.0) {
  // Work on s = sign·x, so that the wanted edge always goes up.
  const double low = sign_ > 0 ? t.low : -t.high, high = sign_ > 0 ? t.high : -t.low;
  arm_ = low;
  fire_ = high;
  mid_ = 0.5 * (low + high);
  double bottom = sign_ > 0 ? t.bottom_level : -t.top_level, top = sign_ > 0 ? t.top_level : -t.bottom_level;
  if (!(top > bottom)) bottom = low, top = high;  // levels unknown: the band itself
  const double swing = top - bottom;
  band_lo_ = bottom + 0.1 * swing;
  band_hi_ = top - 0.1 * swing;
}

void EdgeDetector::push(const double* data, std::size_t frames, std::size_t stride) {
  for (std::size_t i = 0; i < frames; ++i) {
    const double s = sign_ * data[i * stride];
    ring_[n_ % kRing] = s;
    if (!armed_) {
      armed_ = s < arm_;
    } else if (s > fire_) {
      armed_ = false;
      const double t = edge_time(n_);
      if (!edges_.empty() && t - edges_.back() < debounce_s_) ++debounced_;
      else edges_.push_back(t);
    }
    ++n_;
  }
}

double EdgeDetector::edge_time(std::uint64_t fire_index) const {
  const auto fire = static_cast<std::int64_t>(fire_index);
  auto at = [&](std::int64_t k) { return ring_[static_cast<std::uint64_t>(k) % kRing]; };
  auto in_band = [&](std::int64_t k) { return at(k) > band_lo_ && at(k) < band_hi_; };
  const std::int64_t oldest = std::max<std::int64_t>(0, fire + 1 - static_cast<std::int64_t>(kRing));
  // j: the first sample at or above mid-level after the last crossing.
  std::int64_t j = fire;
  while (j > oldest && at(j - 1) >= mid_) --j;
  if (j == oldest) return start_time_s_ + static_cast<double>(fire) / sample_rate_hz_;  // ramp longer than the look-back
  // The samples on the ramp around the crossing, inside the 10–90 % band.
  std::int64_t first = j, last = j - 1;
  for (std::int64_t k = j - 1; k >= oldest && in_band(k); --k) first = k;
  for (std::int64_t k = j; k <= fire && in_band(k); ++k) last = k;
  double index;
  if (last - first + 1 >= 3) {
    // Least-squares line s = a + b·(k − first) through the ramp samples.
    const double n = static_cast<double>(last - first + 1);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::int64_t k = first; k <= last; ++k) {
      const double x = static_cast<double>(k - first), y = at(k);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double a = (sy - b * sx) / n;
    index = static_cast<double>(first) + (mid_ - a) / b;
  } else {
    const double y0 = at(j - 1), y1 = at(j);
    index = static_cast<double>(j - 1) + (mid_ - y0) / (y1 - y0);
  }
  return start_time_s_ + index / sample_rate_hz_;
}

}  // namespace fourbar
