#pragma once
// Reads a fourbar CSV output back: `#` provenance lines and blank lines
// skipped, the header row, then numeric rows. A cell that is not a number
// throws (std::stod), so a malformed output fails the test that reads it.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fourbar::testing {

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

inline Csv read_csv(const std::filesystem::path& p) {
  std::ifstream in(p);
  Csv csv;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string cell;
    if (csv.header.empty()) {
      while (std::getline(ss, cell, ',')) csv.header.push_back(cell);
      continue;
    }
    auto& row = csv.rows.emplace_back();
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
  }
  return csv;
}

}  // namespace fourbar::testing
