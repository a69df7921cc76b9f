#include "analyze/crank_orders.hpp"

#include <algorithm>

namespace fourbar {

/// The spectrum of `x` (FFT bins 0 … N/2) with bin q weighted by
/// weight[q] (bins past the end cleared): the fitted orders only, each with
/// the analysis filter's gain where that is what the data went through.
std::vector<std::complex<double>> band_spectrum(const std::vector<double>& x, const std::vector<double>& weight,
                                                RealFft& fft) {
  std::copy(x.begin(), x.end(), fft.time().begin());
  fft.forward();
  std::vector<std::complex<double>> X(fft.spectrum().begin(), fft.spectrum().end());
  for (std::size_t q = 0; q < X.size(); ++q) X[q] *= q < weight.size() ? weight[q] : 0.0;
  return X;
}

/// The zero-phase gain of an analysis filter at crank orders 0 … K (order 0
/// set to 0: the mean is not fitted). `response` (optional): the filter's
/// response at the bins k·fs/n of an n-point transform (the analysis keeps
/// the α filter's, RecordingAnalysis::spectra), read by linear
/// interpolation; without it the ideal response of `spec`.
std::vector<double> order_gains(const FilterSpec& spec, std::span<const double> response, std::size_t n, double fs,
                                double crank_hz, std::size_t K) {
  std::vector<double> g(K + 1, 0.0);
  const bool sampled = n > 0 && response.size() == n / 2 + 1;
  const std::vector<Band> bands = pass_bands(spec, fs);
  for (std::size_t q = 1; q <= K; ++q) {
    const double f = static_cast<double>(q) * crank_hz;
    if (!sampled) {
      g[q] = passes(bands, f) ? 1.0 : 0.0;
      continue;
    }
    const double x = f * static_cast<double>(n) / fs;
    const auto i = std::min(static_cast<std::size_t>(x), response.size() - 2);
    const double t = x - static_cast<double>(i);
    g[q] = (1 - t) * response[i] + t * response[i + 1];
  }
  return g;
}

/// Σk a[k]·b[k] of two real signals from their spectra (Parseval).
double parseval_inner(const std::vector<std::complex<double>>& A, const std::vector<std::complex<double>>& B, std::size_t N) {
  double s = 0;
  for (std::size_t q = 0; q < A.size(); ++q) {
    const double w = (q == 0 || 2 * q == N) ? 1.0 : 2.0;
    s += w * std::real(std::conj(A[q]) * B[q]);
  }
  return s / static_cast<double>(N);
}

/// Smallest order K holding all but `share` of the energy of `x` (mean removed).
std::size_t band_order(const std::vector<double>& x, double share, RealFft& fft) {
  std::copy(x.begin(), x.end(), fft.time().begin());
  fft.forward();
  const auto X = fft.spectrum();
  double total = 0;
  for (std::size_t q = 1; q < X.size(); ++q) total += std::norm(X[q]);
  double tail = total;
  for (std::size_t q = 1; q < X.size(); ++q) {
    tail -= std::norm(X[q]);
    if (tail <= share * total) return q;
  }
  return X.size() - 1;
}

/// c[τ][s] = Σk m[k]·t[(s + τk) mod N] for τ = +1, −1, by FFT (band-limited spectra).
std::array<std::vector<double>, 2> correlations(const std::vector<std::complex<double>>& m_hat,
                                               const std::vector<std::complex<double>>& t_hat, RealFft& fft) {
  const std::size_t N = fft.size();
  std::array<std::vector<double>, 2> c;
  for (std::size_t ti = 0; ti < 2; ++ti) {
    auto spec = fft.spectrum();
    for (std::size_t q = 0; q < spec.size(); ++q) spec[q] = (ti == 0 ? std::conj(m_hat[q]) : m_hat[q]) * t_hat[q];
    fft.inverse();
    c[ti].assign(fft.time().begin(), fft.time().end());
    for (double& v : c[ti]) v /= static_cast<double>(N);
  }
  return c;
}

}  // namespace fourbar
