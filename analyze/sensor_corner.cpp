#include "analyze/sensor_corner.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "common/units.hpp"

namespace fourbar {

namespace {

/// The discrete first-order high-pass of ac_coupling.cpp at f (1 for corner 0).
std::complex<double> high_pass(double corner_hz, double f_hz, double fs) {
  if (corner_hz <= 0) return 1.0;
  const double a = units::kTwoPi * corner_hz / fs;
  const double d = std::exp(-a), g = -std::expm1(-a) / a;
  const std::complex<double> z1 = std::polar(1.0, -units::kTwoPi * f_hz / fs);  // e^−iω
  return g * (1.0 - z1) / (1.0 - d * z1);
}

/// Share of the corrected reading's energy that k·templ leaves (k real, fitted).
double misfit(std::span<const std::complex<double>> reading, std::span<const std::complex<double>> templ,
              std::span<const double> order_hz, double manifest_corner_hz, double corner_hz, double fs) {
  double mt = 0, tt = 0, mm = 0;
  for (std::size_t q = 1; q < reading.size(); ++q) {
    const std::complex<double> x =
        reading[q] * high_pass(manifest_corner_hz, order_hz[q], fs) / high_pass(corner_hz, order_hz[q], fs);
    mt += std::real(std::conj(x) * templ[q]);
    tt += std::norm(templ[q]);
    mm += std::norm(x);
  }
  if (!(mm > 0) || !(tt > 0)) return 1.0;
  return std::max(0.0, 1.0 - mt * mt / (tt * mm));
}

}  // namespace

CornerFit fit_high_pass_corner(std::span<const std::complex<double>> reading,
                               std::span<const std::complex<double>> templ, std::span<const double> order_hz,
                               double manifest_corner_hz, double sample_rate_hz) {
  assert(reading.size() == templ.size() && reading.size() == order_hz.size());
  const double fs = sample_rate_hz;
  auto u = [&](double c) { return misfit(reading, templ, order_hz, manifest_corner_hz, c, fs); };
  CornerFit out;
  out.unexplained_manifest = u(manifest_corner_hz);
  out.corner_hz = 0;
  out.unexplained = u(0);
  if (reading.size() < 2) return out;
  // Log grid in ln c, then golden-section refinement around the best point.
  const double lo = std::log(0.01), hi = std::log(4 * order_hz[1]);
  constexpr int kGrid = 64;
  const double step = (hi - lo) / (kGrid - 1);
  int best = -1;
  double best_u = out.unexplained;
  for (int i = 0; i < kGrid; ++i) {
    const double v = u(std::exp(lo + step * i));
    if (v < best_u) best_u = v, best = i;
  }
  if (best < 0) return out;  // DC fits best
  double a = lo + step * std::max(best - 1, 0), b = lo + step * std::min(best + 1, kGrid - 1);
  const double r = (std::sqrt(5.0) - 1) / 2;
  double x1 = b - r * (b - a), x2 = a + r * (b - a);
  double f1 = u(std::exp(x1)), f2 = u(std::exp(x2));
  for (int it = 0; it < 40; ++it) {
    if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - r * (b - a), f1 = u(std::exp(x1));
    else a = x1, x1 = x2, f1 = f2, x2 = a + r * (b - a), f2 = u(std::exp(x2));
  }
  const double x = f1 < f2 ? x1 : x2, v = std::min(f1, f2);
  if (v < best_u) best_u = v;
  out.corner_hz = v <= best_u ? std::exp(x) : std::exp(lo + step * best);
  out.unexplained = best_u;
  return out;
}

}  // namespace fourbar
