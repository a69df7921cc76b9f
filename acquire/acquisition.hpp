#pragma once
// Pipeline stage "acquire": a recording and its manifest in; calibrated,
// angle-tagged samples and revolutions out (through an AcquisitionSink), plus
// a report of what was found.
//
// The recording is read in three streaming passes of fixed-size blocks
// (streaming_pass.hpp), so memory stays bounded by one revolution whatever
// the length:
//   1. scan    — channel statistics, clipping, NaN check, the pulse
//                channel's level histogram (channel_scan.hpp); then the
//                Schmitt thresholds (pulse_thresholds.hpp);
//   2. pulses  — Schmitt-trigger edges with sub-sample times, cleaned into
//                the pulse train (pulse_pass.hpp); then the crank motion
//                fitted through it and the revolutions planned
//                (revolution_plan.hpp);
//              — a tooth wheel or an encoder instead: every angle channel's
//                edges, numbered on the wheel, a spline through all of them
//                (wheel_pass.hpp, wheel_decode.hpp, wheel_plan.hpp);
//   3. samples — each sample tagged with θ2, ω2, α2 and calibrated; each
//                revolution resampled onto N crank angles (4-point Lagrange
//                interpolation between samples) as soon as it is complete
//                (sample_tagging.hpp);
// then the warnings (acquisition_warnings.hpp).

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "acquire/channel_scan.hpp"
#include "acquire/level_histogram.hpp"
#include "acquire/manifest.hpp"
#include "acquire/pulse_train.hpp"
#include "acquire/reader.hpp"
#include "acquire/revolution.hpp"
#include "acquire/revolution_plan.hpp"
#include "acquire/signal_excerpt.hpp"
#include "acquire/streaming_pass.hpp"
#include "acquire/time_range.hpp"
#include "acquire/wheel_plan.hpp"

namespace fourbar {

struct AcquireOptions {
  int grid_points_per_rev = 0;     ///< N crank angles per revolution; 0: the smallest multiple of 360 ≥ frames per revolution
  std::size_t block_frames = 16384;
  bool progress = true;            ///< progress bar on stderr when it is a terminal
  PulseTrainOptions pulses;
  /// Revolutions of raw signal to keep (AcquisitionReport::excerpt, recorded
  /// in the third pass, signal_excerpt.hpp); 0: none.
  std::size_t excerpt_revolutions = 0;
  /// Cores acquire may use. More than 1: the file is read on a thread of its
  /// own ahead of each pass, and the scan pass does the pulse channel on a
  /// second thread (the same numbers either way).
  unsigned threads = 1;
  /// The part to analyse (--start-s/--end-s); each bound set here overrides
  /// the manifest's start_s/end_s.
  TimeRange range;
};

struct AcquisitionReport {
  RecordingInfo recording;
  std::vector<AcquiredChannel> channels;     ///< accelerometer channels, manifest order
  std::vector<ChannelStats> channel_stats;   ///< same order
  std::string pulse_channel;                 ///< its name
  ChannelStats pulse_stats;                  ///< volts
  PulseThresholds thresholds;                ///< as used
  double edge_level_V = 0;                   ///< mid-level at which edge times are taken (refined)
  std::size_t edges_debounced = 0;
  /// One pulse per turn: the median time from a configured edge to the
  /// pulse's other edge, as crank angle (the mark's width when the polarity
  /// picks the mark's leading edge); NaN when unknown.
  double pulse_width_deg = NAN;
  PulseTrain pulses;                         ///< once per turn (a wheel or encoder: its turns)
  WheelReport wheel;                         ///< many edges per turn (positions_per_rev 0: one pulse per turn)
  CrankSmoothingReport smoothing;            ///< crank_smoothing = "spline" (period_turns 0: off)
  int grid_points_per_rev = 0;               ///< N crank angles per revolution (0: the sink wanted no grid)
  double frames_per_rev = 0;                 ///< recording frames in a typical revolution
  std::size_t revolutions = 0;               ///< kept
  std::size_t revolutions_repaired = 0;
  std::size_t revolutions_clipped = 0;
  std::size_t revolutions_in_gaps = 0;       ///< dropped: estimated turns inside pulse-train gaps
  SpeedStats speed;
  bool clipping_checked = false;             ///< false for float/text without adc_range_V
  TimeRange range;                           ///< the part analysed (options over manifest; inactive: all)
  std::vector<std::string> warnings;
  std::array<double, kAcquirePasses> pass_seconds{};  ///< wall time of scan, pulses, samples passes
  std::optional<SignalExcerpt> excerpt;      ///< when AcquireOptions::excerpt_revolutions > 0
};

/// Runs the three passes. `manifest` must be bound to the reader's recording
/// (bind_channels). InputError for no pulses, fewer than two revolutions,
/// NaN samples or a damaged file.
AcquisitionReport acquire(Reader& reader, const Manifest& manifest, const AcquireOptions& options,
                          AcquisitionSink& sink);

/// Everything in memory, for analyze and tests: opens `recording`, reads its
/// manifest (`manifest_file`, or the sidecar when empty), runs acquire and
/// keeps every revolution. Memory grows with revolutions × N (an hour at
/// 350 rpm and N = 4680 is several GB): for long recordings pass an
/// AcquisitionSink to `acquire` and average as the revolutions arrive.
struct Acquisition {
  Manifest manifest;
  AcquisitionReport report;
  std::vector<Revolution> revolutions;
};
Acquisition acquire_revolutions(const std::filesystem::path& recording, const std::filesystem::path& manifest_file = {},
                                const AcquireOptions& options = {});

/// Loads the manifest (the sidecar when `manifest_file` is empty, with a clear
/// error when that is missing), opens the recording and binds the channels.
struct OpenedRecording {
  Manifest manifest;
  std::unique_ptr<Reader> reader;
};
OpenedRecording open_with_manifest(const std::filesystem::path& recording, const std::filesystem::path& manifest_file);

}  // namespace fourbar
