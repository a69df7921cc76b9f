// Amplitude spectrum and Welch PSD: sinusoid amplitudes under every window,
// white-noise level and Parseval, a direct-DFT reference, the order axis.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "analyze/spectrum.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

const WindowSpec kWindows[] = {{}, {WindowType::hann, 0}, {WindowType::tukey, 0.3}, {WindowType::kaiser, 8}};

TEST(Spectrum, AmplitudeOfBinCentredSinusoidsUnderEveryWindow) {
  const double fs = 1000;
  const std::size_t n = 2000;  // bins of 0.5 Hz
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = 0.7 + 2.5 * std::sin(units::kTwoPi * 50 * i / fs + 0.4) + 0.3 * std::cos(units::kTwoPi * 212.5 * i / fs);
  for (const WindowSpec& w : kWindows) {
    const Spectrum s = amplitude_spectrum(x, fs, w);
    ASSERT_EQ(s.frequency_hz.size(), n / 2 + 1);
    EXPECT_DOUBLE_EQ(s.frequency_hz[100], 50.0);
    // Rectangular and Hann do not leak into other bin centres; Tukey and
    // Kaiser do, at their side-lobe level (≈ 1e-6 of 2.5 here).
    const bool exact = w.type == WindowType::rectangular || w.type == WindowType::hann;
    const double tol = exact ? 1e-12 : 1e-5 * 2.5;
    EXPECT_NEAR(s.value[100], 2.5, tol) << to_string(w);
    EXPECT_NEAR(s.value[425], 0.3, tol) << to_string(w);
    EXPECT_NEAR(s.value[0], 0.7, tol) << to_string(w);
  }
}

TEST(Spectrum, WelchOfWhiteNoiseHasItsLevelAndPower) {
  const double fs = 2000, sigma = 1.7;
  std::mt19937 rng(13);
  std::normal_distribution<double> d(0, sigma);
  std::vector<double> x(200000);
  for (double& v : x) v = d(rng);
  for (const WindowSpec& w : kWindows) {
    const Spectrum s = welch_psd(x, fs, {1024, 512, w});
    // Level: 2σ²/fs; integral: σ² (Parseval, density scaling).
    double mean = 0, integral = 0;
    for (std::size_t k = 1; k + 1 < s.value.size(); ++k) mean += s.value[k] / (s.value.size() - 2);
    for (double v : s.value) integral += v * fs / 1024;
    EXPECT_NEAR(mean, 2 * sigma * sigma / fs, 0.02 * 2 * sigma * sigma / fs) << to_string(w);
    EXPECT_NEAR(integral, sigma * sigma, 0.02 * sigma * sigma) << to_string(w);
  }
}

TEST(Spectrum, WelchEqualsDirectPeriodogramAverage) {
  const double fs = 100;
  std::mt19937 rng(1);
  std::normal_distribution<double> d(0, 1);
  std::vector<double> x(230);
  for (double& v : x) v = d(rng) + 3.0;
  const WelchOptions o{64, 40, {WindowType::hann, 0}};
  const Spectrum s = welch_psd(x, fs, o);
  const std::vector<double> w = make_window(o.window, 64, WindowSymmetry::periodic);
  double u = 0;
  for (double v : w) u += v * v;
  std::vector<double> ref(33, 0.0);
  int segs = 0;
  for (std::size_t at = 0; at + 64 <= x.size(); at += 24, ++segs) {
    double mean = 0;
    for (std::size_t i = 0; i < 64; ++i) mean += x[at + i] / 64;
    for (std::size_t k = 0; k <= 32; ++k) {
      std::complex<double> X = 0;
      for (std::size_t i = 0; i < 64; ++i) X += (x[at + i] - mean) * w[i] * std::polar(1.0, -units::kTwoPi * k * i / 64.0);
      ref[k] += std::norm(X) * (k == 0 || k == 32 ? 1.0 : 2.0) / (fs * u);
    }
  }
  EXPECT_EQ(segs, 7);  // (230 − 64)/24 + 1
  for (std::size_t k = 0; k <= 32; ++k) EXPECT_NEAR(s.value[k], ref[k] / segs, 1e-12 * (1 + ref[k])) << k;
}

// The stream in pieces whose inner segments were transformed apart
// (segment_powers, as the chunks of an analysis on several threads do) sums
// to the same spectrum as pushing the samples alone, bit for bit; a piece
// given at the wrong position is refused.
TEST(Spectrum, SegmentPowersComputedApartSumTheSame) {
  std::mt19937 rng(7);
  std::normal_distribution<double> d(0, 1);
  std::vector<double> x(5000);
  for (double& v : x) v = d(rng) + 0.5;
  const WelchOptions o{256, 128, {WindowType::hann, 0}};
  SpectrumAverager plain(1000, o), apart(1000, o);
  const std::size_t cuts[] = {0, 300, 301, 1400, 1900, 3333, 5000};  // inside, across and at segment ends
  for (std::size_t i = 0; i + 1 < std::size(cuts); ++i) {
    const std::span<const double> piece = std::span(x).subspan(cuts[i], cuts[i + 1] - cuts[i]);
    plain.push(piece);
    const SpectrumAverager::SegmentPowers p = apart.segment_powers(piece, cuts[i]);
    if (piece.size() >= 2 * o.segment_length) EXPECT_FALSE(p.power.empty());
    apart.push(piece, p);
  }
  ASSERT_EQ(plain.segments(), apart.segments());
  EXPECT_EQ(plain.segments(), (5000u - 256) / 128 + 1);
  const std::vector<double> a = plain.amplitude(), b = apart.amplitude();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
  // A restart begins a new stream at position 0.
  apart.restart();
  EXPECT_EQ(apart.position(), 0u);
  const auto p = apart.segment_powers(std::span(x).subspan(0, 600), 100);
  EXPECT_THROW(apart.push(std::span(x).subspan(0, 600), p), std::logic_error);
}

TEST(Spectrum, OrderAxisAndBadInput) {
  const std::vector<double> f{0.0, 5.8333333333333333, 58.333333333333333};
  const auto o = order_axis(f, units::rpm_to_rad_s(350));
  EXPECT_NEAR(o[1], 1.0, 1e-12);
  EXPECT_NEAR(o[2], 10.0, 1e-12);
  EXPECT_THROW(order_axis(f, 0.0), InputError);
  std::vector<double> x(100, 1.0);
  EXPECT_THROW(welch_psd(x, 100, {200, 0, {}}), InputError);
  EXPECT_THROW(welch_psd(x, 100, {50, 50, {}}), InputError);
  EXPECT_THROW(welch_psd(x, 100, {50, 10, {WindowType::kaiser, 99}}), InputError);
  EXPECT_THROW(amplitude_spectrum(std::span(x).first(1), 100, {}), InputError);
  EXPECT_THROW(amplitude_spectrum(x, -1, {}), InputError);
}

}  // namespace
}  // namespace fourbar
