#pragma once
// Smoothing across turns for steady runs (manifest: crank_smoothing =
// "spline" on the crank_pulse or encoder_a channel, off by default).
//
// Without it the crank motion goes through every edge: an interpolating
// spline through the once-per-turn pulses (crank_angle.hpp), or a spline
// with knots every 30° through a wheel's edges (angle_track.hpp); each
// edge's timing jitter goes straight into θ2, ω2 and α2. With it, edge time
// against edge angle is fitted by a least-squares cubic B-spline with knots
// every smoothing_period_turns / 3 turns (the AngleTrack fit with a longer
// knot spacing), as order-analysis toolboxes smooth a tachometer:
//  • least squares with uniform knots rather than a penalised (Reinsch)
//    smoothing spline: the knot spacing alone sets what is kept — a speed
//    change with a period of three knot spacings or more is followed
//    (test_crank_smoothing: 99.2 % of its amplitude or more at smoothing_period_turns),
//    whatever the jitter or the number of edges, where a penalty weight has
//    to be chosen or estimated per recording; the number of coefficients is
//    known, so the residual the jitter alone leaves is known too (below);
//  • the normal equations are banded (four coefficients per edge), solved
//    once per segment in O(edges): memory grows with the edges, which
//    acquire holds anyway, not with the samples; no windows are needed.
//
// Guard: a run that is not steady on the chosen scale (a speed step, a
// run-up the spline cannot bend to, a fluctuation faster than the period)
// leaves edges far from the fit. The jitter the edges show on their own
// scale is estimated from 4th divided differences of edge time against
// angle (zero for any cubic; their RMS within 4 robust σ, so a step's few
// large ones are left out), independently of the fit. The residuals are compared with it in blocks of at least 16
// edges (two knot spacings): a block whose residual RMS exceeds
// kSmoothingMisfitRatio times what the jitter leaves, and amounts to more
// than kSmoothingMisfitFloorDeg of crank angle, makes acquire refuse the
// recording (exit 2) naming the key, where, by how much, and the fix.
// Refused rather than warned: the fitted θ2, ω2, α2 would be wrong there by
// about three times the jitter they were meant to remove, and every later
// stage would inherit it silently. A milder, spread-out bias — enough that
// the smoothed angle is no closer to the truth than the unsmoothed one (ω2
// and α2 usually still are; see kSmoothingWarnRatio) — is a warning naming
// the key.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "acquire/angle_track.hpp"
#include "acquire/manifest.hpp"

