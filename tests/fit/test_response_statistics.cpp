// The fit's statistics against values known in closed form, and their
// jackknife errors against the scatter over independent repetitions.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "common/error.hpp"
#include "common/units.hpp"
#include "fit/response_statistics.hpp"

namespace fourbar {
namespace {

using units::kPi;

TEST(ResponseStatistics, ClosedFormsOfDeterministicTurns) {
  // Turn r: nominal + c_r·sin(θ) with c_r alternating a ± b: per angle the
  // mean is a·sin, the sample variance over R turns b²·sin²·R/(R−1).
  const std::size_t n = 360, turns = 10;
  const double a = 2.0, b = 0.5;
  std::vector<double> nominal(n), x(n * turns);
  for (std::size_t k = 0; k < n; ++k) nominal[k] = std::cos(2 * kPi * k / n) * 7.0;
  for (std::size_t r = 0; r < turns; ++r)
    for (std::size_t k = 0; k < n; ++k) x[r * n + k] = nominal[k] + (a + (r % 2 ? b : -b)) * std::sin(2 * kPi * k / n);
  const StatisticValues s = response_statistics(x, nominal);
  EXPECT_NEAR(s.value[index_of(ResponseStatistic::mean_deviation)], a / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s.value[index_of(ResponseStatistic::spread)], b * std::sqrt(turns / (turns - 1.0)) / std::sqrt(2.0), 1e-12);
  // Per-turn RMS a ± b over √2 (median of the 5 + 5 values: their middle).
  EXPECT_NEAR(s.value[index_of(ResponseStatistic::turn_deviation)], a / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s.value[index_of(ResponseStatistic::peak_median)], a, 1e-3);  // midway between a − b and a + b
  EXPECT_NEAR(s.value[index_of(ResponseStatistic::turn_correlation)], 1.0, 1e-12);  // same shape every turn
  EXPECT_EQ(s.turns, turns);
}

TEST(ResponseStatistics, JackknifeErrorMatchesScatterOverRepetitions) {
  // White noise σ per point: spread ≈ σ, its standard error over
  // independent repetitions measured and compared with the jackknife's.
  const std::size_t n = 256, turns = 24;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> nominal(n, 0.0), spreads, errors;
  for (int rep = 0; rep < 200; ++rep) {
    std::vector<double> x(n * turns);
    // A slow per-turn level so that the spread varies between turns too.
    for (std::size_t r = 0; r < turns; ++r) {
      const double level = 1.0 + 0.5 * std::abs(g(rng));
      for (std::size_t k = 0; k < n; ++k) x[r * n + k] = level * g(rng);
    }
    const StatisticValues s = response_statistics(x, nominal);
    spreads.push_back(s.value[index_of(ResponseStatistic::turn_deviation)]);
    errors.push_back(s.standard_error[index_of(ResponseStatistic::turn_deviation)]);
  }
  double m = 0, v = 0, e = 0;
  for (double s : spreads) m += s / spreads.size();
  for (double s : spreads) v += (s - m) * (s - m) / (spreads.size() - 1);
  for (double s : errors) e += s / errors.size();
  // The jackknife's mean error within 30 % of the true scatter.
  EXPECT_NEAR(e / std::sqrt(v), 1.0, 0.3) << "mean jackknife error " << e << ", true " << std::sqrt(v);
}

TEST(BandEnergy, ExcessAboveWhiteNoiseFloor) {
  // Noise σ everywhere plus a burst of RMS A over 20 % of the turn: the
  // excess is √(0.2)·A, the floor σ.
  const std::size_t n = 500, turns = 40;
  const double sigma = 1.0, amplitude = 5.0;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> x(n * turns);
  for (std::size_t r = 0; r < turns; ++r)
    for (std::size_t k = 0; k < n; ++k) x[r * n + k] = sigma * g(rng) + (k < n / 5 ? amplitude * g(rng) : 0.0);
  const BandEnergy b = band_energy(x, n);
  EXPECT_NEAR(b.excess, std::sqrt(0.2) * amplitude, 0.1 * std::sqrt(0.2) * amplitude);
  EXPECT_NEAR(b.floor, sigma, 0.15);
  EXPECT_GT(b.standard_error, 0.0);
  // Noise alone: the excess is the quantile's scatter, well below 3× the floor.
  for (std::size_t r = 0; r < turns; ++r)
    for (std::size_t k = 0; k < n; ++k) x[r * n + k] = sigma * g(rng);
  const BandEnergy q = band_energy(x, n);
  EXPECT_LT(q.excess / q.floor, 1.0);
}

TEST(ResponseStatistics, RejectsRaggedInput) {
  std::vector<double> nominal(10), x(25);
  EXPECT_THROW(response_statistics(x, nominal), std::exception);
}

}  // namespace
}  // namespace fourbar
