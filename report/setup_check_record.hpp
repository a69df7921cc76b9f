#pragma once
// The set-up check (analyze/setup_check.hpp) as the report and `fourbar
// analyze` show it: the `setup_check` object of summary.json, the warning
// lines on stderr and the box at the top of the HTML report.
//
// A recording whose check finds a likely mistake has status "check set-up"
// instead of "ok": it was analysed and compared like any other, but its
// numbers rest on a manifest the data contradict.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analyze/setup_check.hpp"

namespace fourbar {

/// The record status of an analysed recording: "ok" or "check set-up".
std::string analysed_status(const SetupCheck& check);

/// True for a record that went through the analysis ("ok" or "check set-up").
bool is_analysed(const nlohmann::json& record);

/// {status, findings: [{item, channel, key, manifest, data, confidence,
/// message}], crank: {offset_deg, direction}, swapped, channels: [...], fit,
/// fit_manifest, band_orders, normal_consistency, not_checked}.
nlohmann::json setup_check_json(const SetupCheck& check, const std::string& manifest_file);

/// One line per finding: "check set-up: MANIFEST: <finding message>".
std::vector<std::string> setup_check_lines(const nlohmann::json& setup_check);

/// The findings as an HTML warning box titled with `title` (empty when none).
std::string setup_check_html(const nlohmann::json& setup_check, const std::string& title);

}  // namespace fourbar
