#pragma once
// Reads a fourbar CSV output back, with or without `#` provenance lines
// (--csv-comments): `#` lines and blank lines skipped, the header row, then
// the rows. read_csv: numeric rows, an empty cell (a value that does not
// exist) as NaN; a cell that is not a number throws (std::stod), so a
// malformed output fails the test that reads it. read_csv_cells: every cell
// as text, RFC 4180 quotes undone (text columns such as status or error).

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fourbar::testing {

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

struct CsvCells {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// The cells of one record starting at `line`; a quoted cell may go on over
/// further lines of `in`.
inline std::vector<std::string> split_csv_record(std::string line, std::istream& in) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0;; ++i) {
    if (i == line.size()) {
      if (!quoted) break;
      std::string more;
      if (!std::getline(in, more)) throw std::runtime_error("unterminated quoted cell: " + line);
      line += "\n" + more;
    }
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else cells.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

inline CsvCells read_csv_cells(const std::filesystem::path& p) {
  std::ifstream in(p);
  CsvCells csv;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto cells = split_csv_record(line, in);
    if (csv.header.empty()) csv.header = std::move(cells);
    else csv.rows.push_back(std::move(cells));
  }
  return csv;
}

inline Csv read_csv(const std::filesystem::path& p) {
  const CsvCells cells = read_csv_cells(p);
  Csv csv{cells.header, {}};
  for (const auto& r : cells.rows) {
    auto& row = csv.rows.emplace_back();
    for (const std::string& cell : r) row.push_back(cell.empty() ? std::numeric_limits<double>::quiet_NaN() : std::stod(cell));
  }
  return csv;
}

}  // namespace fourbar::testing
