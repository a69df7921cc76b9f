#pragma once
// Tables as CSV that open in pandas, Excel and LibreOffice without options:
// one header row of column names that carry their unit, then rows of numbers
// in the shortest form that reads back to the same double
// (common/number_text.hpp). Non-finite values are refused (RunError naming
// column and row), never written silently.
//
// What made the file (provenance) goes into JSON, not into the CSV: into the
// summary.json a command writes beside its tables, or, for a table no JSON
// describes, into NAME.csv.json beside NAME.csv (describe_in_sidecar). With
// --csv-comments the commands also put it as `#` lines above the header.

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/atomic_output.hpp"
#include "common/number_text.hpp"

namespace fourbar {

/// NAME.csv.json for NAME.csv: the provenance of a table no other JSON describes.
std::filesystem::path csv_sidecar_path(const std::filesystem::path& csv);

class CsvWriter {
 public:
  /// `comments` become `# ...` lines above the header; pass none unless the
  /// user asked for them (--csv-comments).
  CsvWriter(std::filesystem::path path, const std::vector<std::string>& comments,
            std::vector<std::string> columns);

  /// Appends one row; `values.size()` must equal the number of columns.
  void row(std::span<const double> values);
  /// Appends a row whose last cell is text (e.g. a mode name), quoted as text_row does.
  void row(std::span<const double> values, const std::string& last_text);
  /// Appends a row of cells as they are: numbers already formatted, empty
  /// cells for values that do not exist, text quoted (RFC 4180) where it
  /// holds a comma, quote or line break.
  void text_row(std::span<const std::string> cells);
  /// At commit, also writes csv_sidecar_path(path) = {"file", "columns",
  /// "rows", "provenance": `provenance`}.
  void describe_in_sidecar(nlohmann::json provenance);
  /// Writes the sidecar (if any), then renames the table into place.
  void commit();

  std::size_t rows() const { return rows_; }

 private:
  void check(std::span<const double> values, std::size_t expected);
  void append_text(const std::string& cell);
  AtomicOutput out_;
  std::vector<std::string> columns_;
  std::size_t rows_ = 0;
  std::string line_;
  std::optional<nlohmann::json> sidecar_;
};

}  // namespace fourbar
