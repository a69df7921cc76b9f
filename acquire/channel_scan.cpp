#include "acquire/channel_scan.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

/// Streaming min/max/mean/rms.
struct Accumulator {
  double min = INFINITY, max = -INFINITY, sum = 0, sum_sq = 0;
  std::uint64_t n = 0, clipped = 0;
  double first_clip_s = 0;
  void add(double v) {
    min = std::min(min, v), max = std::max(max, v), sum += v, sum_sq += v * v, ++n;
  }
  ChannelStats stats() const {
    ChannelStats s;
    if (n == 0) return s;
    s.min = min, s.max = max, s.mean = sum / static_cast<double>(n);
    s.rms = std::sqrt(sum_sq / static_cast<double>(n));
    s.clipped_samples = clipped, s.first_clip_s = first_clip_s;
    return s;
  }
};

void check_finite(const RecordingInfo& info, const double* frame, std::uint64_t frame_index) {
  const auto channels = static_cast<std::size_t>(info.channels);
  const double fs = info.sample_rate_hz, t0 = info.start_time_s;
  for (std::size_t c = 0; c < channels; ++c)
    if (!std::isfinite(frame[c]))
      throw InputError(info.file.string() + ": channel " + std::to_string(c) + " holds a non-finite value at frame " +
                       std::to_string(frame_index) + " (t = " +
                       format_number(t0 + static_cast<double>(frame_index) / fs) + " s); the recording is damaged");
}

/// The pulse channel's part of the scan on a thread of its own: the calling
/// thread hands over each block's pulse values (checked finite) and goes on
/// with the next block; the thread takes them in the file's order, so every
/// sum and count is the one of one thread. At most kQueued blocks wait, so
/// memory stays bounded when the thread falls behind. The blocks' vectors
/// go back to a pool when done and are refilled (no fresh pages per block).
class PulseScanThread {
 public:
  explicit PulseScanThread(std::function<void(std::span<const double>)> work)
      : work_(std::move(work)), thread_([this] { run(); }) {}
  ~PulseScanThread() { finish(); }
  /// Copies `values` into a vector of the pool and queues it.
  void post(std::span<const double> values) {
    std::vector<double> copy;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return queue_.size() < kQueued; });  // (one poster: still true below)
      if (!spare_.empty()) {
        copy = std::move(spare_.back());
        spare_.pop_back();
      }
    }
    copy.assign(values.begin(), values.end());
    {
      const std::lock_guard lock(mutex_);
      queue_.push_back(std::move(copy));
    }
    changed_.notify_all();
  }
  /// Waits until every block posted is done.
  void finish() {
    {
      const std::lock_guard lock(mutex_);
      finishing_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

 private:
  static constexpr std::size_t kQueued = 8;
  void run() {
    for (;;) {
      std::vector<double> values;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !queue_.empty() || finishing_; });
        if (queue_.empty()) return;  // finishing, and nothing left
        values = std::move(queue_.front());
        queue_.pop_front();
      }
      changed_.notify_all();
      work_(values);
      const std::lock_guard lock(mutex_);
      spare_.push_back(std::move(values));
    }
  }
  std::function<void(std::span<const double>)> work_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<double>> queue_;
  std::vector<std::vector<double>> spare_;  // done, to be refilled
  bool finishing_ = false;
  std::thread thread_;
};

}  // namespace

ScanResult scan_pass(const BlockStream& stream, std::span<const AccelerometerInput> accelerometers,
                     const ClipRange& clip, const PulseInput& pulse) {
  const RecordingInfo& info = stream.reader.info();
  const auto channels = static_cast<std::size_t>(info.channels);
  const double fs = info.sample_rate_hz, t0 = info.start_time_s;
  std::vector<Accumulator> acc(accelerometers.size());
  Accumulator pulse_acc;
  ScanResult result;
  result.pulse_local = LocalLevels(fs);
  auto pulse_part = [&](std::span<const double> volts) {
    for (double v : volts) {
      pulse_acc.add(v);
      result.pulse_histogram.add(v);
      result.pulse_local.add(v);
    }
  };
  std::vector<double> volts;
  auto pulse_values = [&](std::span<const double> block, std::size_t frames) {
    volts.resize(frames);
    for (std::size_t f = 0; f < frames; ++f) volts[f] = block[f * channels + pulse.index] * pulse.volts_per_unit;
  };
  // Checks every value of the block (check_finite) before the pulse part sees it.
  auto accelerometer_part = [&](std::span<const double> block, std::size_t frames, std::uint64_t first) {
    for (std::size_t f = 0; f < frames; ++f) {
      const double* frame = block.data() + f * channels;
      check_finite(info, frame, first + f);
      for (std::size_t a = 0; a < accelerometers.size(); ++a) {
        const double raw = frame[accelerometers[a].index];
        acc[a].add(raw * accelerometers[a].m_s2_per_unit);
        if (clip.clipped(raw) && acc[a].clipped++ == 0) acc[a].first_clip_s = t0 + static_cast<double>(first + f) / fs;
      }
    }
  };
  if (stream.split_scan) {
    PulseScanThread pulse_thread(pulse_part);
    for_each_block(stream, AcquirePass::scan, [&](std::span<const double> block, std::size_t frames,
                                                  std::uint64_t first) {
      accelerometer_part(block, frames, first);
      pulse_values(block, frames);
      pulse_thread.post(volts);  // copied: the next block refills `volts`
    });
    pulse_thread.finish();
  } else {
    for_each_block(stream, AcquirePass::scan, [&](std::span<const double> block, std::size_t frames,
                                                  std::uint64_t first) {
      accelerometer_part(block, frames, first);
      pulse_values(block, frames);
      pulse_part(volts);
    });
  }
  result.pulse_local.finish();
  for (const auto& a : acc) result.channel_stats.push_back(a.stats());
  result.pulse_stats = pulse_acc.stats();
  return result;
}

}  // namespace fourbar