namespace fourbar {

/// Knot spacing = smoothing_period_turns / this (a period of three knot spacings is kept).
inline constexpr double kSmoothingKnotsPerPeriod = 3;
inline constexpr double kDefaultSmoothingPeriodTurns = 10;
/// Guard: a block's residual RMS over the jitter's expected residual above which the fit is refused …
inline constexpr double kSmoothingMisfitRatio = 3;
/// … when it is also more than this much crank angle (below it nothing downstream can tell).
inline constexpr double kSmoothingMisfitFloorDeg = 1e-3;
/// Guard blocks hold at least this many edges; a shorter run of edges (a
/// piece between gaps) is not smoothed: its motion goes through every edge.
inline constexpr std::size_t kSmoothingMinBlockEdges = 16;

/// Edges between the smoothing spline's knots for a period of `period_turns`
/// and `edges_per_turn` edges per turn (at least 2).
std::size_t smoothing_knot_spacing(double period_turns, double edges_per_turn);

/// Timing jitter (standard deviation, s) of edges at known angles from the
/// normalised 4th divided differences of time against angle: their RMS
/// within 4 robust σ of zero (the median absolute one / 0.6745). A cubic
/// t(φ) gives 0; white jitter σ gives σ. NaN below 5 edges.
double edge_timing_jitter(std::span<const double> times_s, std::span<const double> phases_rad);

/// How a smoothed track fits its edges (one segment, or the worst of several).
struct SmoothingFit {
  double jitter_s = 0;             ///< the edges' own timing jitter
  double residual_rms_s = 0;       ///< edges against the fit, whole segment
  double expected_rms_s = 0;       ///< what the jitter alone leaves: jitter·√(1 − coefficients/edges)
  double worst_ratio = 0;          ///< largest block residual RMS / expected_rms_s
  double worst_rms_s = 0, worst_rms_deg = 0, worst_from_s = 0, worst_to_s = 0;  ///< that block
  std::size_t edges = 0;
  /// Σ (smoothed − unsmoothed edge time)², and what the jitter alone puts
  /// there, jitter²·(coefficients unsmoothed − smoothed) (below).
  double shift_sq_s2 = 0, shift_noise_sq_s2 = 0, shift_noise_dof = 0;
  /// The guard: a block too far from the fit, in ratio and in angle.
  bool misfit() const { return worst_ratio > kSmoothingMisfitRatio && worst_rms_deg > kSmoothingMisfitFloorDeg; }
};

/// One segment smoothed: the track (knots every `knot_spacing` edges) and its
/// fit, compared with the unsmoothed track: the edges themselves
/// (`unsmoothed_knot_spacing` 0, one pulse per turn: the interpolating
/// spline goes through them) or an AngleTrack with knots that close.
struct SmoothedSegment {
  std::shared_ptr<const AngleTrack> track;
  SmoothingFit fit;
};
SmoothedSegment smooth_segment(std::span<const double> times_s, std::span<const double> phases_rad,
                               std::size_t knot_spacing, std::size_t unsmoothed_knot_spacing);

/// Whether the smoothing helps, from how far it moves the track. Both tracks
/// are least-squares fits, the smoothed one (nearly) inside the unsmoothed
/// one's space, so at the edges Σ(smoothed − unsmoothed)² = edges·bias² +
/// jitter²·(m_unsmoothed − m_smoothed): the jitter the smoothing removes plus
/// its own bias (what it cannot follow). The smoothed angle is closer to the
/// truth than the unsmoothed one while bias²·edges < jitter²·(m_u − m_s),
/// i.e. while the shift is below √2 times what the jitter alone explains.
/// Above that acquire warns (naming the key); judged with at least
/// kSmoothingWarnMinDof degrees of freedom (m_u − m_s).
inline constexpr double kSmoothingWarnRatio = 1.4142135623730951;
inline constexpr double kSmoothingWarnMinDof = 30;

/// What summary.json reports (period 0: smoothing off).
struct CrankSmoothingReport {
  double period_turns = 0;
  double knot_spacing_turns = 0;
  SmoothingFit fit;                ///< the segment with the worst block
  double residual_rms_s = 0;       ///< edges against the fit, all segments
  double shift_rms_s = 0;          ///< smoothed − unsmoothed track at the edges, all segments
  double shift_ratio = 0;          ///< √(Σ shift² / what the jitter explains), all segments (0: no jitter)
  double shift_noise_dof = 0;      ///< m_unsmoothed − m_smoothed, all segments
  /// Adds a segment; keeps its fit when its worst block is worse than the one kept.
  void add(const SmoothingFit& f);

 private:
  double residual_sq_s2_ = 0, shift_sq_s2_ = 0, shift_noise_sq_s2_ = 0;
  std::size_t edges_ = 0;
};

/// InputError (exit 2) when the report's worst block misfits: names the
/// recording, the key on the main crank channel, where, by how much and the fix.
void require_smoothing_fits(const CrankSmoothingReport& report, const Manifest& manifest,
                            const std::filesystem::path& recording);

/// The warning (empty: none) when the smoothing moves the track by more than
/// kSmoothingWarnRatio times what the jitter explains: its bias then costs
/// more than the jitter it removes, though nowhere by the refusal's margin.
std::string smoothing_warning(const CrankSmoothingReport& report);

}  // namespace fourbar
