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
#include "acquire/local_levels.hpp"
#include "acquire/manifest.hpp"
#include "acquire/pulse_train.hpp"
#include "acquire/streaming_pass.hpp"

namespace fourbar {

struct EdgePassResult {
  std::vector<double> edges_s;      ///< edge times (recording time), increasing
  std::vector<double> widths_s;     ///< pulse width after each edge (NaN: the recording ended in it)
  std::size_t edges_debounced = 0;  ///< dropped within the debounce time
  double edge_level_V = 0;          ///< refined mid-level at which edge times are taken
};

/// Reads the recording once through the manifest's pulse channel. InputError
/// when it never crosses the thresholds (no pulses).
/// With `thresholds.follows_baseline`, the signal minus `baseline`'s local
/// mid-level is what crosses them.
EdgePassResult edge_pass(const BlockStream& stream, const Manifest& manifest, const PulseThresholds& thresholds,
                         const LocalLevels* baseline = nullptr);

/// The cleaned pulse train of the edges. InputError naming the recording and
/// the pulse channel when it holds fewer than two complete revolutions, or
/// when its period halves or doubles abruptly and the pulse widths cannot
/// tell a real speed change from echoes or lost pulses (what was seen, and
/// the manifest key that settles it).
PulseTrain pulse_train_from_edges(const EdgePassResult& edges, const PulseTrainOptions& options,
                                  const Manifest& manifest, const std::filesystem::path& recording_file);

/// The median of the finite `widths_s` as crank angle at `period_s` per
/// turn (degrees); NaN when none is finite or the period is not positive.
/// The set-up check uses it to recognise a polarity that picks the pulse's
/// other edge (the crank angle is then off by this width).
double median_width_deg(std::span<const double> widths_s, double period_s);

/// Estimated whole revolutions lost in a gap of the pulse train (at least one).
std::size_t revolutions_lost(const PulseGap& gap);

}  // namespace fourbar
