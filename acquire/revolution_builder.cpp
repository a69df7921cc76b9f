#include "acquire/revolution_builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/units.hpp"

namespace fourbar {

namespace {

/// 4-point Lagrange weights at fraction f ∈ [0, 1) for samples −1, 0, 1, 2.
std::array<double, 4> lagrange4(double f) {
  return {-f * (f - 1) * (f - 2) / 6, (f + 1) * (f - 1) * (f - 2) / 2, -(f + 1) * f * (f - 2) / 2,
          (f + 1) * f * (f - 1) / 6};
}

}  // namespace

RevolutionBuilder::RevolutionBuilder(std::vector<RevolutionPlan> plan, const GridSettings& grid, std::size_t channels,
                                     AcquisitionSink& sink)
    : plan_(std::move(plan)), grid_(grid), channels_(channels), sink_(sink), s_ch_(channels) {
  for (const auto& r : plan_) {
    first_frame_.push_back(static_cast<std::int64_t>(std::floor((r.t_start - grid_.start_time_s) * grid_.sample_rate_hz)) - 1);
    last_frame_.push_back(std::min<std::int64_t>(
        static_cast<std::int64_t>(std::floor((r.t_end - grid_.start_time_s) * grid_.sample_rate_hz)) + 2,
        static_cast<std::int64_t>(grid_.frames) - 1));
  }
  if (!plan_.empty()) buffer_base_ = std::max<std::int64_t>(first_frame_[0], 0);
}

void RevolutionBuilder::push(std::int64_t n, const double* calibrated, bool clipped) {
  const double t = grid_.start_time_s + static_cast<double>(n) / grid_.sample_rate_hz;
  // Buffer what the pending revolutions need.
  if (pending_ < plan_.size() && n >= buffer_base_) {
    if (grid_.points > 0) buffer_.insert(buffer_.end(), calibrated, calibrated + channels_);
    if (clipped) clipped_frames_.push_back(n);
  }
  // Tag the sample with its revolution and crank motion.
  while (current_ < plan_.size() && t >= plan_[current_].t_end) ++current_;
  if (current_ < plan_.size() && t >= plan_[current_].t_start) {
    const RevolutionPlan& r = plan_[current_];
    if (r.track && r.track.get() != cursor_track_) cursor_.emplace(*r.track), cursor_track_ = r.track.get();
    const CrankPoint p = r.track ? cursor_->at(t) : r.curve.at(t);
    s_time_.push_back(t);
    s_crank_.push_back(grid_.offset_rad + grid_.direction * (p.phase_rad - r.curve.phase0_rad));
    s_omega_.push_back(grid_.direction * p.speed_rad_s);
    s_alpha_.push_back(grid_.direction * p.accel_rad_s2);
    s_rev_.push_back(static_cast<std::int64_t>(current_));
    for (std::size_t a = 0; a < channels_; ++a) s_ch_[a].push_back(calibrated[a]);
  }
  // Resample every revolution whose samples are all in.
  while (pending_ < plan_.size() && n >= last_frame_[pending_]) {
    resample(pending_++);
    trim_buffer();
  }
}

void RevolutionBuilder::flush_samples() {
  if (!s_time_.empty()) {
    SampleBlock b{s_time_, s_crank_, s_omega_, s_alpha_, s_rev_, {}};
    for (const auto& c : s_ch_) b.channels_m_s2.emplace_back(c);
    sink_.on_samples(b);
  }
  s_time_.clear(), s_crank_.clear(), s_omega_.clear(), s_alpha_.clear(), s_rev_.clear();
  for (auto& c : s_ch_) c.clear();
}

void RevolutionBuilder::finish() {
  flush_samples();
  while (pending_ < plan_.size()) resample(pending_++);
}

void RevolutionBuilder::resample(std::size_t index) {
  const RevolutionPlan& r = plan_[index];
  rev_.number = index;
  rev_.segment = r.segment;
  rev_.start_time_s = r.t_start;
  rev_.period_s = r.t_end - r.t_start;
  rev_.repaired = r.repaired;
  const std::int64_t lo = first_frame_[index], hi = last_frame_[index];
  rev_.clipped = std::any_of(clipped_frames_.begin(), clipped_frames_.end(),
                             [&](std::int64_t f) { return f >= lo && f <= hi; });
  clipped_revolutions_ += rev_.clipped;
  const auto n = static_cast<std::size_t>(grid_.points);
  rev_.crank_rad.resize(n), rev_.time_s.resize(n), rev_.omega2_rad_s.resize(n), rev_.alpha2_rad_s2.resize(n);
  rev_.channels_m_s2.resize(channels_);
  for (auto& c : rev_.channels_m_s2) c.resize(n);
  const auto buffered = static_cast<std::int64_t>(buffer_.size() / std::max<std::size_t>(channels_, 1));
  std::optional<AngleTrack::Cursor> grid_cursor;
  if (r.track) grid_cursor.emplace(*r.track);
  for (std::size_t j = 0; j < n; ++j) {
    const double u = static_cast<double>(j) / static_cast<double>(n);
    const CrankPoint p = grid_cursor ? grid_cursor->at_phase(r.curve.phase0_rad + units::kTwoPi * u) : r.at_fraction(u);
    rev_.crank_rad[j] = grid_.offset_rad + grid_.direction * units::kTwoPi * u;
    rev_.time_s[j] = p.time_s;
    rev_.omega2_rad_s[j] = grid_.direction * p.speed_rad_s;
    rev_.alpha2_rad_s2[j] = grid_.direction * p.accel_rad_s2;
    if (channels_ == 0) continue;
    // 4-point Lagrange between the buffered samples around the grid time
    // (indices clamped only at the ends of the recording).
    const double x = (p.time_s - grid_.start_time_s) * grid_.sample_rate_hz;
    const auto i = static_cast<std::int64_t>(std::floor(x));
    const auto w = lagrange4(x - static_cast<double>(i));
    std::array<std::int64_t, 4> f{};
    for (int m = 0; m < 4; ++m) f[static_cast<std::size_t>(m)] = i - 1 + m - buffer_base_;
    if (f[0] < 0 || f[3] >= buffered)
      for (auto& k : f) k = std::clamp<std::int64_t>(k, 0, buffered - 1);
    const double* b0 = buffer_.data() + static_cast<std::size_t>(f[0]) * channels_;
    const double* b1 = buffer_.data() + static_cast<std::size_t>(f[1]) * channels_;
    const double* b2 = buffer_.data() + static_cast<std::size_t>(f[2]) * channels_;
    const double* b3 = buffer_.data() + static_cast<std::size_t>(f[3]) * channels_;
    for (std::size_t a = 0; a < channels_; ++a)
      rev_.channels_m_s2[a][j] = w[0] * b0[a] + w[1] * b1[a] + w[2] * b2[a] + w[3] * b3[a];
  }
  sink_.on_revolution(rev_);
}

void RevolutionBuilder::trim_buffer() {
  if (pending_ >= plan_.size()) {
    buffer_.clear();
    return;
  }
  const std::int64_t keep_from = std::max<std::int64_t>(first_frame_[pending_], 0);
  if (keep_from > buffer_base_) {
    const auto drop = std::min<std::size_t>(static_cast<std::size_t>(keep_from - buffer_base_) * channels_, buffer_.size());
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(drop));
    buffer_base_ = keep_from;
  }
  while (!clipped_frames_.empty() && clipped_frames_.front() < keep_from) clipped_frames_.pop_front();
}

}  // namespace fourbar
