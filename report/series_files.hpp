#pragma once
// The CSV series beside the report (crank angle in degrees first, units in
// every column name):
//   series/<recording stem>.csv         crank_deg, per quantity q (alpha3_rad_s2, …):
//                                       q_measured, q_measured_std, q_clearance,
//                                       q_clearance_std, q_nominal, q_modified (units kept last)
//   series/<stem>_orders.csv            order, per measured q: deviation amplitudes from the
//                                       nominal (measured, simulated), floor, significant, factor
//   series/<stem>_impacts.csv           simulated impacts in the averaged turns
//   session_severity.csv                one row per analysed recording
//   summary.csv                         one row per recording (summary_table.hpp)
// Written from the session record (session_report.hpp); their provenance is
// in summary.json beside them (with csv_comments also as `#` lines). A value
// that does not exist (null in summary.json) is an empty cell.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

/// The `# made by` line of the CSV files (with csv_comments).
std::string series_made_by(const std::string& version, const std::string& command);

/// One recording's series/<stem>*.csv from its record (nothing for a failed
/// recording) into out_dir/series/, which must exist: written as soon as the
/// recording is done, on its worker.
void write_recording_series(const nlohmann::json& recording, const std::filesystem::path& out_dir,
                            const std::string& made_by, bool csv_comments);

/// summary.csv and session_severity.csv from the whole session record.
void write_session_series(const nlohmann::json& session, const std::filesystem::path& out_dir, bool csv_comments);

}  // namespace fourbar
