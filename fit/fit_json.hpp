#pragma once
// fit.json: the fitted contact parameters with their intervals, the
// objective per recording, and what the fit cost (docs/fit.md "Fitting the
// contact parameters" lists every field).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fit/session_fit.hpp"

namespace fourbar {

/// One fit (the session's, or one recording's with --per-recording).
nlohmann::json fit_to_json(const FitResult& fit, const std::vector<RecordingTarget>& targets,
                           const ContactParameters& prior, const FitOptions& options);

/// What to record instead when a parameter is not identifiable.
std::string not_identifiable_advice(const std::string& parameter);
/// The advice for `p`: empty when identifiable; for a parameter bounded from
/// below only (μ: the impacts stick), what that means and what to do instead.
std::string parameter_advice(const ParameterEstimate& p);

}  // namespace fourbar
