#pragma once
// summary.csv beside the report: one row per recording of the session, the
// per-recording figures of summary.json flat, for a spreadsheet. Its columns
// are one table (summary_columns()): a name, a unit and how to get the cell
// from the recording's record; a column more is a row more there. The
// verdict comes first after the status: its overall level, the a it judges
// by (value, standard error, kind) and one column per verdict part
// (report/verdict.hpp verdict_parts()); the other a are diagnostics after it.

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fourbar {

struct SummaryColumn {
  std::string name;  ///< without the unit: "speed"
  std::string unit;  ///< appended as "_rpm"; empty for text, counts and ratios
  /// The cell from one recording's record (summary.json "recordings"):
  /// empty when the value does not exist (a failed recording, no rocker channel).
  std::function<std::string(const nlohmann::json& recording)> cell;

  std::string header() const { return unit.empty() ? name : name + "_" + unit; }
};

/// Every column of summary.csv, in order.
std::span<const SummaryColumn> summary_columns();

/// Writes out_dir/summary.csv from the session record (session_report.hpp);
/// `comments` become `#` lines above the header (--csv-comments).
void write_summary_table(const nlohmann::json& session, const std::filesystem::path& out_dir,
                         const std::vector<std::string>& comments);

}  // namespace fourbar
