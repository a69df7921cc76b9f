#pragma once
// The verdict (report/verdict.hpp) in the HTML report: a table of the
// recordings' verdict words at the top of the summary, and the four
// sentences first thing in each recording's section.

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

/// One row per recording: overall level and the words of each part (failed recordings named as such).
void verdict_summary_table(std::ostringstream& h, const nlohmann::json& records);

/// The recording's verdict box (empty when the record has no verdict).
std::string verdict_box(const nlohmann::json& record);

/// "a (spectral) from orders 6, 7, 9; left out: orders 1 … 5 (nominal band), 12, 24 (mains hum)." of a
/// quantity's `magnification` object.
std::string spectral_orders_note(const nlohmann::json& magnification);

}  // namespace fourbar
