// ChunkedAnalysis's chunks in order (chunked_analysis.hpp). With one thread a
// chunk is transformed on the segment buffer itself and delivered at once.
// With more, the chunk takes the segment buffer with it (the buffer goes on
// from a spare one, with the overlap the next chunk needs copied into it),
// it is transformed on a thread of its own (at most `threads` chunks at once, each with its own workspace), and
// the calling thread — the one acquire feeds — delivers the finished chunks
// in their order whenever it passes by, and waits for the oldest only when
// `threads` are in flight. Every step of every chunk is the same in both
// ways, and so is the order of everything that carries over: the result is
// bit for bit the same.
#include "analyze/chunked_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <vector>

namespace fourbar {

namespace {

/// A spare from `spare` (under `m`), else a new one from `make`.
template <class T, class Make>
std::unique_ptr<T> take_spare(std::mutex& m, std::vector<std::unique_ptr<T>>& spare, Make make) {
  {
    const std::lock_guard lock(m);
    if (!spare.empty()) {
      auto p = std::move(spare.back());
      spare.pop_back();
      return p;
    }
  }
  return make();
}

}  // namespace

std::unique_ptr<ChunkedAnalysis::ChunkWorkspace> ChunkedAnalysis::make_workspace() const {
  auto w = std::make_unique<ChunkWorkspace>();
  if (filter_block_frames_ > 0) {
    w->alpha_filter = std::make_unique<FftFilter>(filter_, fs_, filter_block_frames_, Boundary::zero);
    if (has_normal_)
      w->normal_filter = std::make_unique<FftFilter>(normal_filter_, fs_, filter_block_frames_, Boundary::zero,
                                                     w->alpha_filter->transform());
  }
  return w;
}

std::unique_ptr<ChunkedAnalysis::ChunkWorkspace> ChunkedAnalysis::take_workspace() {
  return take_spare(workspace_mutex_, spare_workspaces_, [this] { return make_workspace(); });
}

void ChunkedAnalysis::give_back(std::unique_ptr<ChunkWorkspace> w) {
  const std::lock_guard lock(workspace_mutex_);
  spare_workspaces_.push_back(std::move(w));
}

std::unique_ptr<ChunkedAnalysis::ChunkOutcome> ChunkedAnalysis::take_outcome() {
  return take_spare(workspace_mutex_, spare_outcomes_, [] { return std::make_unique<ChunkOutcome>(); });
}

ChunkedAnalysis::ChunkJob ChunkedAnalysis::make_job(std::size_t rb, bool segment_end) const {
  const std::size_t sa = rev_start(next_rev_), sb = segment_end ? end_ : rev_start(rb);
  const std::size_t begin = std::max(base_, sa >= overlap_ ? sa - overlap_ : 0);
  const std::size_t stop = segment_end ? end_ : std::min(end_, sb + overlap_);
  const std::size_t n = stop - begin, off = begin - base_;
  ChunkJob job;
  job.rev_begin = next_rev_, job.rev_end = rb;
  job.c0 = sa - begin, job.c1 = sb - begin;
  job.stream_at = sa;
  job.at_start = begin == 0;
  job.segment_end = segment_end;
  auto slice = [&](const std::vector<double>& v) { return std::span(v).subspan(off, n); };
  job.theta = slice(theta_), job.speed = slice(speed_), job.accel = slice(accel_);
  for (const auto& v : samples_) job.samples.push_back(slice(v));
  return job;
}

std::vector<std::vector<double>> ChunkedAnalysis::detach_buffer() {
  std::vector<std::vector<double>> spare;
  {
    const std::lock_guard lock(workspace_mutex_);
    if (!spare_buffers_.empty()) {
      spare = std::move(spare_buffers_.back());
      spare_buffers_.pop_back();
    }
  }
  spare.resize(3 + samples_.size());
  std::vector<std::vector<double>*> buffer{&theta_, &speed_, &accel_};
  for (auto& v : samples_) buffer.push_back(&v);
  for (std::size_t i = 0; i < buffer.size(); ++i) {
    spare[i].clear();  // keeps its memory: no page faults refilling it
    std::swap(spare[i], *buffer[i]);
  }
  return spare;  // the samples as they were (the job's spans stay valid: the memory moved with them)
}

void ChunkedAnalysis::process_chunk(std::size_t rb, bool segment_end) {
  if (threads_ <= 1) {
    const ChunkJob job = make_job(rb, segment_end);
    auto w = take_workspace();
    auto outcome = take_outcome();
    transform(job, *w, *outcome);
    give_back(std::move(w));
    deliver(std::move(outcome));
    next_rev_ = rb;
    if (!segment_end) keep_from(rb);
    return;
  }
  if (in_flight_.size() >= threads_) {  // the oldest first
    std::future<std::unique_ptr<ChunkOutcome>> oldest = std::move(in_flight_.front());
    in_flight_.pop_front();
    deliver(oldest.get());
  }
  // The job takes the segment buffer itself; the buffer goes on from a
  // spare one with what the next chunk needs (keep_from).
  ChunkJob job = make_job(rb, segment_end);
  job.owned = detach_buffer();
  next_rev_ = rb;
  if (!segment_end) keep_from(rb, &job.owned);
  in_flight_.push_back(std::async(std::launch::async, [this, job = std::move(job)]() mutable {
    auto w = take_workspace();
    auto outcome = take_outcome();
    transform(job, *w, *outcome);
    give_back(std::move(w));
    const std::lock_guard lock(workspace_mutex_);
    spare_buffers_.push_back(std::move(job.owned));
    return outcome;
  }));
  drain(false);
}

void ChunkedAnalysis::drain(bool wait) {
  while (!in_flight_.empty() &&
         (wait || in_flight_.front().wait_for(std::chrono::seconds(0)) == std::future_status::ready)) {
    // Popped before it is delivered: a chunk that failed is not waited for again.
    std::future<std::unique_ptr<ChunkOutcome>> front = std::move(in_flight_.front());
    in_flight_.pop_front();
    deliver(front.get());
  }
}

}  // namespace fourbar
