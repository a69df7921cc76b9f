#pragma once
// The short table `fourbar report` ends with on stdout: one row per
// recording — name, status, the verdict's words (report/verdict.hpp) and a —
// in columns aligned with spaces (widths counted in characters, not bytes).

#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

/// Rows of `records` (session records, each with name, status and, when
/// analysed, verdict and metrics); a header line first; every line ends in '\n'.
std::string verdict_text_table(const nlohmann::json& records);

/// Characters (UTF-8 code points) in `s`.
std::size_t display_width(const std::string& s);

}  // namespace fourbar
