#include "analyze/known_response.hpp"

#include <cmath>
#include <complex>

#include "analyze/fftw_plan.hpp"
#include "common/units.hpp"

namespace fourbar {

void undo_known_response(std::span<double> x, double fs, double delay_s, const std::vector<AnalogSection>& sections) {
  const std::size_t n = x.size();
  if ((delay_s == 0 && sections.empty()) || n < 4) return;
  // Line through the ends: x_k = s(t_k + d), line L(k) = a + b·k.
  const double a = x[0], b = (x[n - 1] - x[0]) / static_cast<double>(n - 1);
  RealFft fft(n);
  auto t = fft.time();
  for (std::size_t k = 0; k < n; ++k) t[k] = x[k] - (a + b * static_cast<double>(k));
  fft.forward();
  auto spec = fft.spectrum();
  const double shift_samples = delay_s * fs;
  for (std::size_t k = 0; k < spec.size(); ++k) {
    const double f_hz = static_cast<double>(k) / static_cast<double>(n) * fs;
    std::complex<double> factor = std::polar(1.0, -units::kTwoPi * f_hz * delay_s);
    if (!sections.empty()) {
      const std::complex<double> h = analog_response(sections, f_hz);
      factor *= std::abs(h) >= 0.1 ? 1.0 / h : std::conj(h) / std::abs(h);
    }
    if (2 * k == n) spec[k] *= factor.real();
    else spec[k] *= factor;
  }
  fft.inverse();
  const double inv_n = 1.0 / static_cast<double>(n);
  // s(t_k) = x at k − d·fs: the line moves by −b·d·fs.
  for (std::size_t k = 0; k < n; ++k) x[k] = t[k] * inv_n + a + b * (static_cast<double>(k) - shift_samples);
}

}  // namespace fourbar
