// The AC-coupled sensor model: the forward high-pass against the analytic
// first-order response, and the inverse restoring the input exactly.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "analyze/ac_coupling.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

TEST(AcCoupling, ForwardMatchesFirstOrderHighPassResponse) {
  const double fs = 25600, fc = 2.0;
  for (double f : {1.0, 5.8333, 40.0}) {
    // Long enough for the start transient to die out (e^{-ωc·t} < 1e-12).
    const std::size_t n = static_cast<std::size_t>(fs * 3.0);
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(units::kTwoPi * f * i / fs);
    apply_sensor_high_pass(x, fs, fc, 0.0, y);
    const std::complex<double> H = std::complex<double>(0, f) / std::complex<double>(fc, f);
    double worst = 0;
    for (std::size_t i = n - 2000; i < n; ++i) {
      const double t = i / fs;
      const double expected = std::abs(H) * std::sin(units::kTwoPi * f * t + std::arg(H));
      worst = std::max(worst, std::abs(y[i] - expected));
    }
    // Linear interpolation between samples: error O((ω/fs)²).
    EXPECT_LT(worst, 1e-6) << f << " Hz";
  }
}

TEST(AcCoupling, InverseRestoresTheInputWithItsMean) {
  const double fs = 10000, fc = 0.2;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 1);
  std::vector<double> x(50000), y(x.size()), back(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 4.0 + 3 * std::cos(0.01 * i) + noise(rng);
  double mean = 0;
  for (double v : x) mean += v;
  mean /= x.size();
  apply_sensor_high_pass(x, fs, fc, 0.7, y);
  undo_sensor_high_pass(y, fs, fc, mean, back);
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(back[i], x[i], 1e-9) << i;
  // In place as well.
  undo_sensor_high_pass(y, fs, fc, mean, y);
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(y[i], x[i], 1e-9) << i;
}

TEST(AcCoupling, BadRateOrCornerIsInputError) {
  std::vector<double> x(4, 1.0), y(4);
  EXPECT_THROW(apply_sensor_high_pass(x, 0.0, 1.0, 0.0, y), InputError);
  EXPECT_THROW(apply_sensor_high_pass(x, 100.0, -1.0, 0.0, y), InputError);
  EXPECT_THROW(undo_sensor_high_pass(x, 100.0, 60.0, 0.0, y), InputError);
}

}  // namespace
}  // namespace fourbar
