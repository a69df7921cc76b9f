#include "report/verdict_table.hpp"

#include <algorithm>
#include <vector>

#include "common/format.hpp"
#include "report/verdict.hpp"

namespace fourbar {

using nlohmann::json;

std::size_t display_width(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::string verdict_a_text(const json& v) {
  if (!v.is_object() || !v.value("a", json()).is_number()) return "–";
  return format_number(v["a"].get<double>(), 3) +
         (v.value("a_standard_error", json()).is_number() ? " ± " + format_number(v["a_standard_error"].get<double>(), 2) : std::string()) +
         " (" + v.value("a_from", "") + ")";
}

std::string verdict_text_table(const json& records) {
  std::vector<std::string> header = {"recording", "status", "verdict", "a"};
  for (const VerdictPartInfo& p : verdict_parts()) header.push_back(p.label);
  std::vector<std::vector<std::string>> rows = {header};
  for (const json& r : records) {
    std::vector<std::string> row = {r.value("name", ""), r.value("status", "")};
    if (!r.contains("verdict")) {
      row.resize(header.size(), "–");
    } else {
      const json& v = r["verdict"];
      row.push_back(v.value("overall", ""));
      row.push_back(verdict_a_text(v));  // the a the verdict judged by: spectral, time or scatter
      for (const VerdictPartInfo& p : verdict_parts())
        row.push_back(v[p.key]["level"].get<std::string>() + ": " + v[p.key]["words"].get<std::string>());
    }
    rows.push_back(std::move(row));
  }
  std::vector<std::size_t> width(rows[0].size(), 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], display_width(row[c]));
  std::string out;
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      line += row[c];
      if (c + 1 < row.size()) line += std::string(width[c] - display_width(row[c]) + 2, ' ');
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace fourbar
