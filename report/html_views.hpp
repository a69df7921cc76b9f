#pragma once
// The views of one recording in the HTML report (the record's `views`,
// report/views_record.hpp): the channel / calibration sheet as a table, and
// the boxes the report's views script (assets/views.js) draws the raw-signal
// excerpt, the crank speed and the deviation map into.

#include <cstddef>
#include <sstream>

#include <nlohmann/json.hpp>

namespace fourbar {

/// The views of record `r` (the `ri`-th recording); nothing when it has none.
void views_section(std::ostringstream& h, const nlohmann::json& r, std::size_t ri);

}  // namespace fourbar
