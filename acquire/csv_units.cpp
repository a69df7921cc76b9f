#include "acquire/csv_units.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>

#include "acquire/text_cells.hpp"

namespace fourbar {

namespace {

bool is_number(std::string_view cell) {
  std::string buf(trim_space(cell));
  std::replace(buf.begin(), buf.end(), ',', '.');
  std::string_view v = buf;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  double x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  return !v.empty() && ec == std::errc() && end == v.data() + v.size();
}

}  // namespace

NameAndUnit split_unit(std::string_view header_cell) {
  const std::string_view cell = trim_space(header_cell);
  if (cell.size() >= 3) {
    const char close = cell.back();
    const char open = close == ']' ? '[' : close == ')' ? '(' : '\0';
    const std::size_t at = open ? cell.rfind(open) : std::string_view::npos;
    // "(V)" needs a space before it: "data(:,1)" is a name, not a unit.
    if (at != std::string_view::npos && at > 0 && (open == '[' || std::isspace(static_cast<unsigned char>(cell[at - 1])))) {
      const std::string_view name = trim_space(cell.substr(0, at)), unit = trim_space(cell.substr(at + 1, cell.size() - at - 2));
      if (!name.empty() && unit.find_first_of("[]()") == std::string_view::npos) return {std::string(name), std::string(unit)};
    }
  }
  return {std::string(cell), ""};
}

bool is_units_row(const std::vector<std::string_view>& cells) {
  bool any_text = false;
  for (const auto c : cells) {
    if (is_number(c)) return false;
    any_text = any_text || !trim_space(c).empty();
  }
  return any_text;
}

std::string unit_cell(std::string_view cell) {
  std::string_view u = trim_space(cell);
  if (u.size() >= 2 && ((u.front() == '[' && u.back() == ']') || (u.front() == '(' && u.back() == ')')))
    u = trim_space(u.substr(1, u.size() - 2));
  return std::string(u);
}

std::string as_utf8(std::string_view text) {
  bool valid = true;
  for (std::size_t i = 0; i < text.size() && valid;) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > text.size() || (n == 2 && c < 0xC2) || (n == 4 && c > 0xF4)) {
      valid = false;
      break;
    }
    std::uint32_t cp = n == 1 ? c : c & (0x7F >> n);
    for (std::size_t k = 1; k < n; ++k) {
      const auto d = static_cast<unsigned char>(text[i + k]);
      if ((d >> 6) != 0x2) valid = false;
      cp = (cp << 6) | (d & 0x3F);
    }
    // Overlong forms, surrogates and beyond U+10FFFF are not UTF-8 either.
    if ((n == 3 && cp < 0x800) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)) || (cp >= 0xD800 && cp <= 0xDFFF)) valid = false;
    i += n;
  }
  if (valid) return std::string(text);
  std::string out;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x80) out += ch;
    else out += static_cast<char>(0xC0 | (c >> 6)), out += static_cast<char>(0x80 | (c & 0x3F));
  }
  return out;
}

}  // namespace fourbar
