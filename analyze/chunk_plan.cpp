// Chunk planning (chunk_plan.hpp).
#include "analyze/chunk_plan.hpp"

#include <algorithm>
#include <cmath>

#include "analyze/analysis_defaults.hpp"

namespace fourbar {

double slowest_revolution_frames(double sample_rate_hz, double min_rpm) {
  return sample_rate_hz * 60.0 / std::max(min_rpm, 1e-9);  // samples in the slowest revolution
}

std::size_t chunk_overlap_frames(std::size_t kernel_taps, double frames_per_rev) {
  const std::size_t half_kernel_frames = kernel_taps / 2;
  return (kernel_taps > 0 ? half_kernel_frames : static_cast<std::size_t>(std::ceil(2 * frames_per_rev))) + 8;
}

// Chunks of K revolutions. A chunk with its overlaps, or the periodic
// continuation at a segment end, is at most K revolutions + 2·overlap +
// half a kernel long (a segment's tail chunk takes what is left: less than
// K revolutions + overlap); its linear convolution needs half a kernel of
// zeros more. K is chosen so that this fits an FFT of 2^20 samples (more
// for very long kernels): the transforms then cost about 1.5× the chunk's
// own samples. The ideal filter (thesis) takes the chunk as one period.
std::size_t plan_chunk_revolutions(std::size_t requested_revolutions, std::size_t kernel_taps,
                                   std::size_t overlap_frames, double slowest_rev_frames, double frames_per_rev) {
  std::size_t chunk_revolutions = requested_revolutions;
  if (chunk_revolutions == 0) {
    if (kernel_taps > 0) {
      double fft_frames = double(analysis_defaults::kChunkFftFrames);
      while (fft_frames < 8.0 * double(overlap_frames)) fft_frames *= 2;
      chunk_revolutions = static_cast<std::size_t>(
          std::max(1.0, std::floor((fft_frames - 4.0 * double(overlap_frames) - 64) / slowest_rev_frames)));
    } else {
      chunk_revolutions = static_cast<std::size_t>(
          std::max(1.0, std::ceil(double(analysis_defaults::kIdealChunkFrames) / frames_per_rev)));
    }
  }
  return chunk_revolutions;
}

std::size_t filter_block_frames(std::size_t chunk_revolutions, double slowest_rev_frames, std::size_t overlap_frames,
                                double longest_segment_frames, std::size_t half_kernel_frames) {
  const double longest_chunk = std::min(double(chunk_revolutions) * slowest_rev_frames + 2.0 * double(overlap_frames),
                                        longest_segment_frames + 2.0);
  return static_cast<std::size_t>(std::ceil(longest_chunk + double(half_kernel_frames))) + 16;
}

}  // namespace fourbar
