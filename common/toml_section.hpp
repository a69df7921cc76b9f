#pragma once
// Strict, self-describing reading of one TOML table (rig, scene, manifest).
//
// Every accessor names the file, line and dotted key in its error, and
// `finish()` rejects keys nobody asked for, with a "did you mean" hint, so a
// misspelt key is an error instead of a silently ignored default.

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace fourbar {

/// Parses a TOML file; throws InputError naming file and line on failure.
toml::table parse_toml_file(const std::filesystem::path& file);

class TomlSection {
 public:
  /// `prefix` is the dotted path of `table` inside the file ("" for the root).
  TomlSection(const toml::table& table, std::filesystem::path file, std::string prefix = "");

  bool has(std::string_view key);

  double number(std::string_view key);
  std::optional<double> optional_number(std::string_view key);
  /// Required number that must be > 0 (finite).
  double positive(std::string_view key);
  /// Required number that must be >= 0 (finite).
  double non_negative(std::string_view key);
  /// Number in [lo, hi]; `fallback` when absent (nullopt: required).
  double in_range(std::string_view key, double lo, double hi, std::optional<double> fallback = {});
  long long integer(std::string_view key, long long lo, long long hi, std::optional<long long> fallback = {});
  bool boolean(std::string_view key, std::optional<bool> fallback = {});

  std::string string(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);
  /// String that must be one of `choices`; `fallback` when absent.
  std::string choice(std::string_view key, const std::vector<std::string>& choices,
                     std::optional<std::string> fallback = {});
  std::vector<std::string> strings(std::string_view key);
  /// Array of finite numbers (integers or floats).
  std::vector<double> numbers(std::string_view key);

  /// A path relative to the file's folder, made absolute.
  std::filesystem::path path(std::string_view key);

  /// Child table; required unless `optional` (then nullopt when absent).
  TomlSection section(std::string_view key);
  std::optional<TomlSection> optional_section(std::string_view key);
  /// Array of tables (`[[key]]`); empty when absent.
  std::vector<TomlSection> sections(std::string_view key);

  /// Throws InputError for every key present but never read.
  void finish() const;

  const std::filesystem::path& file() const { return file_; }
  /// "file:line: key 'a.b'" — the prefix every error about `key` starts with.
  std::string where(std::string_view key) const;
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;

 private:
  const toml::node& require(std::string_view key);
  const toml::node* find(std::string_view key);
  std::string dotted(std::string_view key) const;

  const toml::table* table_;
  std::filesystem::path file_;
  std::string prefix_;
  std::set<std::string, std::less<>> used_;   // keys read
  std::set<std::string, std::less<>> asked_;  // keys looked for, present or not
};

/// The closest of `candidates` to `word` by edit distance, if close enough.
std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace fourbar
