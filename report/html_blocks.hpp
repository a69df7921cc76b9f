#pragma once
// Building blocks of the HTML report's pages: a chart box (filled by the
// report's scripts), the polar plot of impact directions (inline SVG), the
// settings and input-file tables.

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

/// A titled box with a chart <div id=id>, its legend and (optionally) the
/// series toggles; the chart scripts draw into it by id.
void chart_box(std::ostringstream& h, const std::string& id, const std::string& title, bool small = false,
               bool controls = false);

/// Inline SVG: impact directions on a part, dots at the contact angle, radius by impulse.
std::string polar_svg(const nlohmann::json& impacts, const char* key, const std::string& title);

/// A record key as a label for people: "speed_std_rpm" → "speed std (rpm)".
std::string human_label(const std::string& key);

/// One table row per leaf of `j` (empty tables and arrays left out), the
/// keys as human_label()s joined with " › " under `prefix`.
void settings_rows(std::ostringstream& h, const nlohmann::json& j, const std::string& prefix);

/// Input files: role, path, bytes and SHA-256.
void files_table(std::ostringstream& h, const nlohmann::json& files);

}  // namespace fourbar
