#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/units.hpp"
#include "compare/magnification.hpp"

namespace fourbar {
namespace {

constexpr std::size_t kN = 360;

double angle(std::size_t k) { return units::kTwoPi * static_cast<double>(k) / kN; }

TEST(OrderAmplitudes, ReadsCrankOrdersExactlyAndKeepsNonSynchronousContentOut) {
  const std::size_t rows = 8;
  std::vector<double> x(rows * kN);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double th = units::kTwoPi * static_cast<double>(i) / kN;  // continuous crank angle
    x[i] = 2.0 * std::sin(3 * th + 0.3) + 0.5 * std::cos(7 * th) + 1.0 * std::sin(5.5 * th);  // 5.5: not an order
  }
  std::vector<double> floor;
  const auto a = order_amplitudes(x, kN, 10, &floor);
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
  std::vector<double> nominal(kN), meas(kN), sim(kN);
  for (std::size_t k = 0; k < kN; ++k) {
    nominal[k] = 100 * std::sin(angle(k)) + 40 * std::cos(2 * angle(k));
    const double d = 3 * std::sin(4 * angle(k) + 1) + std::cos(9 * angle(k));
    meas[k] = nominal[k] + d;
    sim[k] = nominal[k] + 30 * d;
  }
  // Per-turn grids: the averages plus seeded white noise that averages out.
  const std::size_t rows = 16;
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::vector<double> meas_rows(rows * kN), sim_rows(rows * kN);
  for (std::size_t i = 0; i < rows * kN; ++i) meas_rows[i] = meas[i % kN] + noise(rng), sim_rows[i] = sim[i % kN];
  const Magnification m = magnification_factor({nominal, meas, sim, meas_rows, sim_rows}, 20);
  ASSERT_TRUE(m.time_domain);
  EXPECT_NEAR(*m.time_domain, 30.0, 1e-12);
  for (std::size_t k = 0; k < kN; ++k) EXPECT_NEAR(m.modified[k], meas[k], 1e-12);  // nominal + d_sim/a = measured
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
  std::vector<double> nominal(kN), sim(kN);
  for (std::size_t k = 0; k < kN; ++k) nominal[k] = std::sin(angle(k)), sim[k] = nominal[k] + 0.1 * std::sin(5 * angle(k));
  const Magnification m = magnification_factor({nominal, nominal, sim, {}, {}}, 10);
  EXPECT_FALSE(m.time_domain);
  EXPECT_TRUE(m.modified.empty());
  EXPECT_FALSE(m.spectral);
  EXPECT_NEAR(m.simulated_deviation_rms, 0.1 / std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace fourbar
