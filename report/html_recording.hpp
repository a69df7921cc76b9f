#pragma once
// One recording's section of the HTML report: status and set-up check,
// operating point, warnings, theory-over-measurement metrics, chart boxes,
// impact directions, analysis settings and input files; or, for a recording
// that failed, the error and its input files.

#include <cstddef>
#include <sstream>

#include <nlohmann/json.hpp>

namespace fourbar {

/// Appends <section id="rec<ri>"> for the session record's recording `r`.
void recording_section(std::ostringstream& h, const nlohmann::json& r, std::size_t ri);

}  // namespace fourbar
