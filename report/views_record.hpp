#pragma once
// The views a technician checks a recording with, as the record's `views`
// object (summary.json, the analysis cache, the HTML page):
//   channels  the channel / calibration sheet: every channel of the manifest
//             with its role, sensitivity, mount, the input range and what the
//             recording used of it, clipping, and the set-up check's verdict;
//   excerpt   a few revolutions of raw signal from the middle of the
//             recording (acquire/signal_excerpt.hpp) with the detected pulses
//             and the Schmitt thresholds used;
//   speed     crank speed per revolution over the whole recording (groups
//             of k consecutive revolutions, mean/min/max, when there are more
//             than kSpeedMaxPoints);
//   map       the revolution × crank-angle map of α3 − nominal
//             (deviation_map.hpp).

#include <nlohmann/json.hpp>

#include "analyze/pipeline.hpp"
#include "report/deviation_map.hpp"

namespace fourbar {

/// Revolutions of raw signal the report keeps.
inline constexpr std::size_t kExcerptRevolutions = 3;
/// Points of the crank-speed view at most.
inline constexpr std::size_t kSpeedMaxPoints = 2000;

/// The channel sheet; `setup_check` is the record's set-up check JSON (may be null).
nlohmann::json channel_sheet_json(const Manifest& manifest, const AcquisitionReport& acquisition,
                                  const nlohmann::json& setup_check);

/// The raw-signal excerpt with pulses and thresholds.
nlohmann::json excerpt_json(const AcquisitionReport& acquisition);

/// Crank speed per revolution (or per group of revolutions) over time.
nlohmann::json speed_json(const AcquisitionReport& acquisition);

/// All four views of an analysed recording whose record (with `series`,
/// `grid` and `setup_check`) is `record`.
nlohmann::json views_record(const RecordingAnalysis& analysis, const DeviationMapCollector& map,
                            const nlohmann::json& record);

}  // namespace fourbar
