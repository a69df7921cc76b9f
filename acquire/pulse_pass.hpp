#pragma once
// Pass 2 of acquire and what follows it: from the pulse channel to a clean
// once-per-revolution pulse train. The Schmitt trigger finds the edges
// (edge_detector.hpp); the period sequence cleans them into pulses
// (pulse_train.hpp), and the train must hold at least two complete
// revolutions. Another pulse source (run-ups, tooth wheels, encoders) plugs in
// here: thresholds in, PulseTrain out.

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include "acquire/level_histogram.hpp"
#include "acquire/manifest.hpp"
#include "acquire/pulse_train.hpp"
#include "acquire/streaming_pass.hpp"

namespace fourbar {

struct EdgePassResult {
  std::vector<double> edges_s;      ///< edge times (recording time), increasing
  std::size_t edges_debounced = 0;  ///< dropped within the debounce time
  double edge_level_V = 0;          ///< refined mid-level at which edge times are taken
};

/// Reads the recording once through the manifest's pulse channel. InputError
/// when it never crosses the thresholds (no pulses).
EdgePassResult edge_pass(const BlockStream& stream, const Manifest& manifest, const PulseThresholds& thresholds);

/// The cleaned pulse train of `edges_s`. InputError naming the recording and
/// the pulse channel when it holds fewer than two complete revolutions.
PulseTrain pulse_train_from_edges(std::span<const double> edges_s, const PulseTrainOptions& options,
                                  const Manifest& manifest, const std::filesystem::path& recording_file);

/// Estimated whole revolutions lost in a gap of the pulse train (at least one).
std::size_t revolutions_lost(const PulseGap& gap);

}  // namespace fourbar
