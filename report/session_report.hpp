#pragma once
// The main job, `fourbar report SESSION_DIR`: every recording of a session
// folder through acquire + analyze, the matched theory and the comparison;
// one self-contained HTML report, summary.json and CSV series beside it.
//
// Cache: each recording's record is stored under a key that is the SHA-256
// of the tool version, the recording's, manifest's and rig's SHA-256 and
// every setting that applies to it; a second run with unchanged inputs reads
// the records back instead of recomputing. Failed recordings are not cached.

#include <cstddef>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

struct ReportOptions {
  std::filesystem::path session_dir;
  std::filesystem::path out_html;   ///< the report; summary.json, summary.csv, session_severity.csv and series/ go beside it
  std::filesystem::path cache_dir;  ///< empty: <out dir>/.fourbar-cache
  bool use_cache = true;
  bool progress = true;             ///< per-recording progress on stderr when it is a terminal
  /// Cores used (0: default_jobs()): min(jobs, recordings) recordings at
  /// once, each analysed on jobs / that many threads (AnalyzeOptions::threads).
  std::size_t jobs = 0;
  std::string command_line;         ///< for provenance
  bool csv_comments = false;        ///< provenance also as `#` lines above the CSV headers
  /// A `fourbar fit` result: the theory is simulated a second time at its
  /// fitted contact parameters and the report gets the section "Fitted
  /// bearing parameters". Empty: SESSION_DIR/fit/fit.json when it exists
  /// (where `fourbar fit` writes by default) unless `use_fit` is false.
  std::filesystem::path fit_json;
  bool use_fit = true;
};

struct ReportOutcome {
  int recordings = 0, failed = 0, from_cache = 0;
  std::filesystem::path fit;  ///< the fit.json shown (empty: none)
  int check_setup = 0;  ///< analysed, but the set-up check found a likely manifest mistake (status "check set-up")
  std::filesystem::path html, summary;
  std::string verdict_table;  ///< recordings, status, verdict words and a, aligned (report/verdict_table.hpp)
};

/// Cores used by default: every core.
std::size_t default_jobs();

/// Runs the whole session. Recordings are processed `jobs` at a time; the
/// outputs are the same for every `jobs` (records in the folder's order). InputError (exit 2) for a bad session folder,
/// session.toml or output path; a bad recording is reported in the outputs
/// and on stderr and counted in `failed`; a set-up check's findings are
/// warned on stderr, shown at the top of the report and counted in `check_setup`.
ReportOutcome run_session_report(const ReportOptions& options);

/// The session record without the bulky per-angle series and spectra (what
/// summary.json holds).
nlohmann::json summary_of(const nlohmann::json& session);

}  // namespace fourbar
