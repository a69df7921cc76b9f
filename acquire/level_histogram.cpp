#include "acquire/level_histogram.hpp"

#include <algorithm>
#include <cmath>

namespace fourbar {

LevelHistogram::LevelHistogram(std::size_t bins) : bins_(bins + bins % 2, 0) {}

void LevelHistogram::grow_down() {
  // Range [lo − B·w, lo + B·w) with bins of 2w: old pairs go to the upper half.
  const std::size_t n = bins_.size(), half = n / 2;
  std::vector<std::uint64_t> merged(n, 0);
  for (std::size_t j = 0; j < half; ++j) merged[half + j] = bins_[2 * j] + bins_[2 * j + 1];
  bins_.swap(merged);
  lo_ -= static_cast<double>(n) * width_;
  width_ *= 2;
  update_range();
}

void LevelHistogram::grow_up() {
  const std::size_t n = bins_.size(), half = n / 2;
  std::vector<std::uint64_t> merged(n, 0);
  for (std::size_t j = 0; j < half; ++j) merged[j] = bins_[2 * j] + bins_[2 * j + 1];
  bins_.swap(merged);
  width_ *= 2;
  update_range();
}

void LevelHistogram::update_range() {
  inv_width_ = 1.0 / width_;
  hi_ = lo_ + width_ * static_cast<double>(bins_.size());
}

void LevelHistogram::add(double v) {
  if (count_ == 0) {
    width_ = 1e-9 * std::max(1.0, std::abs(v));
    lo_ = v - width_ * static_cast<double>(bins_.size() / 2);
    update_range();
  }
  while (v < lo_) grow_down();
  while (v >= hi_) grow_up();
  auto i = static_cast<std::size_t>((v - lo_) * inv_width_);
  ++bins_[std::min(i, bins_.size() - 1)];
  ++count_;
}

double LevelHistogram::quantile(std::size_t from, std::size_t to, std::uint64_t n, double q) const {
  // Linear interpolation inside the bin where the cumulative count passes q·n.
  const double target = q * static_cast<double>(n);
  double cum = 0;
  for (std::size_t i = from; i < to; ++i) {
    const double c = static_cast<double>(bins_[i]);
    if (cum + c >= target && c > 0) return lo_ + width_ * (static_cast<double>(i) + (target - cum) / c);
    cum += c;
  }
  return lo_ + width_ * static_cast<double>(to);
}

std::optional<LevelHistogram::Levels> LevelHistogram::two_levels() const {
  if (count_ < 4) return std::nullopt;
  // Otsu: the split that maximises the between-class variance.
  const std::size_t n = bins_.size();
  double total = 0, total_sum = 0;
  for (std::size_t i = 0; i < n; ++i) total += static_cast<double>(bins_[i]), total_sum += static_cast<double>(bins_[i]) * i;
  double w0 = 0, s0 = 0, best = -1;
  std::size_t split = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    w0 += static_cast<double>(bins_[i]);
    s0 += static_cast<double>(bins_[i]) * i;
    const double w1 = total - w0;
    if (w0 == 0 || w1 == 0) continue;
    const double m0 = s0 / w0, m1 = (total_sum - s0) / w1;
    const double between = w0 * w1 * (m0 - m1) * (m0 - m1);
    if (between > best) best = between, split = i + 1;
  }
  if (best <= 0) return std::nullopt;
  Levels levels;
  auto describe = [&](std::size_t from, std::size_t to) {
    Class c;
    for (std::size_t i = from; i < to; ++i) c.count += bins_[i];
    c.median = quantile(from, to, c.count, 0.5);
    // MAD from the quartiles of the class (1.4826·IQR/2 for a normal spread).
    const double q1 = quantile(from, to, c.count, 0.25), q3 = quantile(from, to, c.count, 0.75);
    c.noise = 0.7413 * (q3 - q1);
    return c;
  };
  levels.low = describe(0, split);
  levels.high = describe(split, n);
  return levels;
}

std::optional<PulseThresholds> automatic_thresholds(const LevelHistogram& histogram) {
  const auto levels = histogram.two_levels();
  if (!levels) return std::nullopt;
  return thresholds_between(levels->low.median, levels->high.median, std::max(levels->low.noise, levels->high.noise));
}

std::optional<PulseThresholds> thresholds_between(double bottom_level, double top_level, double noise) {
  PulseThresholds t;
  t.bottom_level = bottom_level;
  t.top_level = top_level;
  t.noise = noise;
  const double swing = t.top_level - t.bottom_level;
  if (!(swing > 0) || swing < kLevelsMinSwingNoiseSigmas * t.noise) return std::nullopt;
  const double mid = 0.5 * (t.bottom_level + t.top_level);
  const double clean_half_band = kHysteresisHalfBandOfSwing * swing;
  const double noise_half_band = kHysteresisNoiseSigmas * t.noise;
  t.hysteresis_widened = noise_half_band > clean_half_band;
  const double half_band = std::min(std::max(clean_half_band, noise_half_band), kHysteresisMaxHalfBandOfSwing * swing);
  t.low = mid - half_band;
  t.high = mid + half_band;
  return t;
}

}  // namespace fourbar
