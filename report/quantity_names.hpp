#pragma once
// The names a person reads for the keys of the session record: one table for
// the report's tables (C++) and its charts (the page's scripts read the same
// table from the embedded data, `names`). A key such as `alpha3_rad_s2` is
// shown as "coupler angular acceleration α3 (rad/s²)".

#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

struct QuantityName {
  const char* key;          ///< as in summary.json, e.g. "alpha3_rad_s2"
  const char* symbol;       ///< "α3"
  const char* description;  ///< "coupler angular acceleration"
  const char* unit;         ///< "rad/s²"; "" for a pure number
};

/// The entry for `key`, or nullptr for a key the table does not know.
const QuantityName* find_quantity_name(const std::string& key);

/// "coupler angular acceleration α3 (rad/s²)"; an unknown key as it is.
std::string quantity_label(const std::string& key);

/// "α3 (rad/s²)": short, for an axis; an unknown key as it is.
std::string quantity_axis_label(const std::string& key);

/// The whole table as {key: {symbol, description, unit, label, axis}}.
nlohmann::json quantity_names_json();

}  // namespace fourbar
