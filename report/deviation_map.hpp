#pragma once
// The revolution × crank-angle map of the measured coupler angular
// acceleration's deviation from the nominal response (α3 − α3 nominal; α4
// when the recording has no coupler channel): where impacts repeat turn
// after turn and where they wander.
//
// Kept small for the report, by a stated rule:
//   rows     every k-th revolution by acquire's revolution number, averaged
//            ones only, k = ⌈revolutions / kMapMaxRows⌉;
//   columns  C = the largest divisor of N not above kMapMaxColumns; each the
//            mean of N/C consecutive grid angles (so a row's mean is the
//            revolution's mean over the whole grid);
//   values   int8 counts, count = round(127 · deviation / largest |deviation|)
//            (rad_s2_per_count = largest |deviation| / 127), base64.

#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "analyze/pipeline.hpp"

namespace fourbar {

inline constexpr std::size_t kMapMaxRows = 200;
inline constexpr std::size_t kMapMaxColumns = 180;

/// Collects each kept revolution's column means while the analysis runs.
class DeviationMapCollector : public RevolutionObserver {
 public:
  void on_start(const RecordingAnalysis& analysis) override;
  void on_revolution(const AnalyzedRevolution& revolution) override;

  /// The map against the nominal response on the analysis grid (N values),
  /// with `quantity` ("alpha3_rad_s2" or "alpha4_rad_s2") and the grid's
  /// first angle and direction; null when no revolution was kept.
  nlohmann::json map_json(const std::vector<double>& nominal, double first_deg, double direction) const;

  bool coupler() const { return coupler_; }

 private:
  bool coupler_ = true;
  std::size_t points_ = 0, columns_ = 0, every_ = 1;
  std::vector<std::size_t> numbers_;
  std::vector<double> rows_;  ///< numbers_.size() × columns_, column means of α
};

/// The counts back from base64 (for tests and tools).
std::vector<int> decode_map_counts(const std::string& base64);

}  // namespace fourbar
