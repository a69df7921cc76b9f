// Pulse levels, the Schmitt trigger with sub-sample edge times, and the
// period-sequence cleaning of the pulse train (missing, echo, doubled pulses).

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "acquire/edge_detector.hpp"
#include "acquire/level_histogram.hpp"
#include "acquire/pulse_train.hpp"

namespace fourbar {
namespace {

/// A trapezoidal pulse train: edges are linear ramps of `rise` samples
/// centred on the given times (in samples), levels 0 and 5.
std::vector<double> pulse_signal(const std::vector<double>& leads, double width, double rise, std::size_t n) {
  std::vector<double> x(n, 0.0);
  auto ramp = [&](double dt) { return std::clamp(dt / rise + 0.5, 0.0, 1.0); };
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0;
    for (double t : leads) s += ramp(static_cast<double>(i) - t) - ramp(static_cast<double>(i) - t - width);
    x[i] = 5.0 * std::clamp(s, 0.0, 1.0);
  }
  return x;
}

TEST(LevelHistogram, FindsTwoLevelsThroughGrowth) {
  LevelHistogram h(1024);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0, 0.02);
  for (int i = 0; i < 20000; ++i) h.add((i % 50 < 3 ? 5.0 : 0.2) + noise(rng));
  const auto t = automatic_thresholds(h);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->bottom_level, 0.2, 0.01);
  EXPECT_NEAR(t->top_level, 5.0, 0.02);
  EXPECT_NEAR(t->noise, 0.02, 0.01);
  EXPECT_GT(t->low, 0.2 + 0.1 * 4.8);
  EXPECT_LT(t->high, 5.0 - 0.1 * 4.8);
  LevelHistogram flat;
  for (int i = 0; i < 100; ++i) flat.add(1.5);
  EXPECT_FALSE(automatic_thresholds(flat));
  LevelHistogram gauss;  // one level plus noise: no pulses
  for (int i = 0; i < 20000; ++i) gauss.add(noise(rng));
  EXPECT_FALSE(automatic_thresholds(gauss));
}

TEST(EdgeDetector, SubSampleTimesOnLinearRamps) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> frac(0, 1);
  std::vector<double> leads;
  for (int k = 0; k < 40; ++k) leads.push_back(100 + 731.3 * k + frac(rng));
  const auto x = pulse_signal(leads, 40, 4.0, 30000);
  PulseThresholds th{0, 5, 1.75, 3.25, 0, true};
  const double fs = 1000;
  EdgeDetector d(th, PulsePolarity::rising, fs, 2.0, 0);
  for (std::size_t i = 0; i < x.size(); i += 777) d.push(x.data() + i, std::min<std::size_t>(777, x.size() - i), 1);
  ASSERT_EQ(d.edges().size(), leads.size());
  for (std::size_t k = 0; k < leads.size(); ++k) EXPECT_NEAR(d.edges()[k], 2.0 + leads[k] / fs, 1e-9);
  // The falling (trailing) edges instead.
  EdgeDetector f(th, PulsePolarity::falling, fs, 0, 0);
  f.push(x.data(), x.size(), 1);
  ASSERT_EQ(f.edges().size(), leads.size());
  for (std::size_t k = 0; k < leads.size(); ++k) EXPECT_NEAR(f.edges()[k], (leads[k] + 40) / fs, 1e-9);
}

