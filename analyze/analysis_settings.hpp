#pragma once
// Resolution of the analysis settings from the options and the recording:
// the α filter (and the normal channels' filter), the crank-angle grid and
// the spectrum segment. Free functions with their inputs in their
// signatures, each testable alone; ChunkedAnalysis::on_plan calls them in
// order. Unset options take the defaults of analysis_defaults.hpp.

#include <cstddef>
#include <string>
#include <vector>

#include "acquire/pulse_train.hpp"
#include "analyze/filter_design.hpp"
#include "analyze/pipeline.hpp"

namespace fourbar {

/// Frames from the first to the last pulse of the longest pulse-train
/// segment (segments of fewer than 2 pulses count as 0).
double longest_segment_frames(const PulseTrain& pulses, double sample_rate_hz);

/// The α filter: unset corners and transition follow the mean crank
/// frequency and the sample rate. A windowed kernel longer than twice the
/// longest segment has its default transition widened (with a warning
/// appended to `warnings`); InputError when the settings do not fit the
/// recording.
FilterSpec resolve_filter(const FilterSettings& settings, double sample_rate_hz, double mean_crank_hz,
                          double longest_frames, std::vector<std::string>& warnings);

/// The normal channels' filter: ω² has a mean, so it keeps everything below
/// the α filter's upper corner.
FilterSpec without_low_corner(FilterSpec filter);

/// Taps of the filter's windowed-sinc kernel; 0 for the ideal (bin-wise) filter.
std::size_t filter_kernel_taps(const FilterSpec& filter, double sample_rate_hz);

/// Crank angles per revolution N: `requested_points`, or (0) the default
/// that holds the filter's pass band at the fastest revolution. A requested
/// grid that aliases the pass band gets a warning.
std::size_t resolve_grid_points(std::size_t requested_points, const FilterSpec& filter, double sample_rate_hz,
                                double fastest_crank_hz, std::vector<std::string>& warnings);

/// Frames per spectrum segment: `requested_frames`, or (0) a power of two
/// ≥ 8 revolutions, shortened to fit the longest segment.
std::size_t resolve_spectrum_segment_frames(std::size_t requested_frames, double frames_per_rev,
                                            double longest_frames);

}  // namespace fourbar
