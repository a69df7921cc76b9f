#pragma once
// From raw crank-pulse edges to a clean once-per-revolution pulse train, by
// the sequence of periods (robust to what trips simple tachometer readers:
// noise, voltage echoes, doubled sync marks, dropped pulses).
//
// The period P is predicted from the trend of the last periods (a line
// through the last six, extrapolated: follows run-up and coast-down), started
// from the spacing that most edge pairs agree on. Walking forward from each
// accepted pulse:
//   • an edge within (1 ± tolerance)·P of it is the next pulse; of several,
//     the one after which the next period matches the last best (smoothest
//     speed: an echo or doubled mark shifts one period up and the next down);
//     edges before it are spurious (echoes, doubled marks, noise) and removed;
//   • with none there but one at (k ± tolerance)·P, k ≤ max_missing + 1, and
//     nothing else in between, k − 1 pulses were missed: they are inserted at
//     the times a cubic through the neighbouring pulses predicts;
//   • anything else (an edge at an unexplained spacing, a stop) is a gap that
//     fits no whole number of revolutions: the pulse train is cut there into
//     segments, and the revolutions across the gap are dropped.
// Partial revolutions before the first and after the last pulse are never
// revolutions.

#include <cstddef>
#include <span>
#include <vector>

namespace fourbar {

struct PulseTrainOptions {
  double tolerance = 0.25;  ///< |interval/P − k| accepted as k periods
  int max_missing = 4;      ///< longest run of missing pulses that is repaired
};

struct Pulse {
  double time_s = 0;
  bool inserted = false;    ///< repaired (no edge was detected here)
};

/// An interval between two accepted pulses that is no whole number of periods.
struct PulseGap {
  double from_s = 0, to_s = 0;
  double periods = 0;       ///< its length in typical periods
};

struct PulseTrain {
  std::vector<std::vector<Pulse>> segments;  ///< runs of pulses one revolution apart (each ≥ 2 pulses)
  std::vector<double> removed_s;             ///< spurious edges dropped
  std::vector<double> inserted_s;            ///< pulses inserted for missed ones
  std::vector<PulseGap> gaps;
  std::vector<double> orphan_s;              ///< accepted pulses left alone between gaps (no revolution)
  double typical_period_s = 0;               ///< median period of normal revolutions
  std::size_t edges = 0;                     ///< edges given

  std::size_t revolutions() const;
};

/// The spacing of `edges` that most edge pairs agree on (within ±10 %),
/// the smallest of the near-best ones; 0 when fewer than two edges.
double dominant_period(std::span<const double> edges);

PulseTrain clean_pulse_train(std::span<const double> edges, const PulseTrainOptions& options = {});

}  // namespace fourbar
