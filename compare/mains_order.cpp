#include "compare/mains_order.hpp"

#include <algorithm>
#include <cmath>

namespace fourbar {

MainsOrders::MainsOrders(double crank_hz, std::vector<double> mains_hz, double speed_rel_std, std::size_t revolutions)
    : crank_hz_(std::abs(crank_hz)),
      mains_hz_(std::move(mains_hz)),
      speed_rel_std_(std::abs(speed_rel_std)),
      bin_orders_(1.0 / static_cast<double>(std::max<std::size_t>(revolutions, 1))) {}

bool MainsOrders::at_mains(int order) const {
  if (!(crank_hz_ > 0)) return false;
  const double k = order;
  for (double f : mains_hz_) {
    if (!(f > 0)) continue;
    for (int h = 1;; ++h) {
      const double centre = h * f / crank_hz_;  // the hum harmonic, in crank orders
      const double half = kMainsOrderBins * bin_orders_ + kMainsSpreadStd * speed_rel_std_ * centre;
      if (centre - half > k) break;
      if (std::abs(k - centre) <= half) return true;
    }
  }
  return false;
}

}  // namespace fourbar
