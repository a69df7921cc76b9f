#include "acquire/csv_units.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace fourbar {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool is_number(std::string_view cell) {
  std::string buf(trim(cell));
  std::replace(buf.begin(), buf.end(), ',', '.');
  std::string_view v = buf;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  double x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  return !v.empty() && ec == std::errc() && end == v.data() + v.size();
}

}  // namespace

NameAndUnit split_unit(std::string_view header_cell) {
  const std::string_view cell = trim(header_cell);
  if (cell.size() >= 3) {
    const char close = cell.back();
    const char open = close == ']' ? '[' : close == ')' ? '(' : '\0';
    const std::size_t at = open ? cell.rfind(open) : std::string_view::npos;
    // "(V)" needs a space before it: "data(:,1)" is a name, not a unit.
    if (at != std::string_view::npos && at > 0 && (open == '[' || std::isspace(static_cast<unsigned char>(cell[at - 1])))) {
      const std::string_view name = trim(cell.substr(0, at)), unit = trim(cell.substr(at + 1, cell.size() - at - 2));
      if (!name.empty() && unit.find_first_of("[]()") == std::string_view::npos) return {std::string(name), std::string(unit)};
    }
  }
  return {std::string(cell), ""};
}

bool is_units_row(const std::vector<std::string_view>& cells) {
  bool any_text = false;
  for (const auto c : cells) {
    if (is_number(c)) return false;
    any_text = any_text || !trim(c).empty();
  }
  return any_text;
}

std::string unit_cell(std::string_view cell) {
  std::string_view u = trim(cell);
  if (u.size() >= 2 && ((u.front() == '[' && u.back() == ']') || (u.front() == '(' && u.back() == ')')))
    u = trim(u.substr(1, u.size() - 2));
  return std::string(u);
}

}  // namespace fourbar
