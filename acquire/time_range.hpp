#pragma once
// The part of a recording to analyse (manifest `start_s`/`end_s`, or
// --start-s/--end-s), and what tells the user to choose one: turns are kept
// only when they lie wholly inside the range (the pulse train or the
// numbered edges are cut before the revolutions are planned), and two
// warnings say how to cut a recording whose crank did not turn steadily:
//   • more than kOutsideShareWarn of the file (or of the range) lies outside
//     the crank-pulse train: before its first turn, after its last, or in its
//     gaps (a run-up, a stall, the pickup off), beyond the partial turn each
//     end of any recording has;
//   • the turn speed changes by more than kSpeedChangeWarn over the turns
//     kept (a coast-down at the end, a stall, a run-up).
// Each names the steady part — the longest run of turns whose speed is
// within ±kSteadyBand of its median — as the exact keys to type.

#include <optional>
#include <string>
#include <vector>

#include "acquire/pulse_train.hpp"
#include "acquire/revolution_plan.hpp"
#include "acquire/wheel_decode.hpp"

namespace fourbar {

inline constexpr double kOutsideShareWarn = 0.10;
inline constexpr double kSpeedChangeWarn = 0.03;
inline constexpr double kSteadyBand = 0.01;

struct TimeRange {
  std::optional<double> start_s, end_s;  ///< recording time (s), as the time column or the first sample's 0
  bool active() const { return start_s || end_s; }
  bool holds(double t) const { return (!start_s || t >= *start_s) && (!end_s || t <= *end_s); }
};

/// "start_s = 1.2, end_s = 8" (empty when not active).
std::string describe_range(const TimeRange& range);

/// Keeps the pulses inside the range; a segment left with fewer than two goes.
void trim_pulse_train(PulseTrain& train, const TimeRange& range);

/// Keeps the whole turns inside the range: each segment cut to its first and
/// last position-0 edge inside it (P positions per turn).
void trim_numbered_edges(NumberedEdges& edges, const TimeRange& range);

/// The two warnings above for the planned turns, the recording spanning
/// [file_start_s, file_end_s] and the range used.
std::vector<std::string> range_warnings(const std::vector<RevolutionPlan>& plan, double file_start_s,
                                        double file_end_s, const TimeRange& range);

}  // namespace fourbar
