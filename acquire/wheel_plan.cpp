#include "acquire/wheel_plan.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "acquire/angle_track.hpp"
#include "acquire/crank_smoothing.hpp"
#include "acquire/tooth_spacing.hpp"
#include "common/format.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

std::string describe(const Manifest& m) {
  const ChannelSpec& p = m.pulse_channel();
  const ChannelSpec* idx = m.channel_with(ChannelRole::crank_index);
  const std::string index = idx ? ", index channel '" + idx->name + "'" : std::string();
  if (p.role == ChannelRole::encoder_a) return "quadrature encoder, " + std::to_string(p.lines_per_rev) + " lines" + index;
  if (p.missing_teeth > 0)
    return "tooth wheel " + std::to_string(p.pulses_per_rev) + "-" + std::to_string(p.missing_teeth);
  return "tooth wheel, " + std::to_string(p.pulses_per_rev) + " teeth" + index;
}

double deg(double rad) { return units::rad_to_deg(rad); }

void tooth_warnings(const WheelReport& r, std::vector<std::string>& w) {
  const double noise = std::max(3 * r.tooth_error_standard_error_deg, 0.005);
  if (r.tooth_error_rms_deg > noise)
    w.push_back(std::string("tooth-spacing errors of ") + format_number(r.tooth_error_rms_deg, 2) + "° RMS (largest " +
                format_number(r.tooth_error_max_deg, 2) + "°, averaged over " + std::to_string(r.turns_averaged) +
                " turns) " +
                (r.corrected ? "were corrected"
                             : "are in the crank angle; set correct_tooth_spacing = true on the wheel's channel to "
                               "correct them"));
  if (std::max(r.once_per_turn_deg, r.twice_per_turn_deg) > noise)
    w.push_back("the edges show a once-per-turn pattern of " + format_number(r.once_per_turn_deg, 2) +
                "° and a twice-per-turn one of " + format_number(r.twice_per_turn_deg, 2) +
                "°: a speed change locked to the turn or wheel eccentricity (they cannot be told apart); it is "
                "taken as crank motion");
}

}  // namespace

std::size_t angle_knot_spacing(int positions_per_rev) {
  return std::max<std::size_t>(3, static_cast<std::size_t>(std::lround(positions_per_rev * 30.0 / 360.0)));
}

WheelSchedule plan_wheel_revolutions(const NumberedEdges& edges, const Manifest& manifest, double sample_rate_hz,
                                     int grid_points_per_rev) {
  WheelSchedule w;
  const ChannelSpec& main = manifest.pulse_channel();
  const int P = edges.positions_per_rev;
  const double pitch = units::kTwoPi / P;
  WheelReport& r = w.report;
  r.source = describe(manifest);
  r.positions_per_rev = P;
  r.turns_cut = edges.turns_cut;
  r.count_direction = edges.count_direction;
  w.warnings = edges.warnings;

  const ToothSpacing ts = estimate_tooth_spacing(edges);
  r.corrected = main.correct_tooth_spacing && ts.turns > 0;
  for (double e : ts.error_rad) r.tooth_error_deg.push_back(deg(e));
  r.tooth_error_rms_deg = deg(ts.rms_rad), r.tooth_error_max_deg = deg(ts.max_abs_rad);
  r.tooth_error_standard_error_deg = deg(ts.standard_error_rad);
  r.once_per_turn_deg = deg(ts.once_per_turn_rad), r.twice_per_turn_deg = deg(ts.twice_per_turn_rad);
  r.turns_averaged = ts.turns;
  tooth_warnings(r, w.warnings);

  const bool smoothing = main.smoothing_period_turns > 0;
  const std::size_t knot_spacing =
      smoothing ? smoothing_knot_spacing(main.smoothing_period_turns, P) : angle_knot_spacing(P);
  if (smoothing) {
    w.schedule.smoothing.period_turns = main.smoothing_period_turns;
    w.schedule.smoothing.knot_spacing_turns = static_cast<double>(knot_spacing) / P;
  }
  std::vector<double> periods;
  for (std::size_t s = 0; s < edges.segments.size(); ++s) {
    const NumberedSegment& seg = edges.segments[s];
    std::vector<double> phase(seg.time_s.size());
    for (std::size_t i = 0; i < phase.size(); ++i) {
      const auto tooth = static_cast<std::size_t>(seg.position[i] % P);
      phase[i] = pitch * static_cast<double>(seg.position[i]) + (r.corrected && !std::isnan(ts.error_rad[tooth]) ? ts.error_rad[tooth] : 0.0);
    }
    r.edges += phase.size();
    std::shared_ptr<const AngleTrack> track;
    if (smoothing && phase.size() >= kSmoothingMinBlockEdges) {  // a shorter run cannot show its jitter
      SmoothedSegment smooth = smooth_segment(seg.time_s, phase, knot_spacing, angle_knot_spacing(P));
      w.schedule.smoothing.add(smooth.fit);
      track = std::move(smooth.track);
    } else {
      track = std::make_shared<const AngleTrack>(seg.time_s, phase, knot_spacing);
    }
    std::vector<Pulse> pulses;
    for (std::size_t i = 0; i < phase.size(); ++i)
      if (seg.position[i] % P == 0) pulses.push_back({track->knot(i).time_s, false});
    for (std::size_t k = 0; k + 1 < pulses.size(); ++k) {
      RevolutionPlan plan;
      plan.segment = s;
      plan.t_start = pulses[k].time_s, plan.t_end = pulses[k + 1].time_s;
      plan.curve.t0 = plan.t_start, plan.curve.h = plan.t_end - plan.t_start, plan.curve.inv_h = 1 / plan.curve.h;
      plan.curve.phase0_rad = units::kTwoPi * static_cast<double>(k);
      plan.track = track;
      periods.push_back(plan.t_end - plan.t_start);
      w.schedule.plan.push_back(std::move(plan));
    }
    if (!w.turns.segments.empty() && pulses.size() >= 2) {
      const double from = w.turns.segments.back().back().time_s, to = pulses.front().time_s;
      w.turns.gaps.push_back({from, to, 0.0});
    }
    if (pulses.size() >= 2) w.turns.segments.push_back(std::move(pulses));
  }
  std::vector<double> sorted = periods;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  w.turns.typical_period_s = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  for (auto& g : w.turns.gaps) g.periods = (g.to_s - g.from_s) / w.turns.typical_period_s;
  w.turns.edges = r.edges;
  finish_schedule(w.schedule, w.turns.typical_period_s, sample_rate_hz, grid_points_per_rev);
  return w;
}

}  // namespace fourbar
