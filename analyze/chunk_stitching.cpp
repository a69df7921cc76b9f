// ChunkedAnalysis's segment buffer (chunked_analysis.hpp): samples in with
// their continuous crank angle, a chunk out as soon as its revolutions and
// the overlap beyond them have arrived, then the buffer drops what the next
// chunk no longer needs. A gap in time ends the pulse-train segment; its
// last chunk takes what is left, and the per-segment state (guard queue,
// spectrum, ω carry) restarts.
#include "analyze/chunked_analysis.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/units.hpp"

namespace fourbar {

std::size_t ChunkedAnalysis::rev_start(std::size_t rev) const { return starts_[rev - first_rev_]; }

void ChunkedAnalysis::on_samples(const SampleBlock& b) {
  if (!planned_) throw RunError("analyze: samples arrived before the acquisition plan");
  const double gap = 1.5 / fs_;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double t = b.time_s[i];
    const auto rev = b.revolution[i];
    if (in_segment_ && t - last_time_ > gap) end_segment();  // acquire dropped revolutions: a new segment
    if (!in_segment_) {
      in_segment_ = true;
      base_ = end_ = 0;
      starts_.clear();
      first_rev_ = next_rev_ = static_cast<std::size_t>(rev);
      last_rev_.reset();
      revs_in_segment_ = 0;
    }
    if (!last_rev_ || rev != *last_rev_) {
      starts_.push_back(end_);
      last_rev_ = rev;
    }
    // Continuous crank angle: θ2 of the sample plus the turns before it.
    theta_.push_back(b.crank_rad[i] + direction_ * units::kTwoPi * static_cast<double>(rev));
    speed_.push_back(b.omega2_rad_s[i]);
    accel_.push_back(b.alpha2_rad_s2[i]);
    for (std::size_t c = 0; c < used_.size(); ++c) samples_[c].push_back(b.channels_m_s2[used_[c]][i]);
    ++end_;
    last_time_ = t;
  }
  process_ready();
}

void ChunkedAnalysis::process_ready() {
  for (;;) {
    const std::size_t rb = next_rev_ + chunk_revs_;
    if (rb - first_rev_ >= starts_.size()) return;   // revolution rb has not begun
    if (end_ - rev_start(rb) < overlap_) return;     // nor half a kernel beyond it
    process_chunk(rb, false);
  }
}

void ChunkedAnalysis::keep_from(std::size_t rb, const std::vector<std::vector<double>>* detached) {
  // Keep what the next chunk needs: from half a kernel before revolution rb.
  const std::size_t keep = std::max(base_, rev_start(rb) >= overlap_ ? rev_start(rb) - overlap_ : 0);
  const auto drop = static_cast<std::ptrdiff_t>(keep - base_);
  std::vector<std::vector<double>*> buffer{&theta_, &speed_, &accel_};
  for (auto& v : samples_) buffer.push_back(&v);
  for (std::size_t i = 0; i < buffer.size(); ++i) {
    if (detached) buffer[i]->assign((*detached)[i].begin() + drop, (*detached)[i].end());  // (buffer[i] is empty)
    else buffer[i]->erase(buffer[i]->begin(), buffer[i]->begin() + drop);
  }
  base_ = keep;
  while (first_rev_ < rb) starts_.pop_front(), ++first_rev_;
}

void ChunkedAnalysis::end_segment() {
  if (!in_segment_) return;
  const bool too_short = half_kernel_ > 0 && end_ <= half_kernel_;  // never a chunk yet: end_ is the segment's length
  if (too_short)
    result_.warnings.push_back("pulse-train segment of " + format_number(double(end_) / fs_) + " s (revolutions " +
                               std::to_string(first_rev_) + " to " + std::to_string(*last_rev_) +
                               ") is shorter than half the filter kernel (" + format_number(double(half_kernel_) / fs_) +
                               " s): not analysed");
  else if (last_rev_ && static_cast<std::int64_t>(next_rev_) <= *last_rev_)
    process_chunk(static_cast<std::size_t>(*last_rev_) + 1, true);
  drain(true);  // the segment's chunks still in flight, before its ends are settled
  // The segment's last revolutions were guard revolutions.
  for (auto& p : guard_queue_) commit(*p, false);
  guard_queue_.clear();
  repeat_held_.clear();  // the segment's last turns: not clear of its end
  for (auto& s : spectra_) s->restart();
  for (auto& c : omega_carry_) c.reset();
  for (auto* v : {&theta_, &speed_, &accel_}) v->clear();
  for (auto& v : samples_) v.clear();
  starts_.clear();
  in_segment_ = false;
}

}  // namespace fourbar
