#pragma once
// Chunk planning: how many whole revolutions one processing chunk takes, how
// many frames it overlaps its neighbours by, and how long the filter blocks
// (FFT lengths) must be to hold the longest chunk. Free functions of the
// resolved filter and the recording's speed statistics.

#include <cstddef>

namespace fourbar {

/// Frames in the slowest revolution (at `min_rpm`, acquire's slowest).
double slowest_revolution_frames(double sample_rate_hz, double min_rpm);

/// Frames a chunk reads beyond each of its ends: half the kernel (windowed
/// filter, `kernel_taps` > 0) or two revolutions (ideal filter), plus the
/// resampler's stencil.
std::size_t chunk_overlap_frames(std::size_t kernel_taps, double frames_per_rev);

/// Revolutions per chunk: `requested_revolutions`, or (0) as many as fit an
/// FFT of analysis_defaults::kChunkFftFrames with their overlaps (windowed
/// filter), or about analysis_defaults::kIdealChunkFrames (ideal filter).
std::size_t plan_chunk_revolutions(std::size_t requested_revolutions, std::size_t kernel_taps,
                                   std::size_t overlap_frames, double slowest_rev_frames,
                                   double frames_per_rev);

/// Frames of the windowed filter's blocks: the longest chunk (its
/// revolutions at the slowest speed and its overlaps, at most the longest
/// segment) with half a kernel of zeros, plus a margin.
std::size_t filter_block_frames(std::size_t chunk_revolutions, double slowest_rev_frames,
                                std::size_t overlap_frames, double longest_segment_frames,
                                std::size_t half_kernel_frames);

}  // namespace fourbar
