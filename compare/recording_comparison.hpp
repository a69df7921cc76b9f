#pragma once
// Theory over measurement for one recording (thesis ch. 8, Figs 8.1–8.7):
// per link quantity, measured vs clearance model vs nominal on one grid.

#include <array>
#include <optional>
#include <vector>

#include "compare/magnification.hpp"
#include "compare/matched_theory.hpp"
#include "compare/measured_response.hpp"

namespace fourbar {

struct QuantityComparison {
  LinkQuantity quantity = LinkQuantity::alpha3;
  double measured_rms = 0, simulated_rms = 0, nominal_rms = 0;  ///< RMS of each averaged series
  double rms_difference_simulated = 0;  ///< RMS(measured − clearance model)
  double rms_difference_nominal = 0;    ///< RMS(measured − nominal)
  double correlation_simulated = 0, correlation_nominal = 0;
  double peak_ratio_simulated = 0;      ///< max|measured| / max|clearance model|
  double peak_ratio_nominal = 0;        ///< max|measured| / max|nominal|
  /// Where the impact bursts fall: crank angles (turned from the grid start,
  /// degrees) of the three largest deviations from the nominal response, at
  /// least 15° apart, largest first.
  std::vector<double> measured_bursts_deg, simulated_bursts_deg;
  double largest_burst_offset_deg = 0;  ///< between the largest measured and simulated one
  Magnification magnification;
};

struct RecordingComparison {
  std::array<std::optional<QuantityComparison>, 4> quantities;  ///< by LinkQuantity; absent if not measured
};

/// Compares every measured quantity. Throws RunError when the grids differ.
RecordingComparison compare_response(const MeasuredResponse& measured, const MatchedTheory& theory);

}  // namespace fourbar
