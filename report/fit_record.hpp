#pragma once
// A `fourbar fit` result read back for the report (`fourbar report --fit
// FIT.json`, or SESSION_DIR/fit/fit.json when it is there): the fitted
// contact parameters per recording, so that the report simulates its theory
// a second time with them (the same path as the theory at session.toml's
// prior), and the section "Fitted bearing parameters" that compares
// measured, fitted model and prior model.
//
// fit.json is read strictly: a missing or ill-typed key is an InputError
// naming the file and the key. A fit of other recordings than the session's
// (names differ) or one older than a recording is not refused (the theory at
// the fitted values is still a valid model run), but said in a warning on
// stderr and in the section.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/matched_theory.hpp"

namespace fourbar {

struct FittedContact {
  double restitution = 0.5;
  ContactLaw contact = ContactLaw::smooth;
  double friction_coefficient = 0.0;
};

struct ReportFit {
  std::filesystem::path file;
  nlohmann::json fit;                                  ///< fit.json as written by `fourbar fit`
  std::optional<FittedContact> shared;                 ///< the session fit (one bearing)
  std::map<std::string, FittedContact> by_recording;   ///< `fit --per-recording`: by file name
  std::vector<std::string> warnings;

  /// The fitted contact for a recording (the shared one, else its own); none
  /// when the fit does not cover it.
  std::optional<FittedContact> for_recording(const std::string& name) const;
};

/// Reads `file` and checks it against the session's recordings (file names).
/// InputError naming the file and key when it is not a fit.json.
ReportFit load_report_fit(const std::filesystem::path& file, const std::vector<std::filesystem::path>& recordings);

/// `base` with restitution, contact law and μ replaced by the fitted ones.
TheorySettings with_fitted_contact(TheorySettings base, const FittedContact& fitted);

/// One analysed recording's row of the fit section: measured vs the prior
/// model vs the fitted model (a, RMS difference, correlation on α3) with the
/// scatter each averaged deviation holds (README "Fitted bearing parameters
/// in the report"). Reads the record's series, so it is made by the worker
/// that made the record; none for a recording without a fitted theory.
std::optional<nlohmann::json> fit_report_row(const ReportFit& fit, const nlohmann::json& record);

/// The session record's "fit": the fit.json (file, SHA-256, parameters,
/// notes, χ²) and the rows of fit_report_row, in the folder's order.
nlohmann::json fit_report_record(const ReportFit& fit, const std::vector<nlohmann::json>& rows,
                                 const std::filesystem::path& session_dir);

}  // namespace fourbar
