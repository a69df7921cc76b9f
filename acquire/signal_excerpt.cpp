#include "acquire/signal_excerpt.hpp"

#include <algorithm>
#include <cmath>

namespace fourbar {

SignalExcerpt excerpt_window(const PulseTrain& pulses, std::size_t revolutions, double fs, double t0,
                             std::uint64_t recording_frames) {
  SignalExcerpt x;
  const std::vector<Pulse>* longest = nullptr;
  for (const auto& s : pulses.segments)
    if (!longest || s.size() > longest->size()) longest = &s;
  if (!longest || longest->size() < 2 || revolutions == 0 || !(fs > 0)) return x;
  const std::size_t turns = std::min(revolutions, longest->size() - 1);
  const std::size_t first = (longest->size() - 1 - turns) / 2;
  const double t_from = (*longest)[first].time_s, t_to = (*longest)[first + turns].time_s;
  const double margin = 0.1 * (t_to - t_from) / static_cast<double>(turns);
  const auto frame_at = [&](double t) {
    return static_cast<std::uint64_t>(std::clamp(std::floor((t - t0) * fs), 0.0, static_cast<double>(recording_frames)));
  };
  x.first_frame = frame_at(t_from - margin);
  x.frames = frame_at(t_to + margin) - x.first_frame;
  x.start_s = t0 + static_cast<double>(x.first_frame) / fs;
  x.end_s = t0 + static_cast<double>(x.first_frame + x.frames) / fs;
  const auto inside = [&](double t) { return t >= x.start_s && t <= x.end_s; };
  for (const auto& s : pulses.segments)
    for (const Pulse& p : s)
      if (inside(p.time_s)) x.pulse_s.push_back(p.time_s), x.pulse_inserted.push_back(p.inserted);
  for (double t : pulses.removed_s)
    if (inside(t)) x.removed_edge_s.push_back(t);
  return x;
}

ExcerptRecorder::ExcerptRecorder(SignalExcerpt excerpt, const Manifest& manifest, double fs, double t0,
                                 std::size_t max_buckets)
    : x_(std::move(excerpt)), fs_(fs), t0_(t0) {
  for (int pass = 0; pass < 2; ++pass)
    for (const ChannelSpec& c : manifest.channels) {
      const bool angle = is_angle_channel(c.role);
      if (pass == 0 ? !angle : !is_accelerometer(c.role)) continue;
      const double scale = angle ? manifest.full_scale_V : c.axis_sign * manifest.full_scale_V / c.volts_per_m_s2;
      sources_.push_back({static_cast<std::size_t>(*c.index), scale});
      x_.traces.push_back({c.name, to_string(c.role), angle ? "V" : "m/s²", {}});
    }
  const std::uint64_t buckets = std::max<std::size_t>(max_buckets, 1);
  x_.bucket_frames = x_.frames <= buckets ? 1 : static_cast<std::size_t>((x_.frames + buckets - 1) / buckets);
  lo_.assign(sources_.size(), 0), hi_.assign(sources_.size(), 0);
  lo_at_.assign(sources_.size(), 0), hi_at_.assign(sources_.size(), 0);
}

void ExcerptRecorder::take(std::span<const double> block, std::size_t frames, std::uint64_t first, std::size_t channels) {
  const std::uint64_t from = std::max(first, x_.first_frame), to = std::min(first + frames, x_.first_frame + x_.frames);
  for (std::uint64_t f = from; f < to; ++f) {
    const double* frame = block.data() + (f - first) * channels;
    if (in_bucket_ == 0) bucket_start_ = f;
    for (std::size_t s = 0; s < sources_.size(); ++s) {
      const double v = frame[sources_[s].index] * sources_[s].scale;
      if (in_bucket_ == 0 || v < lo_[s]) lo_[s] = v, lo_at_[s] = f;
      if (in_bucket_ == 0 || v > hi_[s]) hi_[s] = v, hi_at_[s] = f;
    }
    if (++in_bucket_ == x_.bucket_frames) close_bucket();
  }
}

void ExcerptRecorder::close_bucket() {
  if (in_bucket_ == 0) return;
  const auto time = [&](std::uint64_t f) { return t0_ + static_cast<double>(f) / fs_; };
  x_.time_s.push_back(time(bucket_start_));
  if (x_.bucket_frames > 1) x_.time_s.push_back(time(bucket_start_) + 0.5 * static_cast<double>(x_.bucket_frames) / fs_);
  for (std::size_t s = 0; s < sources_.size(); ++s) {
    std::vector<double>& v = x_.traces[s].values;
    if (x_.bucket_frames == 1) {
      v.push_back(lo_[s]);
      continue;
    }
    const bool lo_first = lo_at_[s] <= hi_at_[s];
    v.push_back(lo_first ? lo_[s] : hi_[s]);
    v.push_back(lo_first ? hi_[s] : lo_[s]);
  }
  in_bucket_ = 0;
}

SignalExcerpt ExcerptRecorder::finish() {
  close_bucket();
  return std::move(x_);
}

}  // namespace fourbar
