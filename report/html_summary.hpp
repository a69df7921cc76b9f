#pragma once
// The session-level sections of the HTML report: the summary (set-up check
// boxes, one row per recording, ignored files) and the severity charts
// against clearance and crank speed.

#include <sstream>

#include <nlohmann/json.hpp>

namespace fourbar {

/// <section id="summary"> for the (rounded) session record.
void summary_section(std::ostringstream& h, const nlohmann::json& data);

/// <section id="session">: the four severity chart boxes.
void severity_section(std::ostringstream& h, const nlohmann::json& data);

}  // namespace fourbar
