#include "common/toml_section.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

/// Digits of a number echoed back in a TOML error: all a file may hold that matters.
constexpr int kTomlEchoDigits = 12;

const char* type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

toml::table parse_toml_file(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(file.string() + ": no such file (check the path)");
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << file.string() << ":" << e.source().begin.line << ": not valid TOML: " << e.description();
    throw InputError(os.str());
  }
}

TomlSection::TomlSection(const toml::table& table, std::filesystem::path file, std::string prefix)
    : table_(&table), file_(std::move(file)), prefix_(std::move(prefix)) {}

std::string TomlSection::dotted(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
}

std::string TomlSection::where(std::string_view key) const {
  std::ostringstream os;
  os << file_.string();
  const toml::node* n = table_->get(key);
  const auto& src = n ? n->source() : table_->source();
  if (src.begin.line > 0) os << ":" << src.begin.line;
  os << ": key '" << dotted(key) << "'";
  return os.str();
}

void TomlSection::fail(std::string_view key, const std::string& what) const {
  throw InputError(where(key) + " " + what);
}

const toml::node* TomlSection::find(std::string_view key) {
  asked_.emplace(key);
  const toml::node* n = table_->get(key);
  if (n) used_.emplace(key);
  return n;
}

const toml::node& TomlSection::require(std::string_view key) {
  const toml::node* n = find(key);
  if (!n) {
    std::ostringstream os;
    std::vector<std::string> present;
    for (const auto& kv : *table_)
      if (!used_.count(kv.first.str())) present.emplace_back(kv.first.str());
    os << file_.string() << ": missing key '" << dotted(key) << "'"
       << (prefix_.empty() ? std::string() : " (in table [" + prefix_ + "])");
    if (auto m = closest_match(key, present)) os << "; found '" << dotted(*m) << "' instead: misspelt?";
    else os << "; add it";
    throw InputError(os.str());
  }
  return *n;
}

bool TomlSection::has(std::string_view key) {
  asked_.emplace(key);
  return table_->contains(key);
}

double TomlSection::number(std::string_view key) {
  const toml::node& n = require(key);
  std::optional<double> v;
  if (n.is_floating_point()) v = n.as_floating_point()->get();
  if (n.is_integer()) v = static_cast<double>(n.as_integer()->get());
  if (!v) fail(key, std::string("must be a number, not ") + type_name(n));
  if (!std::isfinite(*v)) fail(key, "must be a finite number, not " + format_number(*v, kTomlEchoDigits));
  return *v;
}

std::optional<double> TomlSection::optional_number(std::string_view key) {
  if (!has(key)) return std::nullopt;
  return number(key);
}

double TomlSection::positive(std::string_view key) {
  const double v = number(key);
  if (!(v > 0)) fail(key, "= " + format_number(v, kTomlEchoDigits) + " must be positive");
  return v;
}

double TomlSection::non_negative(std::string_view key) {
  const double v = number(key);
  if (!(v >= 0)) fail(key, "= " + format_number(v, kTomlEchoDigits) + " must not be negative");
  return v;
}

double TomlSection::in_range(std::string_view key, double lo, double hi, std::optional<double> fallback) {
  if (!has(key) && fallback) return *fallback;
  const double v = number(key);
  if (v < lo || v > hi)
    fail(key, "= " + format_number(v, kTomlEchoDigits) + " is outside [" + format_number(lo, kTomlEchoDigits) + ", " + format_number(hi, kTomlEchoDigits) + "]");
  return v;
}

