#pragma once
// From raw crank-pulse edges to a clean once-per-revolution pulse train, by
// the sequence of periods (robust to what trips simple tachometer readers:
// noise, voltage echoes, doubled sync marks, dropped pulses), for any speed
// history: steady, run-up from standstill, coast-down, a stall, a step.
//
//   • Which edges are pulses: the smoothest chain (pulse_chain.hpp), every
//     period judged against its neighbours on both sides, never against a
//     start-up or global period. Edges left out are spurious (removed_s).
//   • Each period of the chain is then checked against its neighbours (the
//     period constant acceleration predicts from both sides, or the trend of
//     one side where the other is itself long). Up to e^kPeriodOutlier
//     times the reference it is one revolution. Longer, between steady
//     neighbours and within `tolerance` of k = 2 … max_missing + 1 of their
//     period, k − 1 pulses were missed: they are inserted at the times a
//     cubic through the neighbouring pulses predicts. Anything else (a stall,
//     an unexplained spacing) is a gap that cuts the train into segments, and
//     the revolutions across it are dropped.
//   • A period that halves or doubles abruptly between steady runs is a
//     finding, not a speed: either the crank speed changed twofold within a
//     turn or every pulse gained a second edge (or lost every other one).
//     With pulse widths, pulses whose width keeps its fraction of the period
//     across the step are real (an angular mark); otherwise the step is
//     listed in `ambiguous` and acquire refuses the recording.
// Partial revolutions before the first and after the last pulse are never
// revolutions.

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace fourbar {

struct PulseTrainOptions {
  double tolerance = 0.25;  ///< |interval/P − k| accepted as k periods
  int max_missing = 4;      ///< longest run of missing pulses that is repaired
};

/// ln(period / its neighbours' reference) beyond which a period is not one
/// revolution of a continuous speed history (a missed pulse, a stall).
inline constexpr double kPeriodOutlier = 0.35;

struct Pulse {
  double time_s = 0;
  bool inserted = false;    ///< repaired (no edge was detected here)
};

/// An interval between two accepted pulses that is no whole number of periods.
struct PulseGap {
  double from_s = 0, to_s = 0;
  double periods = 0;       ///< its length in typical periods
};

/// The period halving (ratio ≈ 0.5) or doubling (≈ 2) abruptly between steady runs.
struct PeriodStep {
  double time_s = 0;                 ///< the last pulse before the step
  double period_before_s = 0, period_after_s = 0;
  double width_before_s = NAN, width_after_s = NAN;  ///< median pulse widths, when known
  bool resolved = false;             ///< widths scale with the period: a real speed change
};

struct PulseTrain {
  std::vector<std::vector<Pulse>> segments;  ///< runs of pulses one revolution apart (each ≥ 2 pulses)
  std::vector<double> removed_s;             ///< spurious edges dropped
  std::vector<double> inserted_s;            ///< pulses inserted for missed ones
  std::vector<PulseGap> gaps;
  std::vector<double> orphan_s;              ///< accepted pulses left alone between gaps (no revolution)
  std::vector<PeriodStep> steps;             ///< twofold period steps (resolved or ambiguous)
  double typical_period_s = 0;               ///< median period of normal revolutions
  std::size_t edges = 0;                     ///< edges given

  std::size_t revolutions() const;
  /// The steps not resolved by the pulse widths: the recording is ambiguous.
  std::vector<PeriodStep> ambiguous() const;
};

/// The spacing of `edges` that most edge pairs agree on (within ±10 %),
/// the smallest of the near-best ones; 0 when fewer than two edges.
double dominant_period(std::span<const double> edges);

/// `widths_s`: each edge's pulse width (empty when unknown, NaN for one).
PulseTrain clean_pulse_train(std::span<const double> edges, const PulseTrainOptions& options = {},
                             std::span<const double> widths_s = {});

}  // namespace fourbar
