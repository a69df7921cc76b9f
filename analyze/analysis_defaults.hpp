#pragma once
// The defaults analyze picks when an option is left unset: each number that
// is a choice, with its unit and the reason for it, in this one place. The
// doc comments in pipeline.hpp and `fourbar analyze --help` read from here.

#include <cstddef>

namespace fourbar::analysis_defaults {

// ---- the α filter (FilterSettings)

/// Lower corner, per Hz of mean crank frequency (half the crank frequency):
/// keeps the first crank order in the pass band, removes the drift below it.
inline constexpr double kLowCornerPerCrankHz = 0.5;

/// Upper corner cap, Hz: the default upper corner when the sample rate allows.
inline constexpr double kHighCornerCapHz = 1000.0;
/// Upper corner at most this fraction of the sample rate (Nyquist is 0.5):
/// leaves room for the transition band below the Nyquist frequency.
inline constexpr double kHighCornerMaxPerSampleRate = 0.4;

/// Transition width of the windowed-sinc kernel, per Hz of mean crank
/// frequency: narrow enough that the lower corner's transition band stays
/// clear of the first crank order (the kernel is then several revolutions
/// long; widened, with a warning, to fit a short record).
inline constexpr double kTransitionPerCrankHz = 0.15;

// ---- the crank-angle grid (AnalyzeOptions::grid_points_per_rev)

/// Default crank angles per revolution N: half-degree steps.
inline constexpr std::size_t kGridPoints = 720;
/// A band that needs more grows N in steps of this many points, so the
/// grid angles stay whole fractions of a degree.
inline constexpr std::size_t kGridPointsStep = 360;
/// Highest crank order the grid holds, per grid point: below the grid's
/// Nyquist order 0.5·N, with a margin for the resampler.
inline constexpr double kGridMaxOrdersPerPoint = 0.4;

// ---- processing chunks (AnalyzeOptions::chunk_revolutions)

/// Windowed filter: a chunk with its overlaps and the half kernel of zeros
/// fits an FFT of 2^20 frames (doubled for very long kernels): large enough
/// that the overlaps cost little, small enough to bound memory by one chunk.
inline constexpr int kChunkFftFramesLog2 = 20;
inline constexpr std::size_t kChunkFftFrames = std::size_t{1} << kChunkFftFramesLog2;

/// Ideal (bin-wise) filter: the chunk is one period of its own FFT, at least
/// 2^19 frames of whole revolutions.
inline constexpr int kIdealChunkFramesLog2 = 19;
inline constexpr std::size_t kIdealChunkFrames = std::size_t{1} << kIdealChunkFramesLog2;

}  // namespace fourbar::analysis_defaults
