#pragma once
// Spectra of a uniformly sampled signal, one-sided, on a frequency axis and
// an order axis (multiples of the crank frequency).
//  - amplitude spectrum: one windowed FFT of the whole record, corrected for
//    the window's coherent gain, so a sinusoid of amplitude A centred on a
//    bin reads A (the thesis's power spectrum, Fig. 7.8, used the
//    rectangular window);
//  - Welch PSD: averaged modified periodograms of overlapping segments,
//    density scaling (unit²/Hz) with the window's power, the mean of each
//    segment removed; the definition of scipy.signal.welch(detrend='constant',
//    scaling='density'), whose periodic windows it uses too.

#include <memory>
#include <span>
#include <vector>

#include "analyze/window.hpp"

namespace fourbar {
class RealFft;
}

namespace fourbar {

struct Spectrum {
  std::vector<double> frequency_hz;
  std::vector<double> value;  ///< amplitude (unit of the signal) or density (unit²/Hz)
};

/// Amplitude spectrum of the whole record. Throws InputError for fewer than
/// 2 samples, a bad rate or window.
Spectrum amplitude_spectrum(std::span<const double> x, double sample_rate_hz, const WindowSpec& window);

struct WelchOptions {
  std::size_t segment_length = 4096;
  std::size_t overlap = 2048;  ///< samples shared by consecutive segments
  WindowSpec window{WindowType::hann, 0};
};

/// Welch PSD. Throws InputError when the segment is shorter than 2 samples
/// or longer than the record, the overlap is not below the segment length,
/// or the window is bad.
Spectrum welch_psd(std::span<const double> x, double sample_rate_hz, const WelchOptions& options);

/// Welch's segmentation as a stream, for records too long to hold: push
/// samples in order in blocks of any size; each full segment (windowed,
/// its mean removed) is transformed and its |X|² summed. psd() equals
/// welch_psd on the same samples; amplitude() is √(mean |X|²) corrected for
/// the window's coherent gain, so a steady sinusoid of amplitude A centred
/// on a bin reads A (an RMS-averaged amplitude spectrum).
class SpectrumAverager {
 public:
  /// Throws InputError for a segment shorter than 2, an overlap not below
  /// it, a bad rate or window.
  SpectrumAverager(double sample_rate_hz, const WelchOptions& options);
  ~SpectrumAverager();

  void push(std::span<const double> x);
  /// A break in the record: the partial segment is dropped.
  void restart();

  /// |X|² of the segments that lie wholly inside one piece of the stream,
  /// computed apart from the averager (on another thread) and summed later.
  struct SegmentPowers {
    std::size_t at = 0;                      ///< stream position of the piece
    std::size_t first = 0;                   ///< index of the first segment since the last restart
    std::vector<std::vector<double>> power;  ///< per segment, per bin
  };
  /// Samples pushed since the last restart (where the next push starts).
  std::size_t position() const { return position_; }
  /// The segments inside `x`, a piece of the stream starting at position
  /// `at`. Reads only the window and the sizes: safe on several threads at once.
  SegmentPowers segment_powers(std::span<const double> x, std::size_t at) const;
  /// The same into `out` (its vectors' memory reused), transformed with
  /// `fft` (segment_length() points, the caller's: one per thread).
  void segment_powers(std::span<const double> x, std::size_t at, RealFft& fft, SegmentPowers& out) const;
  /// push(x) where the segments of `powers` are summed from it instead of
  /// transformed again: bit for bit the same sums. `x` must be the piece
  /// `powers` was computed from, at position() (else std::logic_error).
  void push(std::span<const double> x, const SegmentPowers& powers);

  std::size_t segments() const { return segments_; }
  std::size_t segment_length() const { return m_; }
  std::vector<double> frequency_hz() const;
  std::vector<double> amplitude() const;
  std::vector<double> psd() const;

 private:
  void run_segment(const SegmentPowers* powers);
  /// The windowed segment, its mean removed, through `fft`.
  void transform_segment(std::span<const double> segment, RealFft& fft) const;

  double fs_;
  std::size_t m_, step_;
  std::vector<double> window_;
  double gain_ = 0, power_ = 0;  // Σw, Σw²
  std::unique_ptr<RealFft> fft_;
  std::vector<double> pending_;  // samples of the segment being filled
  std::vector<double> sum_;      // Σ|X_k|²
  std::size_t segments_ = 0;
  std::size_t position_ = 0, since_restart_ = 0;  // samples and segments since the last restart
};

/// Order of each frequency: f / f_crank, with f_crank = |ω2|/2π.
std::vector<double> order_axis(std::span<const double> frequency_hz, double crank_speed_rad_s);

}  // namespace fourbar
