#pragma once
// One recording of a session through the whole chain: acquire + analyze
// (analyze_recording), the matched theory at its operating point, the
// comparison, and the record the report is drawn from (JSON: what the cache
// keeps, what summary.json, the CSV series and the HTML are written from).
// A recording that fails gives a record with status "failed" and the error;
// it never stops the session.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "analyze/pipeline.hpp"
#include "compare/matched_theory.hpp"
#include "compare/measured_response.hpp"
#include "compare/model_family.hpp"
#include "compare/recording_comparison.hpp"

namespace fourbar {

/// The measured response on the analysis grid (α, ω per link, every turn).
MeasuredResponse measured_response(const RecordingAnalysis& analysis);

/// The record of a recording that went through (status "ok").
/// One pulse per turn: {quantities, speed_change_pct, once_per_turn_pct:
/// {alpha, omega}, twice_per_turn_pct} — what an unseen in-turn speed change
/// of speed_change_pct would put into the averaged α and ω, worst over its
/// phase (analyze/unseen_speed_change.hpp); null for wheels and encoders.
nlohmann::json unseen_speed_json(const RecordingAnalysis& analysis);

nlohmann::json recording_record(const RecordingAnalysis& analysis, const MeasuredResponse& measured,
                                const MatchedTheory& theory, const RecordingComparison& comparison);

/// Runs the chain for one recording; the record (status "ok" or "failed"
/// with `error` and `error_kind` "input" | "run"). Never throws for a bad
/// recording. With `fitted` (a `fourbar fit` result), the theory is simulated
/// a second time at those settings and compared the same way: "fitted_theory"
/// holds its settings, metrics, severity and model series (mean and spread).
/// "model_family" holds the model-family check (compare/model_family.hpp)
/// of α3 (α4 without a coupler channel) under `family`.
nlohmann::json process_recording(const std::filesystem::path& recording, const AnalyzeOptions& analysis,
                                 const TheorySettings& theory, const TheorySettings* fitted = nullptr,
                                 const ModelFamilySettings& family = {});

}  // namespace fourbar
