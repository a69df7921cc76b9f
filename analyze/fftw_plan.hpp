#pragma once
// A real-to-complex / complex-to-real FFTW plan pair for one transform
// length, with its own aligned buffers: made once, executed many times.
// The plans of the last few lengths are cached and shared between
// instances (each executes them on its own buffers). FFTW's planner is not
// thread-safe; planning is serialised here.

#include <fftw3.h>

#include <complex>
#include <cstddef>
#include <memory>
#include <span>

namespace fourbar {

class RealFft {
 public:
  /// `flags`: FFTW_ESTIMATE (default, instant) or FFTW_MEASURE (slower
  /// planning, faster transforms for long runs).
  explicit RealFft(std::size_t n, unsigned flags = FFTW_ESTIMATE);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  std::size_t size() const { return n_; }
  std::size_t bins() const { return n_ / 2 + 1; }
  /// Time-domain buffer (n values).
  std::span<double> time() { return {real_, n_}; }
  /// Frequency-domain buffer (n/2 + 1 bins, bin k at k/n cycles per sample).
  std::span<std::complex<double>> spectrum() { return {reinterpret_cast<std::complex<double>*>(spec_), bins()}; }
  /// time → spectrum (unnormalised DFT).
  void forward();
  /// spectrum → time, times n (unnormalised); overwrites the spectrum.
  void inverse();

  struct Plans;  // one length's plan pair, shared (see fftw_plan.cpp)

 private:
  std::size_t n_;
  double* real_ = nullptr;
  fftw_complex* spec_ = nullptr;
  std::shared_ptr<Plans> plans_;
};

/// Smallest n' ≥ n whose factors are only 2, 3, 5 and 7 (fast FFTW sizes).
std::size_t fast_fft_size(std::size_t n);

}  // namespace fourbar
