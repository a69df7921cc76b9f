#include "common/number_text.hpp"

#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace fourbar {

void append_double(std::string& out, double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, end);
}

std::string format_double(double v) {
  std::string s;
  append_double(s, v);
  return s;
}

std::string format_input_decimal(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return format_double(std::strtod(buf, nullptr));
}

}  // namespace fourbar
