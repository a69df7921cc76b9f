#include "acquire/channel_scan.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <semaphore>
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

/// The pulse channel's part of the scan on a thread of its own, block by
/// block in the file's order (so every sum and count is the one of one
/// thread), while the calling thread does the accelerometers' part of the
/// same block. The block stays valid until `wait` returns.
class PulseScanThread {
 public:
  explicit PulseScanThread(std::function<void(std::span<const double>, std::size_t)> work)
      : work_(std::move(work)), thread_([this] { run(); }) {}
  ~PulseScanThread() {
    wait();
    finish_ = true;
    go_.release();
  }
  void post(std::span<const double> block, std::size_t frames) {
    block_ = block, frames_ = frames, busy_ = true;
    go_.release();
  }
  void wait() {
    if (busy_) done_.acquire(), busy_ = false;
  }

 private:
  void run() {
    for (;;) {
      go_.acquire();
      if (finish_) return;
      work_(block_, frames_);
      done_.release();
    }
  }
  std::function<void(std::span<const double>, std::size_t)> work_;
  std::span<const double> block_;
  std::size_t frames_ = 0;
  bool busy_ = false, finish_ = false;
  std::binary_semaphore go_{0}, done_{0};
  std::jthread thread_;
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
  auto pulse_part = [&](std::span<const double> block, std::size_t frames) {
    for (std::size_t f = 0; f < frames; ++f) {
      const double raw = block[f * channels + pulse.index];
      if (!std::isfinite(raw)) return;  // the accelerometers' part stops the scan at this frame (check_finite)
      const double v = raw * pulse.volts_per_unit;
      pulse_acc.add(v);
      result.pulse_histogram.add(v);
      result.pulse_local.add(v);
    }
  };
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
      pulse_thread.post(block, frames);
      accelerometer_part(block, frames, first);
      pulse_thread.wait();
    });
  } else {
    for_each_block(stream, AcquirePass::scan, [&](std::span<const double> block, std::size_t frames,
                                                  std::uint64_t first) {
      accelerometer_part(block, frames, first);
      pulse_part(block, frames);
    });
  }
  result.pulse_local.finish();
  for (const auto& a : acc) result.channel_stats.push_back(a.stats());
  result.pulse_stats = pulse_acc.stats();
  return result;
}

}  // namespace fourbar
