#pragma once
// A link's modal frequencies and damping ratios from an accelerometer
// recording of a hammer tap (the free decay after it), for the rig file's
// `[<link>.elastic]` table (`fourbar tap REC`, docs/flex.md "Tap test").
//
// 1. The tap is the recording's largest |value|; the decay runs from just
//    after it for twice the time its envelope (RMS over 5 ms blocks) takes
//    to reach 1.5 times the noise floor (the RMS before the tap, or of the
//    record's last tenth).
//    A record clipped by an overloaded recorder (3 or more samples at its
//    largest or smallest value, two of them neighbours, the last before the
//    record's last tenth) is fitted from 0.5 ms after the last of them.
//    A later strike of the hammer (a bounce) is found where a linear
//    predictor of the free decay fails (its error's RMS over 0.5 ms blocks
//    12 times the median block's); the decay then runs from 0.5 ms after
//    the last strike, since only there is it free.
//    No decay (the record's last tenth within 10 dB of the decay's first
//    block, or an envelope that falls less than 6 dB) is an error.
// 2. Modes one at a time: the strongest peak of the zero-padded spectrum
//    (a falling half-Hann taper) of what the modes found so far leave
//    unexplained starts the next mode, then all are fitted again (step 3);
//    until no peak stands 18 dB above the spectrum's median (at most 4
//    modes; with --modes N at most kMaxTapModes, and the N lowest are
//    reported). Two close modes that make one hump come out as two.
// 3. A nonlinear least-squares fit of Σ e^{−σ_k t}(a_k cos ω_k t + b_k sin ω_k t)
//    by Levenberg–Marquardt on (σ_k, ω_k), the amplitudes solved linearly at
//    each step (variable projection, Golub–Pereyra).
// 4. Uncertainty: the covariance s²(JᵀJ)⁻¹ of all parameters at the optimum
//    (white noise), carried to f_k = √(σ² + ω²)/2π (undamped natural
//    frequency) and ζ_k = σ/√(σ² + ω²) by their gradients (1 σ). That
//    assumes the fitted modes are all there is; a real link also rings in
//    higher, more damped modes that die within the first milliseconds and
//    pull the highest fitted mode (a beam's third mode moved its second by
//    4 standard errors, tests/independent_rig/tap_beam.py). So the fit is
//    repeated from 2 ms later (kLateStart_s), and the change is each
//    estimate's window sensitivity; the uncertainty printed is both in
//    quadrature (TapMode::frequency_uncertainty_Hz).
// 5. A fitted component that does not decay over the window (σ·T not above
//    0.1 by 2 standard errors) is a steady tone (mains hum), named apart and
//    not a mode; with --modes N the N lowest of the rest are reported.

#include <span>
#include <string>
#include <vector>

namespace fourbar {

struct TapMode {
  double frequency_Hz = 0;        ///< undamped natural frequency
  double frequency_sigma_Hz = 0;  ///< its standard error
  double damping_ratio = 0;
  double damping_sigma = 0;
  double amplitude = 0;  ///< at the start of the decay, recorded units
  /// How far f and ζ move when the fit starts kLateStart_s later (0 when the
  /// decay is too short for that): unmodelled early ringing, not noise alone.
  double frequency_window_Hz = 0;
  double damping_window = 0;
  double frequency_uncertainty_Hz() const;  ///< √(σ_f² + window²)
  double damping_uncertainty() const;
};

/// The most modes a tap fit looks for (`--modes` 1 to this).
inline constexpr int kMaxTapModes = 8;

struct TapOptions {
  /// 0: as many as the spectrum shows (<= 4); N: the N lowest of all that
  /// stand out (<= kMaxTapModes are fitted), the higher ones fitted too.
  int modes = 0;
};

struct TapResult {
  std::vector<TapMode> modes;  ///< lowest frequency first
  /// With TapOptions::modes = N: the modes found above the N lowest, fitted
  /// with them and not reported (Hz).
  std::vector<double> higher_modes_Hz;
  /// Components that do not decay over the fitted window (mains hum, a
  /// machine nearby): fitted with the modes, not among them (Hz).
  std::vector<double> steady_tones_Hz;
  double tap_time_s = 0;       ///< the largest |value|, from the first sample
  /// Later strikes of the hammer (a bounce), from the first sample: the
  /// decay is fitted from after the last of them (step 1).
  std::vector<double> later_strikes_s;
  /// Samples at the record's largest or smallest value when they make a
  /// clip (step 1: an overloaded recorder's flat tops; 0: not clipped), and the last one's
  /// time: the decay is fitted from after it.
  std::size_t clipped_samples = 0;
  double clipped_until_s = 0;
  double decay_start_s = 0, decay_duration_s = 0;
  double noise_rms = 0;     ///< the floor the decay ends at
  double residual_rms = 0;  ///< of the fit over the decay
  double decay_db = 0;      ///< how far the envelope fell (dB)
};

/// Throws InputError (message: what is wrong, without the file name; the
/// caller prefixes it) when there is no decay to fit.
TapResult identify_tap_modes(std::span<const double> samples, double sample_rate_hz, const TapOptions& options = {});

}  // namespace fourbar