// The histogram's levels are only as good as its bins; the detector refines
// them from the samples, so edge times do not inherit the bin error.
TEST(EdgeDetector, RefinesTheLevelsBeforeTimingEdges) {
  const std::vector<double> leads{300.37, 1300.81, 2300.05};
  const auto x = pulse_signal(leads, 50, 5.0, 3000);
  PulseThresholds rough{0.02, 4.96, 1.7, 3.3, 0.0, true};  // bottom and top off by 20 and 40 mV
  EdgeDetector d(rough, PulsePolarity::rising, 1, 0, 0);
  d.push(x.data(), x.size(), 1);
  EXPECT_NEAR(d.mid_level(), 2.5, 1e-12);
  ASSERT_EQ(d.edges().size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(d.edges()[k], leads[k], 1e-9);
}

TEST(EdgeDetector, HysteresisIgnoresNoiseAndEchoesBelowTheBand) {
  std::vector<double> leads{500.2, 1500.7, 2500.1};
  auto x = pulse_signal(leads, 30, 1.0, 3200);
  std::mt19937_64 rng(9);
  std::normal_distribution<double> noise(0, 0.3);
  for (auto& v : x) v += noise(rng);  // σ = 0.3 V on a 5 V swing: many mid-level crossings
  PulseThresholds th{0, 5, 1.0, 4.0, 0.3, true};
  EdgeDetector d(th, PulsePolarity::rising, 1, 0, 0);
  d.push(x.data(), x.size(), 1);
  ASSERT_EQ(d.edges().size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(d.edges()[k], leads[k], 0.6);
}

TEST(EdgeDetector, DebounceDropsEdgesTooSoonAfterThePrevious) {
  const auto x = pulse_signal({100.0, 130.0, 1100.0}, 10, 2.0, 1500);
  PulseThresholds th{0, 5, 1.75, 3.25, 0, true};
  EdgeDetector d(th, PulsePolarity::rising, 1000, 0, 0.050);
  d.push(x.data(), x.size(), 1);
  EXPECT_EQ(d.edges().size(), 2u);
  EXPECT_EQ(d.debounced(), 1u);
}

/// Pulse times with a slowly varying speed (periods within ±1.5 %).
std::vector<double> regular(int n, double period, double start = 0.3) {
  std::vector<double> t;
  for (int k = 0; k < n; ++k) t.push_back(start + period * (k + 0.05 * std::sin(0.3 * k)));
  return t;
}

TEST(PulseTrain, CleanTrainIsOneSegment) {
  const auto t = regular(50, 0.17);
  const PulseTrain p = clean_pulse_train(t);
  ASSERT_EQ(p.segments.size(), 1u);
  EXPECT_EQ(p.segments[0].size(), 50u);
  EXPECT_EQ(p.revolutions(), 49u);
  EXPECT_TRUE(p.removed_s.empty());
  EXPECT_TRUE(p.inserted_s.empty());
  EXPECT_NEAR(p.typical_period_s, 0.17, 0.003);
}

TEST(PulseTrain, MissingPulsesAreInsertedWhereTheyBelong) {
  const auto truth = regular(60, 0.17);
  std::vector<double> t = truth;
  t.erase(t.begin() + 40, t.begin() + 42);  // two in a row
  t.erase(t.begin() + 10);                  // one alone
  const PulseTrain p = clean_pulse_train(t);
  ASSERT_EQ(p.segments.size(), 1u);
  ASSERT_EQ(p.segments[0].size(), 60u);
  ASSERT_EQ(p.inserted_s.size(), 3u);
  for (std::size_t k = 0; k < 60; ++k) {
    EXPECT_NEAR(p.segments[0][k].time_s, truth[k], 1e-4) << k;
    EXPECT_EQ(p.segments[0][k].inserted, k == 10 || k == 40 || k == 41) << k;
  }
}

TEST(PulseTrain, EchoesAndDoubledMarksAreRemoved) {
  const auto truth = regular(40, 0.2);
  std::vector<double> t = truth;
  t.push_back(truth[5] + 0.004);   // voltage echo
  t.push_back(truth[20] + 0.09);   // spurious edge near half a period
  t.push_back(truth[30] - 0.003);  // noise just before a pulse
  std::sort(t.begin(), t.end());
  const PulseTrain p = clean_pulse_train(t);
  ASSERT_EQ(p.segments.size(), 1u);
  ASSERT_EQ(p.segments[0].size(), 40u);
  EXPECT_EQ(p.removed_s.size(), 3u);
  for (std::size_t k = 0; k < 40; ++k) EXPECT_DOUBLE_EQ(p.segments[0][k].time_s, truth[k]);

  // Doubled sync mark on every revolution: keep the first of each pair.
  std::vector<double> doubled;
  for (double x : truth) doubled.push_back(x), doubled.push_back(x + 0.02);
  const PulseTrain d = clean_pulse_train(doubled);
  ASSERT_EQ(d.segments.size(), 1u);
  ASSERT_EQ(d.segments[0].size(), 40u);
  EXPECT_EQ(d.removed_s.size(), 40u);
  for (std::size_t k = 0; k < 40; ++k) EXPECT_DOUBLE_EQ(d.segments[0][k].time_s, truth[k]);
}

TEST(PulseTrain, UnexplainedIntervalCutsTheTrain) {
  std::vector<double> t = regular(20, 0.2);
  const std::vector<double> after = regular(20, 0.2, t.back() + 0.2 * 1.5);  // 1.5 periods: no whole number
  t.insert(t.end(), after.begin(), after.end());
  const PulseTrain p = clean_pulse_train(t);
  ASSERT_EQ(p.segments.size(), 2u);
  EXPECT_EQ(p.segments[0].size(), 20u);
  EXPECT_EQ(p.segments[1].size(), 20u);
  ASSERT_EQ(p.gaps.size(), 1u);
  EXPECT_NEAR(p.gaps[0].periods, 1.5, 0.05);
  EXPECT_EQ(p.revolutions(), 38u);
}

// A run-up: the period shrinks by 8 % per revolution (100 → 350 rpm in 16
// turns), with a pulse missing on the way; the tracker follows.
TEST(PulseTrain, FollowsARunUp) {
  std::vector<double> truth{0.1};
  double period = 0.6;
  while (period > 0.172) truth.push_back(truth.back() + period), period *= 0.92;
  for (int k = 0; k < 20; ++k) truth.push_back(truth.back() + 0.1714);
  std::vector<double> t = truth;
  t.erase(t.begin() + 25);
  const PulseTrain p = clean_pulse_train(t);
  ASSERT_EQ(p.segments.size(), 1u);
  EXPECT_EQ(p.segments[0].size(), truth.size());
  EXPECT_TRUE(p.removed_s.empty());
  ASSERT_EQ(p.inserted_s.size(), 1u);
  EXPECT_NEAR(p.inserted_s[0], truth[25], 1e-3);
}

TEST(PulseTrain, DominantPeriod) {
  EXPECT_NEAR(dominant_period(regular(30, 0.1)), 0.1, 0.002);
  EXPECT_EQ(dominant_period(std::vector<double>{1.0}), 0.0);
}

}  // namespace
}  // namespace fourbar
