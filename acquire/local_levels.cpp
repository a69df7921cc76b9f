#include "acquire/local_levels.hpp"

#include <algorithm>
#include <cmath>

#include "common/statistics.hpp"

namespace fourbar {

LocalLevels::LocalLevels(double sample_rate_hz)
    : window_samples_(std::max<std::uint64_t>(64, static_cast<std::uint64_t>(kLocalLevelWindow_s * sample_rate_hz))),
      stride_(std::max<std::uint64_t>(1, static_cast<std::uint64_t>(sample_rate_hz / kLocalLevelMinRate_hz))) {}

void LocalLevels::add(double v) {
  if (--until_next_ == 0) current_.add(v), until_next_ = stride_;
  if (++n_ - window_start_ == window_samples_) close_window();
}

void LocalLevels::finish() {
  if (n_ > window_start_) close_window();
}

void LocalLevels::close_window() {
  const auto levels = current_.two_levels();
  if (levels && levels->low.count >= 2 && levels->high.count >= 2) {
    const double swing = levels->high.median - levels->low.median;
    const double noise = std::max(levels->low.noise, levels->high.noise);
    if (swing > 0 && swing >= kLevelsMinSwingNoiseSigmas * noise)
      windows_.push_back({window_start_ + (n_ - window_start_) / 2, levels->low.median, levels->high.median, noise,
                          levels->low.count, levels->high.count});
  }
  current_ = LevelHistogram(256);
  window_start_ = n_;
  until_next_ = 1;
}

std::optional<LocalLevels::Summary> LocalLevels::summary() const {
  if (windows_.empty()) return std::nullopt;
  std::vector<double> swing, noise;
  Summary s;
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& w : windows_) {
    swing.push_back(w.top - w.bottom), noise.push_back(w.noise);
    const double mid = 0.5 * (w.bottom + w.top);
    lo = std::min(lo, mid), hi = std::max(hi, mid);
    s.bottom_count += w.bottom_count, s.top_count += w.top_count;
  }
  s.swing = median(swing), s.noise = median(noise), s.wander = hi - lo;
  return s;
}

double LocalLevels::mid_at(std::uint64_t index) const {
  if (windows_.empty()) return 0;
  auto mid = [&](std::size_t k) { return 0.5 * (windows_[k].bottom + windows_[k].top); };
  if (index <= windows_.front().centre) return mid(0);
  if (index >= windows_.back().centre) return mid(windows_.size() - 1);
  if (cursor_ >= windows_.size() || windows_[cursor_].centre > index) cursor_ = 0;
  while (windows_[cursor_ + 1].centre < index) ++cursor_;
  const auto& a = windows_[cursor_];
  const auto& b = windows_[cursor_ + 1];
  const double f = static_cast<double>(index - a.centre) / static_cast<double>(b.centre - a.centre);
  return mid(cursor_) + f * (mid(cursor_ + 1) - mid(cursor_));
}

}  // namespace fourbar
