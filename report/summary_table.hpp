#pragma once
// summary.csv beside the report: one row per recording of the session, the
// per-recording figures of summary.json flat, for a spreadsheet. Its columns
// are one table (summary_columns()): a name, a unit and how to get the cell
// from the recording's record; a column more is a row more there.

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace fourbar {

struct SummaryColumn {
  std::string_view name;  ///< without the unit: "speed"
  std::string_view unit;  ///< appended as "_rpm"; empty for text, counts and ratios
  /// The cell from one recording's record (summary.json "recordings"):
  /// empty when the value does not exist (a failed recording, no rocker channel).
  std::string (*cell)(const nlohmann::json& recording);

  std::string header() const { return unit.empty() ? std::string(name) : std::string(name) + "_" + std::string(unit); }
};

/// Every column of summary.csv, in order.
std::span<const SummaryColumn> summary_columns();

/// Writes out_dir/summary.csv from the session record (session_report.hpp);
/// `comments` become `#` lines above the header (--csv-comments).
void write_summary_table(const nlohmann::json& session, const std::filesystem::path& out_dir,
                         const std::vector<std::string>& comments);

}  // namespace fourbar
