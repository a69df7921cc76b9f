#pragma once
// The part of a recording's record that comes from the comparison alone
// (operating point, theory, grid, series, metrics, impacts), in the JSON
// schema the report, summary.json and the CSV series are written from.
// recording_job.hpp adds what the analysis knows (acquisition, filter,
// spectra, warnings).

#include <nlohmann/json.hpp>

#include "compare/matched_theory.hpp"
#include "compare/measured_response.hpp"
#include "compare/recording_comparison.hpp"

namespace fourbar {

/// status "ok", operating_point, theory, grid (crank_deg: θ2 from the ground
/// line), series (per quantity: nominal, clearance, clearance_std and, when
/// measured, measured, measured_std, modified), metrics, impacts; empty
/// acquisition, analysis, spectra and warnings.
nlohmann::json comparison_record(const MeasuredResponse& measured, const MatchedTheory& theory,
                                 const RecordingComparison& comparison);

nlohmann::json theory_settings_json(const TheorySettings& t);

/// Session severity tables (compare/session_severity.hpp) from the records
/// (each with name, status, operating_point, metrics, theory): by_speed and by_clearance.
nlohmann::json severity_record(const nlohmann::json& records);

}  // namespace fourbar
