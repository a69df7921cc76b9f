#pragma once
// The set-up check: from the analysed data alone, what the manifest should
// have said, compared with what it says.
//
// The analysis inverts the conversion with the manifest's values, so the
// averaged α (tangential channel) or ω² (normal channel) of a link, put back
// through the same affine conversion (conversion.hpp) with the manifest's
// mount, gives the calibrated reading itself on the crank-angle grid. Per
// crank order q that is G_q·m + (1 − G_q)·f0_manifest, G the analysis
// filter's gain (α was filtered, the terms added back were not), so the fit
// compares G·m with G·template; its mean is not fitted. The nominal mechanism
// predicts that reading for any set-up: at the mean crank speed a sensor at
// distance r along the link reads f(θ2) = f0(θ2) + r·f1(θ2), with
//   tangential  f0 = a_J·n − h·ω² + g·cos θ,  f1 = α        (centripetal
//               crank-pin term ∝ ω2², gravity's once-per-turn signature)
//   normal      f0 = a_J·u − h·α + g·sin θ,   f1 = −ω²       (centripetal)
// With the true set-up the reading on the manifest's grid is
//   m(θk) = A·[f0(φk) + r·f1(φk)],  φk = θ0 + τ·360°·k/N,
// A = axis sign × calibration ratio, θ0 the crank angle at the pulse, τ the
// direction of rotation. The check fits these by least squares against the
// nominal templates, every pulse angle and both directions at once (circular
// cross-correlation by FFT), jointly over the channels (they share θ0 and τ),
// for both assignments of the tangential channels to coupler and rocker:
//   crank_offset_deg, crank_direction  the best (θ0, τ);
//   coupler/rocker swapped             the best assignment;
//   axis_sign                          the sign of A (r fixed at the manifest's);
//   volts_per_unit                     |A|;
//   position_mm                        B/A from the two-term fit A·f0 + B·f1.
// Only the crank orders that hold the nominal response are fitted (1 … K, K
// holding all but 1e-4 of the templates' energy: 5 for the thesis rig).
// Each is flagged when the data's value lies outside a tolerance of the
// manifest's AND explains the data clearly better: the confidence is the
// share of the misfit with the manifest's value that the data's value
// removes, 1 − U_data/U_manifest (U: the unexplained share of the reading's
// energy, the other parameters fitted). Impacts (clearance) add broadband
// content nearly orthogonal to the smooth nominal templates; an AC-coupled
// sensor loses only the mean, which the fit leaves out anyway. With few
// channels the response mirrored (other direction) at another pulse angle
// can fit nearly as well: then one finding names both crank keys.

#include <optional>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"

namespace fourbar {

struct RecordingAnalysis;

/// Tolerances: a value outside them, explained clearly better by the data, is a finding.
struct SetupCheckLimits {
  double min_confidence = 0.5;       ///< share of the misfit the data's value must remove
  double offset_tolerance_deg = 3;   ///< crank_offset_deg (the estimate is within ±0.5° on the matrix)
  double scale_tolerance = 1.5;      ///< volts_per_unit: ratio data/manifest outside [1/x, x]
  double position_tolerance_mm = 20; ///< position_mm
  double common_scale_tolerance = 0.05; ///< every channel's scale beyond 1 ± this, same side (correct manifests: ≤ 0.002)
  double channel_scale_tolerance = 0.10; ///< one channel's scale beyond 1 ± this (correct manifests: ≤ 0.0243, setup_check_matrix)
  double min_fit = 0.5;              ///< a channel's fit (share explained) below which its own keys are not judged
};

/// One likely mistake in the manifest.
struct SetupFinding {
  std::string item;        ///< "axis_sign", "volts_per_unit", "position_mm", "highpass_hz", "crank_offset_deg", "polarity", "crank_direction", "channels_swapped", "common_scale"
  std::string channel;     ///< the channel concerned (empty for the crank)
  std::string key;         ///< where to change it, e.g. [[channel]] name="coupler_t" axis_sign
  std::string manifest;    ///< what the manifest says
  std::string data;        ///< what the data say
  double confidence = 0;   ///< 0 … 1
  std::string message;     ///< one line: what, manifest, data, confidence, key
};

/// What the data say about one accelerometer channel.
struct ChannelSetupEstimate {
  std::string channel;
  ChannelRole role = ChannelRole::ignore;
  std::string fitted_as;       ///< the role whose template fits it best (differs when swapped)
  double scale = 0;            ///< A with the manifest's position: sign × calibration ratio (1: as the manifest)
  double position_mm = 0;      ///< from the two-term fit; NaN when the reading cannot tell it (a rocker sensor: only gravity's term beside α)
  double position_confidence = 0;
  double fit = 0;              ///< share of the reading's energy the data's set-up explains
  double fit_manifest = 0;     ///< … that the manifest's set-up explains (no free parameter)
};

struct SetupCheck {
  bool checked = false;
  std::string not_checked;          ///< why not (thesis conversion, no averaged data)
  std::vector<SetupFinding> findings;
  std::vector<ChannelSetupEstimate> channels;
  double crank_offset_deg = 0;      ///< the data's pulse angle
  double crank_direction = 1;       ///< the data's direction (+1 ccw)
  bool swapped = false;             ///< coupler and rocker tangential channels swapped
  double fit = 0, fit_manifest = 0; ///< mean over the channels
  std::size_t band_orders = 0;      ///< crank orders 1 … this fitted (the nominal response's band)
  /// The normal channels' consistency figure, RMS(ω²_normal − ω²_integrated)/RMS(ω²_integrated), when present.
  std::vector<std::pair<std::string, double>> normal_consistency;

  /// "ok", "check set-up" or "not checked".
  std::string status() const;
};

/// Runs the check on a finished analysis with its manifest (the one the
/// analysis used: its rig, channels, pulse). Pure: reads only its arguments.
SetupCheck check_setup(const RecordingAnalysis& analysis, const Manifest& manifest, const SetupCheckLimits& limits = {});

}  // namespace fourbar
