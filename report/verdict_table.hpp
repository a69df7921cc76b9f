#pragma once
// The short table `fourbar report` ends with on stdout: one row per
// recording — name, status, the overall verdict, the a it judges by, then
// each verdict part's level and words (report/verdict.hpp verdict_parts()) —
// in columns aligned with spaces (widths counted in characters, not bytes).

#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

/// Rows of `records` (session records, each with name, status and, when
/// analysed, verdict and metrics); a header line first; every line ends in '\n'.
std::string verdict_text_table(const nlohmann::json& records);

/// The a a verdict (verdict_json) judges by: "0.841 ± 0.12 (scatter)"; "–" when it has none.
std::string verdict_a_text(const nlohmann::json& verdict);

/// Characters (UTF-8 code points) in `s`.
std::size_t display_width(const std::string& s);

}  // namespace fourbar
