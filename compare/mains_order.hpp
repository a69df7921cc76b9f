#pragma once
// Which crank orders carry mains hum. Hum at h·f_mains (h = 1, 2, …) is not
// locked to the crank: in the crank-angle spectrum over R revolutions it sits
// at order h·f_mains/f_crank, spread by the crank-speed wander over
// ±kMainsSpreadStd standard deviations of the speed. An order k is a mains
// order when it lies within kMainsOrderBins bins (1/R order each: the Hann
// main lobe is ±2 bins) of that range: its measured amplitude then holds hum
// the clearance model cannot have. At 250 rpm 50 Hz is exactly order 12.

#include <cstddef>
#include <vector>

namespace fourbar {

/// Half width of the Hann window's main lobe, in bins of the order spectrum.
inline constexpr double kMainsOrderBins = 2.0;
/// The crank speed wanders over ± this many standard deviations.
inline constexpr double kMainsSpreadStd = 2.0;

/// The hum of a recording: |crank frequency| (Hz), the mains frequencies
/// (Hz; empty: none) and the crank speed's std over its mean.
struct MainsHum {
  double crank_hz = 0;
  std::vector<double> mains_hz;
  double speed_rel_std = 0;
};

class MainsOrders {
 public:
  /// `crank_hz` ≤ 0 or no mains frequency: no order is a mains order.
  MainsOrders(double crank_hz, std::vector<double> mains_hz, double speed_rel_std, std::size_t revolutions);
  MainsOrders(const MainsHum& hum, std::size_t revolutions)
      : MainsOrders(hum.crank_hz, hum.mains_hz, hum.speed_rel_std, revolutions) {}

  bool at_mains(int order) const;

 private:
  double crank_hz_;
  std::vector<double> mains_hz_;
  double speed_rel_std_;
  double bin_orders_;
};

}  // namespace fourbar
