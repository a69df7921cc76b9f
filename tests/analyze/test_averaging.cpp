// Crank-angle resampling and synchronous averaging.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analyze/angle_resampler.hpp"
#include "analyze/averaging.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

using units::kTwoPi;

TEST(Resampler, MapsAFunctionOfAngleOntoTheGrid) {
  // ~1000 samples per turn at a crank speed that varies by ±20 %.
  const double fs = 5000, w0 = 30;
  std::vector<double> angle, value;
  for (int i = 0; i < 20000; ++i) {
    const double t = i / fs;
    const double th = -1.0 + w0 * t + 0.2 * w0 / 3.0 * std::sin(3.0 * t);
    angle.push_back(th);
    value.push_back(std::sin(3 * th) + 0.5 * std::cos(7 * th + 0.3));
  }
  const double start = 0.25;
  RevolutionResampler rs(angle, 360, start);
  // Covered: from ceil((−1 − 0.25)/2π) = 0 to floor((θ_end − 0.25)/2π).
  EXPECT_EQ(rs.first_revolution(), 0);
  EXPECT_EQ(rs.revolutions(), static_cast<std::size_t>(std::floor((angle.back() - start) / kTwoPi)));
  const std::vector<double> grid = rs.resample(value);
  ASSERT_EQ(grid.size(), rs.revolutions() * 360);
  double worst = 0;
  for (std::size_t r = 0; r < rs.revolutions(); ++r)
    for (std::size_t k = 0; k < 360; ++k) {
      const double th = rs.grid_angle_rad(r, k);
      EXPECT_NEAR(th, start + kTwoPi * (r + k / 360.0), 1e-12);
      const double exact = std::sin(3 * th) + 0.5 * std::cos(7 * th + 0.3);
      worst = std::max(worst, std::abs(grid[r * 360 + k] - exact));
    }
  // Cubic interpolation: error ~ (Δθ·7)⁴/… with Δθ ≈ 2π/1000.
  EXPECT_LT(worst, 1e-6);
}

TEST(Resampler, RejectsBadAngleTracks) {
  std::vector<double> back{0.0, 1.0, 0.5, 2.0, 3.0, 7.0};
  EXPECT_THROW(RevolutionResampler(back, 36, 0.0), InputError);
  std::vector<double> short_track{0.0, 1.0, 2.0, 3.0, 4.0};
  EXPECT_THROW(RevolutionResampler(short_track, 36, 0.0), InputError);
  std::vector<double> ok{0.0, 2.0, 4.0, 6.0, 8.0};
  EXPECT_THROW(RevolutionResampler(ok, 3, 0.0), InputError);
  RevolutionResampler rs(ok, 36, 0.0);
  std::vector<double> wrong(4, 0.0);
  EXPECT_THROW(rs.resample(wrong), InputError);
}

TEST(Resampler, PlannedAgainInItsMemoryEqualsOneMadeAnew) {
  // Three tracks one after the other (long, short, longer: the chunks of a
  // recording) through one resampler, against a resampler made for each.
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> jitter(0.9, 1.1);
  RevolutionResampler reused(std::vector<double>{0.0, -1.0, -2.0, -3.0, -4.0, -5.0, -6.0, -7.0}, 90, 0.1, -1.0);
  std::vector<double> into{42.0};
  for (const int samples : {9000, 3000, 12000}) {
    std::vector<double> angle, value;
    double th = -2.0;
    for (int i = 0; i < samples; ++i) {
      th -= 0.0061 * jitter(rng);  // clockwise, uneven steps
      angle.push_back(th);
      value.push_back(std::sin(2 * th) + 0.1 * jitter(rng));
    }
    reused.plan(angle);
    const RevolutionResampler fresh(angle, 90, 0.1, -1.0);
    EXPECT_EQ(reused.first_revolution(), fresh.first_revolution());
    ASSERT_EQ(reused.revolutions(), fresh.revolutions());
    reused.resample(value, into);
    EXPECT_EQ(into, fresh.resample(value)) << samples << " samples";  // bit for bit
  }
  EXPECT_THROW(reused.plan(std::vector<double>{0.0, -1.0, 1.0, -2.0}), InputError);
}

TEST(Averaging, MeanAndSpreadPerAngle) {
  const std::size_t n = 90, revs = 40;
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.3);
  std::vector<double> data(n * revs);
  // A large common offset checks the numerical stability of the update.
  for (std::size_t r = 0; r < revs; ++r)
    for (std::size_t k = 0; k < n; ++k) data[r * n + k] = 1e6 + std::sin(kTwoPi * k / n) + noise(rng);
  const AngleAverage a = synchronous_average(data, n);
  EXPECT_EQ(a.revolutions, revs);
  for (std::size_t k = 0; k < n; ++k) {
    double mean = 0, var = 0;
    for (std::size_t r = 0; r < revs; ++r) mean += data[r * n + k] / revs;
    for (std::size_t r = 0; r < revs; ++r) var += (data[r * n + k] - mean) * (data[r * n + k] - mean) / (revs - 1);
    EXPECT_NEAR(a.mean[k], mean, 1e-9);
    EXPECT_NEAR(a.std[k], std::sqrt(var), 1e-8);
  }
  const AngleAverage one = synchronous_average(std::span(data).first(n), n);
  for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(one.std[k], 0.0);
  EXPECT_THROW(synchronous_average(std::span(data).first(n + 1), n), InputError);
}

}  // namespace
}  // namespace fourbar
