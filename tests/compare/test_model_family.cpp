// The model-family check (compare/model_family.hpp) on turns made by
// tests/support/impact_turns.hpp: an impact-like broadband response in both,
// white noise in the measurement, and — in some — a damped 600 Hz ringing
// after each impact that the model lacks.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/units.hpp"
#include "compare/model_family.hpp"
#include "support/impact_turns.hpp"

namespace fourbar {
namespace {

using test::kCrankHz;
using test::kN;
using test::nominal;
using test::turns;
using units::kPi;

TEST(ModelFamily, RigidMeasurementOfAnotherRestitutionNamesNothing) {
  // A model 1.6x more violent than the measurement, noise in the measurement only.
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto measured = turns(25, 200, 5, 0, seed), model = turns(20, 320, 0, 0, seed + 100);
    const ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, {});
    ASSERT_TRUE(c.checked) << c.not_checked;
    EXPECT_TRUE(c.unmodelled.empty()) << "seed " << seed << ": " << c.unmodelled.front().kind << " at " << c.unmodelled.front().low_hz;
    EXPECT_FALSE(c.judged_below_hz);
  }
}

TEST(ModelFamily, RingingTheModelLacksIsNamedWithItsBand) {
  // The same impacts and noise (seed 7) with and without a 600 Hz ring.
  const auto measured = turns(25, 200, 5, 1.0, 7), rigid = turns(25, 200, 5, 0, 7), model = turns(20, 320, 0, 0, 8);
  const ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, {});
  ASSERT_TRUE(c.checked);
  ASSERT_FALSE(c.unmodelled.empty());
  const UnmodelledEnergy& u = c.unmodelled.front();
  EXPECT_LE(u.low_hz, 600);
  EXPECT_GE(u.high_hz, 600);
  EXPECT_NEAR(u.peak_hz, 600, 10);
  EXPECT_EQ(u.kind, "narrow resonance");
  EXPECT_GT(u.rms_share, kMinRmsShare);
  ASSERT_TRUE(c.judged_below_hz);
  const double cut = std::min(u.low_hz, kCutShareOfPeak * u.peak_hz);
  EXPECT_DOUBLE_EQ(*c.judged_below_hz, cut);
  // Below the cut the ring weighs far less: over the whole band it makes the
  // scatter 3× the rigid one (its energy is 10× the impacts'); below the cut
  // only its flank remains (this synthetic ring is a bare damped sine, whose
  // flank is heavier than a mode's response).
  const double below_ring = turn_scatter(low_passed_turns(measured, kN, cut / kCrankHz), kN);
  const double below_rigid = turn_scatter(low_passed_turns(rigid, kN, cut / kCrankHz), kN);
  const double whole = turn_scatter(measured, kN) / turn_scatter(rigid, kN);
  EXPECT_GT(whole, 2.5);
  EXPECT_LT(below_ring / below_rigid, 0.6 * whole);
  ASSERT_TRUE(c.a_scatter_below);
  EXPECT_NEAR(*c.a_scatter_below, turn_scatter(low_passed_turns(model, kN, cut / kCrankHz), kN) / below_ring, 1e-12);
}

// A lower-Q resonance (ζ = 0.05, Q = 10: a mounted accelerometer's) spreads
// over ~4 bands of 20 Hz at 800 Hz and its own skirts raise the neighbours a
// window of two bands is compared with; the wider windows find it.
TEST(ModelFamily, LowerQResonanceIsNamedAtItsFrequency) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto measured = turns(25, 200, 5, 1.0, seed, 800, 0.05), model = turns(20, 320, 0, 0, seed + 100);
    const ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, {});
    ASSERT_TRUE(c.checked) << c.not_checked;
    ASSERT_FALSE(c.unmodelled.empty()) << "seed " << seed;
    const UnmodelledEnergy& u = c.unmodelled.front();
    EXPECT_NEAR(u.peak_hz, 800, 40) << "seed " << seed;
    EXPECT_LE(u.low_hz, 800);
    EXPECT_GE(u.high_hz, 800);
    EXPECT_EQ(u.kind, "narrow resonance") << "seed " << seed;
  }
}

// A mode the model has too, but at a sixth of the measured amplitude: the
// measured spectrum peaks there (prominence 9.5–11×) while the ratio over
// the trend is only 5–6× (the model's own weak line lifts its level there).
// Missed at the old kExcessRatio of 6 (seeds 2 and 4, 5.97× and 5.96×), as
// were a two-way ringing session of the independent generator (5.85×) and a
// Q = 5 mount at 450 Hz (5.59×) (docs/verdict.md "A lower ratio threshold").
// The same line at the measured amplitude in the model names nothing.
TEST(ModelFamily, AModeTheModelHasTooWeaklyIsNamed) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto measured = turns(25, 200, 5, 0.18, seed);
    const ModelFamilyCheck weak = check_model_family(measured, turns(20, 320, 0, 0.03, seed + 100), nominal(), kCrankHz, 1000, {});
    ASSERT_TRUE(weak.checked) << weak.not_checked;
    ASSERT_FALSE(weak.unmodelled.empty()) << "seed " << seed;
    EXPECT_NEAR(weak.unmodelled.front().peak_hz, 600, 20) << "seed " << seed;
    const ModelFamilyCheck same = check_model_family(measured, turns(20, 200, 0, 0.18, seed + 100), nominal(), kCrankHz, 1000, {});
    EXPECT_TRUE(same.unmodelled.empty()) << "seed " << seed << ": " << same.unmodelled.front().peak_hz;
  }
}

TEST(ModelFamily, HeavilyDampedRingingIsNeverCalledNarrow) {
  const auto measured = turns(25, 200, 5, 1.0, 9, 500, 0.3), model = turns(20, 200, 0, 0, 10);
  const ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, {});
  ASSERT_TRUE(c.checked);
  for (const UnmodelledEnergy& u : c.unmodelled) EXPECT_EQ(u.kind, "broad ringing") << u.peak_hz;
}

TEST(ModelFamily, TooFewTurnsOrBandsAreNotChecked) {
  const auto few = turns(3, 200, 5, 0, 1), model = turns(20, 200, 0, 0, 2);
  EXPECT_FALSE(check_model_family(few, model, nominal(), kCrankHz, 1000, {}).checked);
  const auto measured = turns(25, 200, 5, 0, 3);
  ModelFamilySettings narrow;
  narrow.max_frequency_hz = 100;  // 10 orders = 42 Hz on: fewer than 3 bands of 50 Hz
  const ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, narrow);
  EXPECT_FALSE(c.checked);
  EXPECT_FALSE(c.not_checked.empty());
}

TEST(ModelFamily, LowPassKeepsLowOrdersAndRemovesHighOnes) {
  std::vector<double> x(2 * kN);
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t i = 0; i < kN; ++i)
      x[r * kN + i] = std::sin(2 * kPi * 5 * static_cast<double>(i) / kN) + 0.5 * std::cos(2 * kPi * 50 * static_cast<double>(i) / kN);
  const std::vector<double> y = low_passed_turns(x, kN, 20);
  for (std::size_t i = 0; i < kN; ++i) EXPECT_NEAR(y[i], std::sin(2 * kPi * 5 * static_cast<double>(i) / kN), 1e-9);
}

TEST(ModelFamily, TurnScatterIsTheRmsOfThePerAngleStandardDeviation) {
  // Two turns differing by a constant 2: per-angle sample std √2 everywhere.
  std::vector<double> x(2 * kN, 1.0);
  for (std::size_t i = 0; i < kN; ++i) x[kN + i] = 3.0;
  EXPECT_NEAR(turn_scatter(x, kN), std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace fourbar
