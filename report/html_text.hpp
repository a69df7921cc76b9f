#pragma once
// Text helpers of the HTML report: escaping for HTML, <script> and inlined
// JSON; number formatting of the session record; safe lookup of nested keys.

#include <filesystem>
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

/// The folder with dygraph.min.js and dygraph.min.css (libjs-dygraphs);
/// FOURBAR_DYGRAPHS_DIR in the environment overrides the built-in path.
std::filesystem::path dygraphs_dir();

/// A whole text file; RunError naming libjs-dygraphs when it cannot be read.
std::string read_text(const std::filesystem::path& p);

/// Drops source-map comments (they would make developer tools fetch a file).
std::string without_source_maps(std::string text);

/// JavaScript inside <script>: only "</script" (any case) ends the element;
/// "<\/script" means the same in JavaScript strings and regular expressions.
std::string script_safe(std::string text);

/// JSON inside <script>: every "<" (only in strings) as \u003c.
std::string json_safe(const std::string& text);

/// `s` with & < > " escaped for HTML text and attributes.
std::string html_escape(const std::string& s);

/// Six significant digits: the embedded data stays small, the plots identical.
/// Non-finite numbers become null.
void round_numbers(nlohmann::json& j);

/// j[k1][k2]…, or null when any step is missing.
const nlohmann::json& at(const nlohmann::json& j, std::initializer_list<const char*> keys);

/// A value for a table cell: "–" for null, yes/no, escaped strings, numbers by
/// the printf format `f`.
std::string fmt(const nlohmann::json& v, const char* f = "%.4g");

}  // namespace fourbar
