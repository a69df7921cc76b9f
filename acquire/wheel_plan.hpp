#pragma once
// A crank angle from many edges per turn, from numbered edges to the
// revolutions to build: the tooth-spacing estimate (tooth_spacing.hpp), used
// when the manifest asks; each run of edges turned into an AngleTrack
// (angle_track.hpp); one RevolutionPlan per complete turn (position 0 to
// position 0), evaluated per sample on the track; the turns as a
// once-per-turn PulseTrain (for the speed statistics, the segments and what
// analyze plans with); and a WheelReport.

#include <cstddef>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "acquire/pulse_train.hpp"
#include "acquire/revolution_plan.hpp"
#include "acquire/wheel_decode.hpp"

namespace fourbar {

struct WheelReport {
  std::string source;                 ///< e.g. "tooth wheel, 60 teeth, index channel 'index'"
  int positions_per_rev = 0;          ///< P: teeth (missing ones included) or 4 × encoder lines
  std::size_t edges = 0;              ///< numbered edges used
  std::size_t turns_cut = 0;          ///< turns dropped for a wrong count
  double count_direction = 1;         ///< encoder: +1 A leads B, −1 B leads A
  bool corrected = false;             ///< tooth-spacing errors applied (correct_tooth_spacing)
  std::vector<double> tooth_error_deg;  ///< per position, orders above 2 (NaN: no tooth)
  double tooth_error_rms_deg = 0, tooth_error_max_deg = 0, tooth_error_standard_error_deg = 0;
  double once_per_turn_deg = 0, twice_per_turn_deg = 0;  ///< turn-locked signature, left in the crank motion
  std::size_t turns_averaged = 0;
};

struct WheelSchedule {
  RevolutionSchedule schedule;
  PulseTrain turns;                   ///< one pulse per turn: position-0 edges
  WheelReport report;
  std::vector<std::string> warnings;
};

/// Edges between the knots of the angle track's spline for P positions per
/// turn: 30° of crank (twelve knots per turn: speed changes up to about the
/// fourth order of the turn are followed), at least 3 edges.
std::size_t angle_knot_spacing(int positions_per_rev);

WheelSchedule plan_wheel_revolutions(const NumberedEdges& edges, const Manifest& manifest, double sample_rate_hz,
                                     int grid_points_per_rev);

}  // namespace fourbar
