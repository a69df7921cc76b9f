#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/units.hpp"
#include "compare/magnification.hpp"

namespace fourbar {
namespace {

constexpr std::size_t kPointsPerTurn = 360;

double angle(std::size_t k) { return units::kTwoPi * static_cast<double>(k) / kPointsPerTurn; }

TEST(OrderAmplitudes, ReadsCrankOrdersExactlyAndKeepsNonSynchronousContentOut) {
  const std::size_t rows = 8;
  std::vector<double> x(rows * kPointsPerTurn);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double th = units::kTwoPi * static_cast<double>(i) / kPointsPerTurn;  // continuous crank angle
    x[i] = 2.0 * std::sin(3 * th + 0.3) + 0.5 * std::cos(7 * th) + 1.0 * std::sin(5.5 * th);  // 5.5: not an order
  }
  std::vector<double> floor;
  const auto a = order_amplitudes(x, kPointsPerTurn, 10, &floor);
  EXPECT_NEAR(a[3], 2.0, 1e-12);
  EXPECT_NEAR(a[7], 0.5, 1e-12);
  // Half an order away from a line of amplitude 1, Hann over 8 turns leaks < 1e-3 into orders 5 and 6
  // (the rectangular window would leak 0.64).
  EXPECT_LT(a[5], 1e-3);
  EXPECT_LT(a[6], 1e-3);
  EXPECT_LT(a[1], 1e-6);
}

TEST(Magnification, TimeAndSpectralFactorsOfAScaledDeviation) {
  // Nominal response, a measured deviation d (orders 4 and 9), simulation = nominal + 30·d (thesis: a ≈ 30).
  std::vector<double> nominal(kPointsPerTurn), meas(kPointsPerTurn), sim(kPointsPerTurn);
  for (std::size_t k = 0; k < kPointsPerTurn; ++k) {
    nominal[k] = 100 * std::sin(angle(k)) + 40 * std::cos(2 * angle(k));
    const double d = 3 * std::sin(4 * angle(k) + 1) + std::cos(9 * angle(k));
    meas[k] = nominal[k] + d;
    sim[k] = nominal[k] + 30 * d;
  }
  // Per-turn grids: the averages plus seeded white noise that averages out.
  const std::size_t rows = 16;
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::vector<double> meas_rows(rows * kPointsPerTurn), sim_rows(rows * kPointsPerTurn);
  for (std::size_t i = 0; i < rows * kPointsPerTurn; ++i) meas_rows[i] = meas[i % kPointsPerTurn] + noise(rng), sim_rows[i] = sim[i % kPointsPerTurn];
  const Magnification m = magnification_factor({nominal, meas, sim, meas_rows, sim_rows}, 20);
  ASSERT_TRUE(m.time_domain);
  EXPECT_NEAR(*m.time_domain, 30.0, 1e-12);
  for (std::size_t k = 0; k < kPointsPerTurn; ++k) EXPECT_NEAR(m.modified[k], meas[k], 1e-12);  // nominal + d_sim/a = measured
  ASSERT_EQ(m.orders.size(), 20u);
  for (const OrderRatio& o : m.orders) {
    if (o.order == 4 || o.order == 9) {
      EXPECT_TRUE(o.significant) << o.order;
      ASSERT_TRUE(o.factor);
      // The noise adds to the measured line: 0.2/√(16·360/2)·(Hann) ≈ 4e-3 relative at most.
      EXPECT_NEAR(*o.factor, 30.0, 30.0 * 0.02) << o.order;
    } else {
      EXPECT_FALSE(o.significant) << o.order << " " << o.measured_amplitude << " floor " << o.measured_floor;
    }
  }
  ASSERT_TRUE(m.spectral);
  EXPECT_NEAR(*m.spectral, 30.0, 30.0 * 0.02);
}

TEST(Magnification, AbsentWhenTheMeasurementEqualsTheNominal) {
  std::vector<double> nominal(kPointsPerTurn), sim(kPointsPerTurn);
  for (std::size_t k = 0; k < kPointsPerTurn; ++k) nominal[k] = std::sin(angle(k)), sim[k] = nominal[k] + 0.1 * std::sin(5 * angle(k));
  const Magnification m = magnification_factor({nominal, nominal, sim, {}, {}}, 10);
  EXPECT_FALSE(m.time_domain);
  EXPECT_TRUE(m.modified.empty());
  EXPECT_FALSE(m.spectral);
  EXPECT_NEAR(m.simulated_deviation_rms, 0.1 / std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

TEST(MainsOrders, HumHarmonicsNearAnOrderLine) {
  // 250 rpm: 50 Hz is exactly order 12, 100 Hz order 24; 60 Hz is order 14.4.
  const double crank_hz = 250.0 / 60.0;
  const MainsOrders hum(crank_hz, {50.0}, 0.0, 16);  // 16 turns: a bin is 1/16 order, ±2 bins = ±0.125
  EXPECT_TRUE(hum.at_mains(12));
  EXPECT_TRUE(hum.at_mains(24));
  EXPECT_FALSE(hum.at_mains(11));
  EXPECT_FALSE(hum.at_mains(13));
  // 350 rpm: 50 Hz is order 8.57, 0.43 from order 9: clear with 16 turns, not with 2 (±1 order).
  EXPECT_FALSE(MainsOrders(350.0 / 60.0, {50.0}, 0.0, 16).at_mains(9));
  EXPECT_TRUE(MainsOrders(350.0 / 60.0, {50.0}, 0.0, 2).at_mains(9));
  // A 3 % speed spread sweeps order 8.57 over ±0.51 orders (2 std): order 9 is reached.
  EXPECT_TRUE(MainsOrders(350.0 / 60.0, {50.0}, 0.03, 16).at_mains(9));
  // No mains frequency, or no crank speed: nothing is a mains order.
  EXPECT_FALSE(MainsOrders(crank_hz, {}, 0.0, 16).at_mains(12));
  EXPECT_FALSE(MainsOrders(0.0, {50.0}, 0.0, 16).at_mains(12));
}

TEST(Magnification, NominalBandIsTheOrdersHoldingTheNominalResponse) {
  std::vector<double> nominal(kPointsPerTurn);
  for (std::size_t k = 0; k < kPointsPerTurn; ++k) nominal[k] = 100 * std::sin(angle(k)) + 30 * std::cos(2 * angle(k)) + 0.5 * std::sin(3 * angle(k));
  // Order 3 holds 0.25/(10000 + 900 + 0.25) = 2.3e-5 of the energy: below 1e-4, so K = 2.
  EXPECT_EQ(nominal_band_orders(nominal), 2);
  for (std::size_t k = 0; k < kPointsPerTurn; ++k) nominal[k] += 5 * std::sin(3 * angle(k));
  EXPECT_EQ(nominal_band_orders(nominal), 3);
}

// A synthetic spectrum where hum and the nominal band would bias a_spec: the
// model is exactly 2× the measured clearance deviation at orders 6 and 9;
// the measurement also holds 50 Hz hum on order 12 (250 rpm) and a once-per-turn
// deviation (the crank speed's) that no clearance model has.
TEST(Magnification, SpectralFactorLeavesOutMainsAndNominalBandOrders) {
  const std::size_t rows = 16;
  std::vector<double> nominal(kPointsPerTurn), meas(kPointsPerTurn), sim(kPointsPerTurn);
  std::vector<double> meas_rows(rows * kPointsPerTurn), sim_rows(rows * kPointsPerTurn);
  for (std::size_t k = 0; k < kPointsPerTurn; ++k) {
    const double th = angle(k);
    nominal[k] = 100 * std::sin(th) + 40 * std::cos(2 * th);
    const double clearance = 1.0 * std::sin(6 * th + 0.4) + 0.5 * std::cos(9 * th);
    meas[k] = nominal[k] + clearance + 2.0 * std::sin(12 * th) + 1.5 * std::sin(th + 1.0);
    sim[k] = nominal[k] + 2.0 * clearance;
  }
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (std::size_t i = 0; i < rows * kPointsPerTurn; ++i) meas_rows[i] = meas[i % kPointsPerTurn] + noise(rng), sim_rows[i] = sim[i % kPointsPerTurn];

  const MagnificationInput in{nominal, meas, sim, meas_rows, sim_rows};
  const Magnification plain = magnification_factor(in, 20);  // no mains given: the hum counts
  ASSERT_TRUE(plain.spectral);
  EXPECT_EQ(plain.nominal_band_orders, 2);
  EXPECT_EQ(plain.orders_used, (std::vector<int>{6, 9, 12}));
  // √((4·1.25) / (1.25 + 4)) = 0.98: the hum pulls a_spec from 2 to below 1.
  EXPECT_LT(*plain.spectral, 1.0);

  const Magnification m = magnification_factor(in, 20, MainsHum{250.0 / 60.0, {50.0}, 0.004});
  ASSERT_TRUE(m.spectral);
  EXPECT_EQ(m.orders_used, (std::vector<int>{6, 9}));
  EXPECT_NEAR(*m.spectral, 2.0, 2.0 * 0.01);
  EXPECT_TRUE(m.orders[11].mains);   // order 12
  EXPECT_TRUE(m.orders[11].significant);
  EXPECT_FALSE(m.orders[5].mains);  // order 6
  // The order-1 deviation is significant but in the nominal band: left out.
  EXPECT_TRUE(m.orders[0].significant);
  // The synchronous effect over the floor, above the band and clear of mains: ≫ 3; the model's twice it.
  ASSERT_TRUE(m.effect_to_floor && m.model_effect_to_floor);
  EXPECT_GT(*m.effect_to_floor, 30.0);
  EXPECT_GT(*m.model_effect_to_floor, *m.effect_to_floor);
  EXPECT_GT(m.floor_rms, 0.0);
}

TEST(Magnification, NoiseAloneStandsAboutOnceTheFloor) {
  // Deviation = white noise only: the order lines are noise like the bins between them.
  const std::size_t rows = 32;
  std::vector<double> nominal(kPointsPerTurn), meas_rows(rows * kPointsPerTurn);
  for (std::size_t k = 0; k < kPointsPerTurn; ++k) nominal[k] = 100 * std::sin(angle(k));
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t i = 0; i < rows * kPointsPerTurn; ++i) meas_rows[i] = nominal[i % kPointsPerTurn] + noise(rng);
  std::vector<double> mean(kPointsPerTurn, 0.0);
  for (std::size_t i = 0; i < rows * kPointsPerTurn; ++i) mean[i % kPointsPerTurn] += meas_rows[i] / rows;
  const Magnification m = magnification_factor({nominal, mean, nominal, meas_rows, {}}, 50);
  ASSERT_TRUE(m.effect_to_floor);
  // Rayleigh amplitudes: RMS over median = √2/√(2 ln 2) = 1.20; 49 orders scatter it by ~10 %.
  EXPECT_GT(*m.effect_to_floor, 0.9);
  EXPECT_LT(*m.effect_to_floor, 1.6);
}

}  // namespace
}  // namespace fourbar
