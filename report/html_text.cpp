#include "report/html_text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "common/json_text.hpp"

#ifndef FOURBAR_DYGRAPHS_DIR
#define FOURBAR_DYGRAPHS_DIR "/usr/share/javascript/dygraphs"
#endif

namespace fourbar {

using nlohmann::json;

std::filesystem::path dygraphs_dir() {
  if (const char* env = std::getenv("FOURBAR_DYGRAPHS_DIR")) return env;
  return FOURBAR_DYGRAPHS_DIR;
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in)
    throw RunError(p.string() + ": cannot be read; the report inlines Debian's dygraphs: install libjs-dygraphs "
                                "(scripts/install-deps.sh) or set FOURBAR_DYGRAPHS_DIR");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Drops source-map comments (they would make developer tools fetch a file).
std::string without_source_maps(std::string text) {
  for (const char* marker : {"//# sourceMappingURL=", "/*# sourceMappingURL="}) {
    for (auto p = text.find(marker); p != std::string::npos; p = text.find(marker)) {
      auto e = text.find('\n', p);
      if (std::string(marker).starts_with("/*")) e = text.find("*/", p) + 2;
      text.erase(p, e == std::string::npos ? std::string::npos : e - p);
    }
  }
  return text;
}

/// JavaScript inside <script>: only "</script" (any case) ends the element;
/// "<\/script" means the same in JavaScript strings and regular expressions.
std::string script_safe(std::string text) {
  for (std::size_t p = 0; (p = text.find("</", p)) != std::string::npos; ++p) {
    std::string ahead = text.substr(p, 8);
    for (char& c : ahead) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ahead == "</script") text.insert(p + 1, "\\");
  }
  return text;
}

/// JSON inside <script>: every "<" (only in strings) as \u003c.
std::string json_safe(const std::string& text) {
  std::string o;
  o.reserve(text.size());
  for (char c : text) {
    if (c == '<') o += "\\u003c";
    else o += c;
  }
  return o;
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

/// Six significant digits: the embedded data stays small, the plots identical.
/// std::to_chars with a precision writes what printf's %.6g writes, and
/// std::from_chars reads it back correctly rounded as strtod does, at a
/// fraction of their cost (a report holds some 10^5 numbers).
void round_numbers(json& j) {
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (!std::isfinite(v)) {
      j = nullptr;
      return;
    }
    char buf[32];
    const auto written = std::to_chars(buf, buf + sizeof buf - 1, v, std::chars_format::general, 6);
    *written.ptr = '\0';
    double rounded = 0;
    if (std::from_chars(buf, written.ptr, rounded).ec != std::errc())
      rounded = std::strtod(buf, nullptr);  // (not seen for a finite double: six digits stay in range)
    j = rounded;
  } else if (j.is_structured()) {
    for (auto& e : j) round_numbers(e);
  }
}

/// j[k1][k2]…, or null when any step is missing.
const json& at(const json& j, std::initializer_list<const char*> keys) {
  static const json null_value;
  const json* p = &j;
  for (const char* k : keys) {
    if (!p->is_object() || !p->contains(k)) return null_value;
    p = &(*p)[k];
  }
  return *p;
}

std::string fmt(const json& v, const char* f) {
  if (v.is_null()) return "–";
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_string()) return html_escape(v.get<std::string>());
  if (!v.is_number()) return html_escape(json_text(v));
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v.get<double>());
  return buf;
}

}  // namespace fourbar
