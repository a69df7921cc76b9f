#pragma once
// The reads of the recording for a crank angle from many edges per turn (a
// tooth wheel with an index or missing teeth, a quadrature encoder): the
// level histograms of the channels beside the main one (its thresholds come
// from the scan pass), then every channel's edges with the Schmitt trigger of
// edge_detector.hpp — the wheel's chosen edge, the index's, and both edges
// of encoder A and B.

#include <string>
#include <vector>

#include "acquire/level_histogram.hpp"
#include "acquire/manifest.hpp"
#include "acquire/streaming_pass.hpp"

namespace fourbar {

struct WheelEdges {
  std::vector<double> teeth_s;               ///< crank_pulse: its polarity's edges
  std::vector<double> index_s;               ///< crank_index: its polarity's edges (empty without one)
  std::vector<double> a_rise_s, a_fall_s;    ///< encoder A (empty for a tooth wheel)
  std::vector<double> b_rise_s, b_fall_s;    ///< encoder B
  std::vector<std::string> warnings;
};

/// Reads the recording once (twice when there are channels beside the main
/// one, for their thresholds). `main` are the main channel's thresholds.
/// InputError naming the channel when one of them never crosses its thresholds.
WheelEdges wheel_edge_pass(const BlockStream& stream, const Manifest& manifest, const PulseThresholds& main);

}  // namespace fourbar
