#pragma once
// Spectra over the crank orders of one averaged revolution (N grid points,
// FFT bins 0 … N/2 = orders), as the set-up check fits them.

#include <array>
#include <complex>
#include <span>
#include <vector>

#include "analyze/fftw_plan.hpp"
#include "analyze/filter_design.hpp"

namespace fourbar {

/// The spectrum of `x` (FFT bins 0 … N/2) with bin q weighted by
/// weight[q] (bins past the end cleared): the fitted orders only, each with
/// the analysis filter's gain where that is what the data went through.
std::vector<std::complex<double>> band_spectrum(const std::vector<double>& x, const std::vector<double>& weight,
                                                RealFft& fft);

/// The zero-phase gain of an analysis filter at crank orders 0 … K (order 0
/// set to 0: the mean is not fitted). `response` (optional): the filter's
/// response at the bins k·fs/n of an n-point transform (the analysis keeps
/// the α filter's, RecordingAnalysis::spectra), read by linear
/// interpolation; without it the ideal response of `spec`.
std::vector<double> order_gains(const FilterSpec& spec, std::span<const double> response, std::size_t n, double fs,
                                double crank_hz, std::size_t K);

/// Σk a[k]·b[k] of two real signals from their spectra (Parseval).
double parseval_inner(const std::vector<std::complex<double>>& A, const std::vector<std::complex<double>>& B, std::size_t N);

/// Smallest order K holding all but `share` of the energy of `x` (mean removed).
std::size_t band_order(const std::vector<double>& x, double share, RealFft& fft);

/// c[τ][s] = Σk m[k]·t[(s + τk) mod N] for τ = +1, −1, by FFT (band-limited spectra).
std::array<std::vector<double>, 2> correlations(const std::vector<std::complex<double>>& m_hat,
                                               const std::vector<std::complex<double>>& t_hat, RealFft& fft);

}  // namespace fourbar
