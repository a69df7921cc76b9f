#include "acquire/edge_detector.hpp"

#include <algorithm>
#include <cmath>

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
  levels_known_ = top > bottom;
  if (!levels_known_) bottom = low, top = high;  // levels unknown: the band itself
  const double swing = top - bottom;
  bottom_s_ = bottom, top_s_ = top;
  window_ = std::max(4.0 * t.noise, 0.02 * swing);
  band_lo_ = bottom + 0.1 * swing;
  band_hi_ = top - 0.1 * swing;
}

void EdgeDetector::push(const double* data, std::size_t frames, std::size_t stride) {
  for (std::size_t i = 0; i < frames; ++i) {
    const double s = sign_ * data[i * stride];
    ring_[n_ % kRing] = s;
    // Level refinement from the previous sample, if it sits on a plateau (both
    // neighbours within the window: the corners of a ramp are left out).
    if (n_ >= 2) {
      const double prev = ring_[(n_ - 1) % kRing], prev2 = ring_[(n_ - 2) % kRing];
      if (std::abs(prev - prev2) < window_ && std::abs(s - prev) < window_) {
        if (std::abs(prev - bottom_s_) < window_) sum_bottom_ += prev, ++n_bottom_;
        else if (std::abs(prev - top_s_) < window_) sum_top_ += prev, ++n_top_;
      }
    }
    if (!armed_) {
      armed_ = s < arm_;
      if (armed_ && !ramps_.empty() && std::isnan(widths_.back()))
        widths_.back() = static_cast<double>(n_ - last_fire_) / sample_rate_hz_;
    } else if (s > fire_) {
      armed_ = false;
      const Ramp r = edge_ramp(n_);
      const double t = time_of(r, mid_);
      if (t - last_time_ < debounce_s_) {
        ++debounced_;
      } else {
        ramps_.push_back(r);
        widths_.push_back(NAN);
        last_fire_ = n_;
        last_time_ = t;
      }
    }
    ++n_;
  }
}

double EdgeDetector::mid_level() const {
  double mid = mid_;
  if (levels_known_ && n_bottom_ > 0 && n_top_ > 0)
    mid = 0.5 * (sum_bottom_ / static_cast<double>(n_bottom_) + sum_top_ / static_cast<double>(n_top_));
  return sign_ * mid;
}

std::vector<double> EdgeDetector::edges() const {
  const double mid_s = sign_ * mid_level();
  std::vector<double> t;
  t.reserve(ramps_.size());
  for (const Ramp& r : ramps_) t.push_back(time_of(r, mid_s));
  return t;
}

double EdgeDetector::time_of(const Ramp& r, double mid_s) const {
  return start_time_s_ + (r.first + (mid_s - r.a) / r.b) / sample_rate_hz_;
}

EdgeDetector::Ramp EdgeDetector::edge_ramp(std::uint64_t fire_index) const {
  const auto fire = static_cast<std::int64_t>(fire_index);
  auto at = [&](std::int64_t k) { return ring_[static_cast<std::uint64_t>(k) % kRing]; };
  auto in_band = [&](std::int64_t k) { return at(k) > band_lo_ && at(k) < band_hi_; };
  const std::int64_t oldest = std::max<std::int64_t>(0, fire + 1 - static_cast<std::int64_t>(kRing));
  // j: the first sample at or above mid-level after the last crossing.
  std::int64_t j = fire;
  while (j > oldest && at(j - 1) >= mid_) --j;
  if (j == oldest) return {static_cast<double>(fire), mid_, 1.0};  // ramp longer than the look-back
  // The samples on the ramp around the crossing, inside the 10–90 % band.
  std::int64_t first = j, last = j - 1;
  for (std::int64_t k = j - 1; k >= oldest && in_band(k); --k) first = k;
  for (std::int64_t k = j; k <= fire && in_band(k); ++k) last = k;
  if (last - first + 1 >= 3) {
    // Least-squares line s = a + b·(k − first) through the ramp samples.
    const double n = static_cast<double>(last - first + 1);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::int64_t k = first; k <= last; ++k) {
      const double x = static_cast<double>(k - first), y = at(k);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    if (b > 0) return {static_cast<double>(first), (sy - b * sx) / n, b};
  }
  // The two samples around the crossing.
  return {static_cast<double>(j - 1), at(j - 1), at(j) - at(j - 1)};
}

}  // namespace fourbar
