#pragma once
// Zero-phase FFT filtering with FFTW (plans made once per filter and reused).
//
// FftFilter filters whole records of one length:
//  - ideal spec (transition 0): the record's FFT bins outside the pass bands
//    are zeroed (thesis §7.2), i.e. a circular filter: the record is treated
//    as one period (right for whole revolutions in steady state);
//  - windowed kernel, Boundary::periodic: the kernel applied circularly;
//  - windowed kernel, Boundary::zero: linear convolution, the record
//    continued by zeros (no wrap-around), equal to OverlapSaveFilter;
//  - Boundary::reflect (ideal or windowed): the record continued by its
//    mirror image at both ends (period 2N, as a DCT), so a record that does
//    not hold whole periods (mains hum, a drifting crank speed) has no jump
//    at the ends and far less edge ringing than the periodic boundary.
// OverlapSaveFilter streams a record of any length through the windowed
// kernel in blocks, in memory bounded by the FFT block.

#include <memory>
#include <span>
#include <vector>

#include "analyze/fftw_plan.hpp"
#include "analyze/filter_design.hpp"

namespace fourbar {

enum class Boundary { periodic, zero, reflect };

class FftFilter {
 public:
  /// Validates the spec (InputError). `length` ≥ 1 samples; a periodic
  /// windowed kernel must not be longer than the record. `shared`: another
  /// filter's transform, used when its length fits (making an FFTW plan of
  /// a million points costs about as much as three transforms: its twiddle
  /// factors), so filters of one record share it.
  FftFilter(const FilterSpec& spec, double sample_rate_hz, std::size_t length, Boundary boundary = Boundary::periodic,
            std::shared_ptr<RealFft> shared = nullptr);

  std::size_t length() const { return length_; }
  /// Transform length (the record length; longer for zero, 2N for reflect).
  std::size_t fft_size() const { return fft_->size(); }
  /// The transform, to share with another filter of the same length.
  const std::shared_ptr<RealFft>& transform() const { return fft_; }
  /// The real (zero-phase) response at bin k, frequency k·fs/fft_size().
  std::span<const double> response() const { return response_; }

  /// Filters `in` (length() samples; with zero boundaries any length up to
  /// length()) into `out` of the same size (may be the same memory).
  void apply(std::span<const double> in, std::span<double> out);
  /// Zero boundaries: filters the concatenation before + x + after (at most
  /// length() samples) and writes the outputs at x's samples into `out`
  /// (x.size()), without building the concatenation.
  void apply_between(std::span<const double> before, std::span<const double> x, std::span<const double> after,
                     std::span<double> out);

 private:
  void filter_buffer();  // the transform buffer through the response

  std::size_t length_;
  bool reflect_, zero_;
  std::shared_ptr<RealFft> fft_;
  std::vector<double> response_;
};

/// The filter's real (zero-phase) response at the n/2 + 1 frequencies
/// k·fs/n: the ideal response for transition 0, else the kernel's (wrapped
/// modulo n when longer, which samples its response exactly).
std::vector<double> zero_phase_response(const FilterSpec& spec, double sample_rate_hz, std::size_t n);

class OverlapSaveFilter {
 public:
  /// Windowed specs only (transition_hz > 0). `fft_block` 0 picks a power of
  /// two ≥ 4·(taps − 1) (at least 1024).
  OverlapSaveFilter(const FilterSpec& spec, double sample_rate_hz, std::size_t fft_block = 0);

  std::size_t taps() const { return 2 * half_ + 1; }
  std::size_t fft_size() const { return fft_.size(); }

  /// Feeds samples; appends the outputs that are complete to `out` (they lag
  /// the input by half the kernel).
  void push(std::span<const double> in, std::vector<double>& out);
  /// Ends the record (zeros beyond it) and appends the remaining outputs: in
  /// total exactly as many outputs as inputs. The filter can then be reused.
  void finish(std::vector<double>& out);

 private:
  void run_block(std::size_t emit, std::vector<double>& out);

  std::size_t half_;
  RealFft fft_;
  std::vector<double> response_;
  std::vector<double> window_;  // inputs from the block start onwards
  std::size_t received_ = 0, emitted_ = 0;
};

}  // namespace fourbar
