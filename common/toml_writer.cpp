#include "common/toml_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fourbar {

std::string toml_quoted(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  for (const char ch : text) {
    const auto byte = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\t': out += "\\t"; break;
      case '\n': out += "\\n"; break;
      case '\f': out += "\\f"; break;
      case '\r': out += "\\r"; break;
      default:
        if (byte < 0x20 || byte == 0x7F) {  // TOML 1.0: "control characters … must be escaped"
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04X", static_cast<unsigned>(byte));
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  out += '"';
  return out;
}

std::string toml_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, end);
  if (s.find_first_of(".e") == std::string::npos && std::abs(v) >= 1e15) s += ".0";
  return s;
}

std::string toml_number_in_unit(double si, double in_unit, double (*to_si)(double)) {
  if (!std::isfinite(in_unit)) return toml_number(in_unit);
  std::string best;
  double below = in_unit, above = in_unit;
  const double inf = std::numeric_limits<double>::infinity();
  auto consider = [&](double x) {
    if (to_si(x) != si || std::signbit(x) != std::signbit(in_unit)) return;
    std::string s = toml_number(x);
    if (best.empty() || s.size() < best.size()) best = std::move(s);
  };
  consider(in_unit);
  for (int k = 0; k < 4; ++k) {
    consider(below = std::nextafter(below, -inf));
    consider(above = std::nextafter(above, inf));
  }
  return best.empty() ? toml_number(in_unit) : best;
}

}  // namespace fourbar
