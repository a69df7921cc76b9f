// FFT filters: FFTW against a direct O(N²) DFT filter and a direct
// convolution, overlap-save against the whole record, the designed response
// (pass/stop levels, mains comb, zero phase), windows and bad specs.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "analyze/fft_filter.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

std::vector<double> random_signal(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> d(0, 1);
  std::vector<double> x(n);
  for (double& v : x) v = d(rng);
  return x;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Direct DFT filter: X = DFT(x), Y_k = H(k)·X_k, y = IDFT(Y), all by sums.
template <class Response>
std::vector<double> dft_filter(const std::vector<double>& x, Response H) {
  const std::size_t n = x.size();
  std::vector<std::complex<double>> X(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::complex<double> s = 0;
    for (std::size_t i = 0; i < n; ++i) s += x[i] * std::polar(1.0, -units::kTwoPi * double((k * i) % n) / n);
    X[k] = s * H(std::min(k, n - k));
  }
  std::vector<double> y(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::complex<double> s = 0;
    for (std::size_t k = 0; k < n; ++k) s += X[k] * std::polar(1.0, units::kTwoPi * double((k * i) % n) / n);
    y[i] = s.real() / n;
  }
  return y;
}

FilterSpec bandpass_with_comb(WindowSpec w, double transition_hz) {
  FilterSpec s;
  s.band = BandType::bandpass;
  s.low_hz = 20;
  s.high_hz = 300;
  s.mains_hz = 60;
  s.mains_width_hz = 8;
  s.window = w;
  s.transition_hz = transition_hz;
  return s;
}

TEST(FftFilter, IdealFilterEqualsDirectDft) {
  const double fs = 1000;
  for (std::size_t n : {64u, 45u, 200u}) {
    const FilterSpec spec = bandpass_with_comb({}, 0.0);
    const auto bands = pass_bands(spec, fs);
    const std::vector<double> x = random_signal(n, 11);
    std::vector<double> y(n);
    FftFilter f(spec, fs, n);
    f.apply(x, y);
    const auto ref = dft_filter(x, [&](std::size_t k) { return passes(bands, fs * k / n) ? 1.0 : 0.0; });
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(y[i], ref[i], 1e-12 * max_abs(ref)) << "n " << n << " i " << i;
  }
}

TEST(FftFilter, PeriodicKernelFilterEqualsDirectDft) {
  const double fs = 1000;
  const FilterSpec spec = bandpass_with_comb({WindowType::kaiser, 6.0}, 100.0);
  const std::vector<double> kernel = design_kernel(spec, fs);
  const long m = static_cast<long>(kernel.size() / 2);
  for (std::size_t n : {96u, 151u}) {
    ASSERT_LE(kernel.size(), n);
    const std::vector<double> x = random_signal(n, 5);
    std::vector<double> y(n);
    FftFilter f(spec, fs, n, Boundary::periodic);
    f.apply(x, y);
    const auto ref = dft_filter(x, [&](std::size_t k) {
      double h = 0;
      for (long i = -m; i <= m; ++i) h += kernel[i + m] * std::cos(units::kTwoPi * double(k) * i / n);
      return h;
    });
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(y[i], ref[i], 1e-12 * max_abs(ref)) << "n " << n << " i " << i;
  }
}

TEST(FftFilter, ReflectBoundaryFiltersTheMirroredRecord) {
  const double fs = 1000;
  const FilterSpec spec = bandpass_with_comb({WindowType::kaiser, 6.0}, 100.0);
  const std::vector<double> kernel = design_kernel(spec, fs);
  const long m = static_cast<long>(kernel.size() / 2);
  const std::size_t n = 70;
  const std::vector<double> x = random_signal(n, 8);
  std::vector<double> mirrored(x);
  mirrored.insert(mirrored.end(), x.rbegin(), x.rend());
  const auto ref = dft_filter(mirrored, [&](std::size_t k) {
    double h = 0;
    for (long i = -m; i <= m; ++i) h += kernel[i + m] * std::cos(units::kTwoPi * double(k) * i / (2 * n));
    return h;
  });
  std::vector<double> y(n);
  FftFilter f(spec, fs, n, Boundary::reflect);
  EXPECT_EQ(f.fft_size(), 2 * n);
  f.apply(x, y);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(y[i], ref[i], 1e-12 * max_abs(ref)) << i;
}

// Linear convolution with the centred kernel, zeros beyond the record.
std::vector<double> direct_convolution(const std::vector<double>& x, const std::vector<double>& h) {
  const long n = static_cast<long>(x.size()), m = static_cast<long>(h.size() / 2);
  std::vector<double> y(x.size(), 0.0);
  for (long i = 0; i < n; ++i)
    for (long j = -m; j <= m; ++j)
      if (i - j >= 0 && i - j < n) y[i] += h[j + m] * x[i - j];
  return y;
}

TEST(FftFilter, ZeroBoundaryAndOverlapSaveEqualDirectConvolution) {
  const double fs = 2000;
  const FilterSpec spec = bandpass_with_comb({WindowType::hann, 0}, 40.0);
  const std::vector<double> kernel = design_kernel(spec, fs);
  const std::vector<double> x = random_signal(3000, 9);
  const std::vector<double> ref = direct_convolution(x, kernel);
  const double tol = 1e-12 * max_abs(ref);

  std::vector<double> y(x.size());
  FftFilter whole(spec, fs, x.size(), Boundary::zero);
  whole.apply(x, y);
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(y[i], ref[i], tol) << i;

  // Streamed in uneven chunks through a small block (many blocks), twice to
  // check that finish() resets the filter.
  OverlapSaveFilter os(spec, fs, 1024);
  ASSERT_LT(os.taps(), 1024u);
  std::mt19937 rng(2);
  std::uniform_int_distribution<std::size_t> chunk(1, 700);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<double> out;
    for (std::size_t at = 0; at < x.size();) {
      const std::size_t c = std::min(chunk(rng), x.size() - at);
      os.push(std::span(x).subspan(at, c), out);
      at += c;
    }
    os.finish(out);
    ASSERT_EQ(out.size(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(out[i], ref[i], tol) << "pass " << pass << " i " << i;
  }
}

// The designed response: within transition/2 of an edge it may do anything;
// elsewhere it is 1 in the pass bands and 0 in the stop bands, to the
// window's leakage level.
void check_response(const FilterSpec& spec, double fs, double tolerance) {
  const std::size_t n = 1 << 16;
  FftFilter f(spec, fs, n, Boundary::zero);
  const auto bands = pass_bands(spec, fs);
  const auto H = f.response();
  double worst = 0;
  for (std::size_t k = 0; k < H.size(); ++k) {
    const double freq = fs * k / f.fft_size();
    bool near_edge = false;
    for (const Band& b : bands)
      near_edge |= std::abs(freq - b.lo_hz) < 0.5 * spec.transition_hz ||
                   std::abs(freq - b.hi_hz) < 0.5 * spec.transition_hz;
    if (near_edge) continue;
    worst = std::max(worst, std::abs(H[k] - (passes(bands, freq) ? 1.0 : 0.0)));
  }
  EXPECT_LT(worst, tolerance) << describe(spec);
}

TEST(FftFilter, DesignedResponseMeetsWindowLeakage) {
  const double fs = 5000;
  check_response(bandpass_with_comb({WindowType::kaiser, 8.0}, 4.0), fs, 3e-4);
  check_response(bandpass_with_comb({WindowType::hann, 0}, 4.0), fs, 1e-2);
  check_response(bandpass_with_comb({WindowType::tukey, 0.5}, 4.0), fs, 0.1);
  FilterSpec lp;
  lp.band = BandType::lowpass;
  lp.high_hz = 100;
  lp.window = {WindowType::kaiser, 10.0};
  lp.transition_hz = 10;
  check_response(lp, fs, 3e-5);
  FilterSpec hp = lp;
  hp.band = BandType::highpass;
  hp.low_hz = 50;
  check_response(hp, fs, 3e-5);
  FilterSpec bs = lp;
  bs.band = BandType::bandstop;
  bs.low_hz = 200;
  bs.high_hz = 400;
  check_response(bs, fs, 3e-5);
}

TEST(FftFilter, ZeroPhaseAndMainsCombOnWholeRevolutions) {
  // 8 s at 1 kHz: every tone has a whole number of periods.
  const double fs = 1000;
  const std::size_t n = 8000;
  std::vector<double> clean(n), x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i / fs;
    clean[i] = std::sin(units::kTwoPi * 35.5 * t + 0.3) + 0.4 * std::cos(units::kTwoPi * 150 * t);
    x[i] = clean[i] + 0.8 * std::sin(units::kTwoPi * 60 * t) + 0.3 * std::sin(units::kTwoPi * 180 * t + 1) +
           0.5 * std::sin(units::kTwoPi * 2 * t) + 0.2 * std::sin(units::kTwoPi * 420 * t);
  }
  FilterSpec spec = bandpass_with_comb({}, 0.0);
  spec.mains_width_hz = 2;
  FftFilter ideal(spec, fs, n);
  ideal.apply(x, y);
  for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(y[i], clean[i], 1e-12);
  // A Kaiser kernel applied circularly: no phase shift, leakage-level error.
  spec.window = {WindowType::kaiser, 8.0};
  spec.transition_hz = 1.5;
  FftFilter kaiser(spec, fs, n);
  kaiser.apply(x, y);
  for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(y[i], clean[i], 1e-3);
}

TEST(FftFilter, BadSpecsAreInputErrors) {
  const double fs = 1000;
  auto expect_error = [&](FilterSpec s, const char* needle) {
    try {
      FftFilter f(s, fs, 512);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  FilterSpec s;
  s.band = BandType::lowpass;
  s.high_hz = 600;
  expect_error(s, "Nyquist");
  s.high_hz = -5;
  expect_error(s, "positive");
  s.band = BandType::bandpass;
  s.low_hz = 100;
  s.high_hz = 50;
  expect_error(s, "below high_hz");
  s.high_hz = 200;
  s.window = {WindowType::tukey, 1.5};
  s.transition_hz = 10;
  expect_error(s, "alpha = 1.5");
  s.window = {WindowType::kaiser, -1};
  expect_error(s, "beta = -1");
  s.window = {WindowType::hann, 0};
  s.transition_hz = 0;
  expect_error(s, "transition");
  s.window = {};
  s.mains_hz = 50;
  s.mains_width_hz = 60;
  expect_error(s, "mains_width_hz");
  s.mains_hz = 0;
  s.window = {WindowType::kaiser, 8};
  s.transition_hz = 1;  // ~5500 taps > 512 samples
  expect_error(s, "longer than the record");
  EXPECT_THROW(parse_window("kaiser", "--window"), InputError);
  EXPECT_THROW(parse_window("tukey:x", "--window"), InputError);
  EXPECT_THROW(parse_window("hamming", "--window"), InputError);
  EXPECT_THROW(parse_window("tukey:2", "--window"), InputError);
  EXPECT_EQ(parse_window("kaiser:8.5", "--window").parameter, 8.5);
}

TEST(Window, ShapesMatchTheirDefinitions) {
  const auto hann = make_window({WindowType::hann, 0}, 9, WindowSymmetry::symmetric);
  EXPECT_NEAR(hann[0], 0.0, 1e-15);
  EXPECT_NEAR(hann[4], 1.0, 1e-15);
  EXPECT_NEAR(hann[2], 0.5, 1e-15);
  const auto hp = make_window({WindowType::hann, 0}, 8, WindowSymmetry::periodic);
  EXPECT_NEAR(hp[0], 0.0, 1e-15);
  EXPECT_NEAR(hp[4], 1.0, 1e-15);
  EXPECT_NEAR(hp[2], 0.5, 1e-15);
  const auto t0 = make_window({WindowType::tukey, 0.0}, 9, WindowSymmetry::symmetric);
  const auto t1 = make_window({WindowType::tukey, 1.0}, 9, WindowSymmetry::symmetric);
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_EQ(t0[i], 1.0);
    EXPECT_NEAR(t1[i], hann[i], 1e-15);
  }
  // Kaiser: w = I0(β·√(1 − x²))/I0(β); ends I0(0)/I0(β), β = 0 rectangular.
  const auto k = make_window({WindowType::kaiser, 8.0}, 11, WindowSymmetry::symmetric);
  EXPECT_NEAR(k[0], 1.0 / 427.56411572180474, 1e-15);  // 1/I0(8)
  EXPECT_NEAR(k[5], 1.0, 1e-15);
  for (double v : make_window({WindowType::kaiser, 0.0}, 5, WindowSymmetry::symmetric)) EXPECT_EQ(v, 1.0);
}

}  // namespace
}  // namespace fourbar
