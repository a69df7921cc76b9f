#pragma once
// A short window of the recording kept for the eye: the crank-angle channels
// in volts and the accelerometers calibrated (m/s²) over a few revolutions
// in the middle of the longest pulse-train segment, with the pulses (and
// spurious edges) detected in it. Recorded during acquire's third pass, so
// it costs no extra read; asked for with AcquireOptions::excerpt_revolutions.
//
// Display-sized: a window longer than `max_buckets` frames is cut into
// buckets of `bucket_frames` consecutive frames, and each bucket keeps its
// minimum and maximum (in the order they occur, drawn at the bucket's start
// and middle: times within one bucket), so pulses and impact spikes stay visible; a shorter window keeps every frame (bucket_frames 1).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "acquire/pulse_train.hpp"

namespace fourbar {

struct ExcerptTrace {
  std::string name;             ///< the manifest's channel name
  std::string role;             ///< its role
  std::string unit;             ///< "V" (angle channels) or "m/s²" (accelerometers, axis sign applied)
  std::vector<double> values;   ///< per point of SignalExcerpt::time_s
};

struct SignalExcerpt {
  double start_s = 0, end_s = 0;          ///< the window
  std::uint64_t first_frame = 0, frames = 0;
  std::size_t bucket_frames = 1;          ///< frames per min/max bucket (1: every frame)
  /// Per point: a frame's time; with buckets two points per bucket, at its
  /// first frame and half-way, holding its extremes in the order they occur.
  std::vector<double> time_s;
  std::vector<ExcerptTrace> traces;       ///< angle channels first, then accelerometers, manifest order
  std::vector<double> pulse_s;            ///< accepted once-per-turn pulses in the window
  std::vector<bool> pulse_inserted;       ///< per pulse: inserted for a missed one (no edge there)
  std::vector<double> removed_edge_s;     ///< edges in the window judged spurious and dropped
  std::vector<double> wheel_edge_s;       ///< tooth wheel or encoder: the main channel's edges in the window
};

/// The window: `revolutions` turns from the middle of the longest segment,
/// widened by a tenth of a period on each side, as frames of the recording.
/// Empty (frames 0) when there is no segment.
SignalExcerpt excerpt_window(const PulseTrain& pulses, std::size_t revolutions, double sample_rate_hz,
                             double start_time_s, std::uint64_t recording_frames);

/// Fills an excerpt's traces from the blocks of a pass over the recording.
class ExcerptRecorder {
 public:
  /// `excerpt` holds the window (excerpt_window); `max_buckets` ≥ 1.
  ExcerptRecorder(SignalExcerpt excerpt, const Manifest& manifest, double sample_rate_hz, double start_time_s,
                  std::size_t max_buckets = 600);
  /// One block of interleaved recorded values starting at `first_frame`.
  void take(std::span<const double> block, std::size_t frames, std::uint64_t first_frame, std::size_t channels);
  /// The excerpt with the last bucket closed.
  SignalExcerpt finish();

 private:
  struct Source {
    std::size_t index;
    double scale;  ///< recorded unit → V or m/s²
  };
  void close_bucket();
  SignalExcerpt x_;
  std::vector<Source> sources_;
  double fs_, t0_;
  std::uint64_t bucket_start_ = 0;
  std::size_t in_bucket_ = 0;
  std::vector<double> lo_, hi_;
  std::vector<std::uint64_t> lo_at_, hi_at_;
};

}  // namespace fourbar
