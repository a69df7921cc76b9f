#pragma once
// What the comparison needs from a measurement: the operating point and each
// measured link quantity on the crank-angle grid, averaged over the analysed
// revolutions (mean and spread per angle), optionally with every revolution.
// Built from analyze's RecordingAnalysis (report/) or directly in tests.

#include <array>
#include <optional>
#include <vector>

#include "compare/link_quantity.hpp"

namespace fourbar {

struct AngleSeries {
  std::vector<double> mean;         ///< per grid angle
  std::vector<double> std;          ///< spread per grid angle (sample std over revolutions)
  std::vector<double> revolutions;  ///< revolutions × N, row-major; may be empty
  std::size_t revolution_count = 0;
};

struct MeasuredResponse {
  CrankGrid grid;
  double crank_speed_rad_s = 0;  ///< mean over the analysed revolutions (sign: direction)
  double speed_rel_std = 0;      ///< crank speed's standard deviation over its mean (acquisition)
  /// Mains frequencies whose hum orders the spectral magnification leaves
  /// out (compare/mains_order.hpp); empty: none.
  std::vector<double> mains_hz;
  /// Per LinkQuantity (index_of); empty when the recording has no such channel.
  std::array<std::optional<AngleSeries>, 4> series;
};

}  // namespace fourbar
