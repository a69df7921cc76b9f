#pragma once
// Series output as CSV: a few `#` provenance lines, one header row of
// column names that carry their unit, then rows of numbers printed in the
// shortest form that reads back to the same double. Non-finite values are
// refused (RunError naming column and row), never written silently.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "common/atomic_output.hpp"

namespace fourbar {

class CsvWriter {
 public:
  /// `comments` become `# ...` lines above the header (provenance).
  CsvWriter(std::filesystem::path path, const std::vector<std::string>& comments,
            std::vector<std::string> columns);

  /// Appends one row; `values.size()` must equal the number of columns.
  void row(std::span<const double> values);
  /// Appends a row whose last cell is text (e.g. a mode name).
  void row(std::span<const double> values, const std::string& last_text);
  /// Appends a row of cells as they are: numbers already formatted, empty
  /// cells for values that do not exist, text quoted (RFC 4180) where it
  /// holds a comma, quote or line break.
  void text_row(std::span<const std::string> cells);
  void commit() { out_.commit(); }

 private:
  void check(std::span<const double> values, std::size_t expected);
  AtomicOutput out_;
  std::vector<std::string> columns_;
  std::size_t rows_ = 0;
  std::string line_;
};

/// Shortest round-trip decimal form of `v`.
std::string format_double(double v);

}  // namespace fourbar
