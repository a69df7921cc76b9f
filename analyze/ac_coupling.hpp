#pragma once
// AC-coupled (piezoelectric) accelerometers: the charge amplifier acts as a
// first-order high-pass H(s) = s/(s + ωc), ωc = 2π·f_corner. It removes the
// constant part of the specific force (most of the gravity projection) and,
// more importantly, shifts the phase of the low crank harmonics: at a 0.2 Hz
// corner the 350 rpm fundamental (5.83 Hz) is advanced by 2.0°, a 3.4 %
// error of the link acceleration if left in; at 2 Hz by 19°.
//
// Rather than high-passing the gravity model (which corrects only the constant
// and leaves the phase error), the channel is restored: between samples the
// input is taken as linear, for which the sensor's ODE y' = x' − ωc·y has the
// exact step
//   y[k+1] = e^{−a}·y[k] + (x[k+1] − x[k])·(1 − e^{−a})/a,   a = ωc/fs,
// and its exact inverse
//   x[k+1] = x[k] + (y[k+1] − e^{−a}·y[k])·a/(1 − e^{−a}),
// which recovers x up to the constant the sensor lost. The caller supplies
// that constant as the record mean (conversion.hpp derives it from the model).
// Slow noise drift of the restored signal (ωc × the running integral of the
// noise) lies far below the crank frequency and is removed by the band-pass.

#include <span>

namespace fourbar {

/// The sensor's high-pass applied to `input` (forward model, e.g. for a
/// virtual rig), starting from output `initial_output`. `output` may alias `input`.
void apply_sensor_high_pass(std::span<const double> input, double sample_rate_hz, double corner_hz,
                            double initial_output, std::span<double> output);

/// Exact inverse of `apply_sensor_high_pass`, with the free constant chosen so
/// that the mean of `restored` equals `restored_mean`. `restored` may alias
/// `sensed`. Throws InputError for a non-positive rate or a negative corner.
void undo_sensor_high_pass(std::span<const double> sensed, double sample_rate_hz, double corner_hz,
                           double restored_mean, std::span<double> restored);

}  // namespace fourbar
