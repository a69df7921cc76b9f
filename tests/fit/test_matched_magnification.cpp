// The fit's magnification factor a against turns drawn from a known process:
// a repeatable curve d plus a deviation that differs from turn to turn (as
// chaotic impacts do), the averaged deviation mostly scatter (share ≈ 0.9,
// as on the recovery sessions).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "common/units.hpp"
#include "fit/matched_magnification.hpp"

namespace fourbar {
namespace {

using units::kPi;
constexpr std::size_t kN = 128;

/// `turns` turns of nominal 0 + scale·(d + scatter): d = 0.15·sin 7θ (RMS
/// 0.106), scatter of RMS 1 per turn from 8 orders with random amplitudes.
std::vector<double> turns_of(std::size_t turns, double scale, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 0.5);
  std::vector<double> x(turns * kN);
  for (std::size_t r = 0; r < turns; ++r) {
    double a[8], b[8];
    for (int j = 0; j < 8; ++j) a[j] = g(rng), b[j] = g(rng);
    for (std::size_t k = 0; k < kN; ++k) {
      const double th = 2 * kPi * static_cast<double>(k) / kN;
      double v = 0.15 * std::sin(7 * th);
      for (int j = 0; j < 8; ++j) v += (a[j] * std::sin((5 + j) * th) + b[j] * std::cos((5 + j) * th)) / std::sqrt(2.0);
      x[r * kN + k] = scale * v;
    }
  }
  return x;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

TEST(MatchedMagnification, OneAtTheTruthWithAnHonestError) {
  const std::size_t R = 23, M = kMagnificationTurnsPerMeasuredTurn * R;
  const std::vector<double> nominal(kN, 0.0);
  std::mt19937_64 rng(11);
  std::vector<double> a, raw, z;
  int inside = 0;
  const int reps = 200;
  for (int rep = 0; rep < reps; ++rep) {
    const StatisticValues meas = response_statistics(turns_of(R, 1.0, rng), nominal);
    const StatisticValues model = response_statistics(turns_of(M, 1.0, rng), nominal);
    const StatisticValues model_2r = response_statistics(turns_of(2 * R, 1.0, rng), nominal);
    const auto m = matched_magnification(meas, R, model, M);
    ASSERT_TRUE(m);
    a.push_back(m->value);
    inside += std::abs(m->value - 1.0) <= 2 * m->standard_error;
    z.push_back(m->standard_error);
    // The plain ratio with the model averaged over 2R turns (the fit's a before).
    raw.push_back(model_2r.value[index_of(ResponseStatistic::mean_deviation)] /
                  meas.value[index_of(ResponseStatistic::mean_deviation)]);
  }
  // The plain ratio is biased low: √((d² + σ²/2R)/(d² + σ²/R)) = 0.78 here.
  EXPECT_LT(median(raw), 0.85);
  // The matched a is centred on 1 ...
  EXPECT_NEAR(median(a), 1.0, 0.05);
  // ... and its standard error is the scatter of a over the repetitions (±30 %).
  double mean = 0, var = 0;
  for (double v : a) mean += v / reps;
  for (double v : a) var += (v - mean) * (v - mean) / (reps - 1);
  EXPECT_NEAR(median(z) / std::sqrt(var), 1.0, 0.3) << "median error " << median(z) << ", scatter " << std::sqrt(var);
  // 1 within two standard errors in about 95 % of the repetitions.
  EXPECT_GE(inside, static_cast<int>(0.88 * reps)) << inside << " of " << reps;
}

TEST(MatchedMagnification, FindsATwiceAsViolentModel) {
  const std::size_t R = 23, M = kMagnificationTurnsPerMeasuredTurn * R;
  const std::vector<double> nominal(kN, 0.0);
  std::mt19937_64 rng(12);
  std::vector<double> a;
  for (int rep = 0; rep < 40; ++rep) {
    const StatisticValues meas = response_statistics(turns_of(R, 1.0, rng), nominal);
    const StatisticValues model = response_statistics(turns_of(M, 2.0, rng), nominal);
    a.push_back(matched_magnification(meas, R, model, M)->value);
  }
  EXPECT_NEAR(median(a), 2.0, 0.15);
}

TEST(MatchedMagnification, AbsentWithoutAMeasuredDeviation) {
  StatisticValues meas, model;
  model.value[index_of(ResponseStatistic::mean_deviation)] = 1.0;
  EXPECT_FALSE(matched_magnification(meas, 23, model, 184));
  meas.value[index_of(ResponseStatistic::mean_deviation)] = 1.0;
  EXPECT_TRUE(matched_magnification(meas, 23, model, 184));
  EXPECT_FALSE(matched_magnification(meas, 1, model, 184));
}

}  // namespace
}  // namespace fourbar
