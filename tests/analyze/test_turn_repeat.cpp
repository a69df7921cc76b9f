// analyze/turn_repeat.hpp on turns built from closed forms (periods 2 and 3
// under noise, irregular turns, a slow drift, pure noise; seeded), and the
// streaming accumulator against the formula computed directly over the
// whole grid, with and without a turn left out.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "analyze/turn_repeat.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

// Turns built from closed forms: a period-2 motion (two alternating patterns)
// under white noise, a period 3, irregular turns, a slow drift and pure
// noise. Seeded.
std::vector<double> turns_of(std::size_t turns, std::size_t n, const std::function<double(std::size_t, double)>& f) {
  std::vector<double> x;
  for (std::size_t r = 0; r < turns; ++r)
    for (std::size_t k = 0; k < n; ++k) x.push_back(f(r, units::kTwoPi * static_cast<double>(k) / static_cast<double>(n)));
  return x;
}

TEST(TurnRepeat, FindsAPeriodicMotionUnderNoiseAndNothingInIrregularTurns) {
  const std::size_t n = 360, turns = 23;
  std::mt19937 gen(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  auto pattern = [](std::size_t r, double th) { return 10 * std::sin(2 * th) + 6 * std::sin(5 * th + 1.3 * static_cast<double>(r)); };
  // Period 2: the deviation alternates sign; noise at 0.1 of it.
  const TurnRepeat two = turn_repeat(turns_of(turns, n, [&](std::size_t r, double th) {
    return 50 * std::sin(th) + (r % 2 ? 8.0 : -8.0) * std::cos(7 * th) + 0.8 * noise(gen);
  }), n);
  EXPECT_EQ(two.period, 2u);
  EXPECT_LT(two.ratio(), 0.2);
  EXPECT_NEAR(two.neighbours(), std::sqrt(2.0), 0.05);
  EXPECT_EQ(two.by_lag[0], two.neighbours());
  EXPECT_NEAR(two.by_lag[2], std::sqrt(2.0), 0.05);  // odd lags differ, even ones repeat
  EXPECT_LT(two.by_lag[3], 0.2);
  // Period 3: three patterns in turn.
  const TurnRepeat three = turn_repeat(turns_of(turns, n, [&](std::size_t r, double th) {
    return pattern(r % 3, th) + 0.3 * noise(gen);
  }), n);
  EXPECT_EQ(three.period, 3u);
  // Irregular: a random pattern each turn.
  std::uniform_real_distribution<double> phase(0.0, units::kTwoPi);
  std::vector<double> phases(turns);
  for (double& p : phases) p = phase(gen);
  const TurnRepeat irregular = turn_repeat(turns_of(turns, n, [&](std::size_t r, double th) {
    return 5 * std::sin(6 * th + phases[r]) + 0.3 * noise(gen);
  }), n);
  EXPECT_EQ(irregular.period, 0u);
  EXPECT_NEAR(irregular.ratio(), 1.0, 0.25);
  // Every turn alike but noise: no period (the spread is the noise's).
  EXPECT_EQ(turn_repeat(turns_of(turns, n, [&](std::size_t, double th) { return 50 * std::sin(th) + noise(gen); }), n).period, 0u);
  // A slow drift: every lag small, neighbours too: no period.
  EXPECT_EQ(turn_repeat(turns_of(turns, n, [&](std::size_t r, double th) { return 0.5 * static_cast<double>(r) * std::sin(th); }), n).period, 0u);
  // Too few turns for period 2 (2p + 4 = 8): not named, but said to be unconfirmed.
  const TurnRepeat few = turn_repeat(turns_of(7, n, [&](std::size_t r, double th) { return (r % 2 ? 1.0 : -1.0) * std::cos(th); }), n);
  EXPECT_EQ(few.period, 0u);
  EXPECT_EQ(few.unconfirmed_period, 2u);
  EXPECT_EQ(few.turns, 7u);
  EXPECT_EQ(two.unconfirmed_period, 0u);
  EXPECT_EQ(irregular.unconfirmed_period, 0u);
  EXPECT_THROW(turn_repeat(std::vector<double>(10, 0.0), 3), RunError);
}

/// ratio_p directly from its definition, over runs of consecutive turns:
/// deviations from the mean curve of every turn, lag pairs within a run only.
std::array<double, kMaxTurnRepeatPeriod> direct_ratios(const std::vector<std::vector<double>>& runs, std::size_t n) {
  std::vector<double> mean(n, 0.0);
  std::size_t turns = 0;
  for (const auto& run : runs) turns += run.size() / n;
  for (const auto& run : runs)
    for (std::size_t i = 0; i < run.size(); ++i) mean[i % n] += run[i] / static_cast<double>(turns);
  double dev = 0;
  for (const auto& run : runs)
    for (std::size_t i = 0; i < run.size(); ++i) dev += (run[i] - mean[i % n]) * (run[i] - mean[i % n]);
  dev /= static_cast<double>(turns * n);
  std::array<double, kMaxTurnRepeatPeriod> out{1, 1, 1, 1};
  for (std::size_t p = 1; p <= kMaxTurnRepeatPeriod; ++p) {
    double s = 0;
    std::size_t count = 0;
    for (const auto& run : runs)
      for (std::size_t i = 0; i + p * n < run.size(); ++i, ++count) s += (run[i + p * n] - run[i]) * (run[i + p * n] - run[i]);
    if (count > 0) out[p - 1] = std::sqrt(s / static_cast<double>(count) / (2 * dev));
  }
  return out;
}

TEST(TurnRepeat, StreamingEqualsTheDirectFormulaAcrossAGap) {
  const std::size_t n = 97;
  std::mt19937 gen(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  auto run = [&](std::size_t turns, double offset) {
    return turns_of(turns, n, [&](std::size_t r, double th) {
      return 300 * std::sin(th) + offset + (r % 2 ? 3.0 : -3.0) * std::cos(4 * th) + 0.3 * noise(gen);
    });
  };
  const std::vector<double> a = run(13, 0.0), b = run(9, 1.0);
  // One run: the accumulator (through turn_repeat) against the direct sums.
  const TurnRepeat whole = turn_repeat(a, n);
  const auto direct = direct_ratios({a}, n);
  for (std::size_t p = 0; p < kMaxTurnRepeatPeriod; ++p) EXPECT_NEAR(whole.by_lag[p], direct[p], 1e-12 * direct[p]) << p;
  EXPECT_EQ(whole.period, 2u);
  // Two runs with a turn left out between them: lags pair turns within a run only.
  TurnRepeatAccumulator acc(n);
  for (std::size_t r = 0; r < a.size() / n; ++r) acc.add(std::span<const double>(a).subspan(r * n, n));
  acc.gap();
  for (std::size_t r = 0; r < b.size() / n; ++r) acc.add(std::span<const double>(b).subspan(r * n, n));
  EXPECT_EQ(acc.turns(), 22u);
  const TurnRepeat split = acc.result();
  const auto direct_split = direct_ratios({a, b}, n);
  for (std::size_t p = 0; p < kMaxTurnRepeatPeriod; ++p) EXPECT_NEAR(split.by_lag[p], direct_split[p], 1e-12 * direct_split[p]) << p;
  // Without the gap, the pairs across it would count (b is out of step with a by its offset and phase).
  const TurnRepeat joined = turn_repeat([&] {
    std::vector<double> ab = a;
    ab.insert(ab.end(), b.begin(), b.end());
    return ab;
  }(), n);
  EXPECT_GT(std::abs(joined.by_lag[1] - split.by_lag[1]), 1e-6);
  EXPECT_THROW(acc.add(std::vector<double>(n + 1, 0.0)), RunError);
}

}  // namespace
}  // namespace fourbar