long long TomlSection::integer(std::string_view key, long long lo, long long hi, std::optional<long long> fallback) {
  if (!has(key) && fallback) return *fallback;
  const toml::node& n = require(key);
  if (!n.is_integer()) fail(key, std::string("must be a whole number, not ") + type_name(n));
  const long long v = n.as_integer()->get();
  if (v < lo || v > hi)
    fail(key, "= " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

bool TomlSection::boolean(std::string_view key, std::optional<bool> fallback) {
  if (!has(key) && fallback) return *fallback;
  const toml::node& n = require(key);
  if (!n.is_boolean()) fail(key, std::string("must be true or false, not ") + type_name(n));
  return n.as_boolean()->get();
}

std::string TomlSection::string(std::string_view key) {
  const toml::node& n = require(key);
  if (!n.is_string()) fail(key, std::string("must be a string in quotes, not ") + type_name(n));
  return n.as_string()->get();
}

std::optional<std::string> TomlSection::optional_string(std::string_view key) {
  if (!has(key)) return std::nullopt;
  return string(key);
}

std::string TomlSection::choice(std::string_view key, const std::vector<std::string>& choices,
                                std::optional<std::string> fallback) {
  if (!has(key) && fallback) return *fallback;
  const std::string v = string(key);
  if (std::find(choices.begin(), choices.end(), v) != choices.end()) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  std::string hint;
  if (auto m = closest_match(v, choices)) hint = " (did you mean '" + *m + "'?)";
  fail(key, "= \"" + v + "\" is not one of: " + list + hint);
}

std::vector<std::string> TomlSection::strings(std::string_view key) {
  const toml::node& n = require(key);
  const toml::array* arr = n.as_array();
  if (!arr) fail(key, std::string("must be an array of strings, not ") + type_name(n));
  std::vector<std::string> out;
  for (const auto& el : *arr) {
    if (!el.is_string()) fail(key, "must hold only strings in quotes");
    out.push_back(el.as_string()->get());
  }
  return out;
}

std::vector<double> TomlSection::numbers(std::string_view key) {
  const toml::node& n = require(key);
  const toml::array* arr = n.as_array();
  if (!arr) fail(key, std::string("must be an array of numbers, e.g. [580.0, 2410.0], not ") + type_name(n));
  std::vector<double> out;
  for (const auto& el : *arr) {
    std::optional<double> v;
    if (el.is_floating_point()) v = el.as_floating_point()->get();
    if (el.is_integer()) v = static_cast<double>(el.as_integer()->get());
    if (!v || !std::isfinite(*v)) fail(key, "must hold only finite numbers");
    out.push_back(*v);
  }
  return out;
}

std::filesystem::path TomlSection::path(std::string_view key) {
  std::filesystem::path p = string(key);
  if (p.is_relative()) p = file_.parent_path() / p;
  return p.lexically_normal();
}

TomlSection TomlSection::section(std::string_view key) {
  const toml::node& n = require(key);
  if (!n.is_table()) fail(key, std::string("must be a table [") + dotted(key) + "], not " + type_name(n));
  return TomlSection(*n.as_table(), file_, dotted(key));
}

std::optional<TomlSection> TomlSection::optional_section(std::string_view key) {
  if (!has(key)) return std::nullopt;
  return section(key);
}

std::vector<TomlSection> TomlSection::sections(std::string_view key) {
  std::vector<TomlSection> out;
  const toml::node* n = find(key);
  if (!n) return out;
  const toml::array* arr = n->as_array();
  if (!arr) fail(key, std::string("must be an array of tables [[") + dotted(key) + "]], not " + type_name(*n));
  int i = 0;
  for (const auto& el : *arr) {
    if (!el.is_table()) fail(key, "must hold only tables [[" + dotted(key) + "]]");
    out.emplace_back(*el.as_table(), file_, dotted(key) + "[" + std::to_string(i++) + "]");
  }
  return out;
}

void TomlSection::finish() const {
  std::vector<std::string> known(asked_.begin(), asked_.end());
  for (const auto& [k, v] : *table_) {
    if (used_.count(k.str())) continue;
    std::string hint;
    if (auto m = closest_match(k.str(), known)) hint = " (did you mean '" + *m + "'?)";
    std::ostringstream os;
    os << file_.string();
    if (v.source().begin.line > 0) os << ":" << v.source().begin.line;
    os << ": unknown key '" << dotted(k.str()) << "'" << hint << "; remove or correct it";
    throw InputError(os.str());
  }
}

}  // namespace fourbar
