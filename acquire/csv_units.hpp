#pragma once
// Units in text exports: DAQ software writes them into the header
// (`coupler_t [V]`, `coupler_t (V)`) or as a second row under it
// (`s;V;V;V`). The channel keeps its bare name (`coupler_t`), so a manifest's
// `column` names it either way, and the unit is reported by `fourbar inspect`.

#include <string>
#include <string_view>
#include <vector>

namespace fourbar {

struct NameAndUnit {
  std::string name;  ///< the header cell without its unit, trimmed
  std::string unit;  ///< the unit inside [ ] or ( ), trimmed; empty when none
};

/// Splits a header cell `name [unit]` (or `name[unit]`, `name (unit)`).
/// A cell that would leave an empty name is returned whole.
NameAndUnit split_unit(std::string_view header_cell);

/// True when every cell of a row is text, not a number (decimal point or
/// comma), and at least one is not empty: the units row of an export.
bool is_units_row(const std::vector<std::string_view>& cells);

/// A units row cell without its brackets: "[V]" → "V".
std::string unit_cell(std::string_view cell);

/// `text` when it is valid UTF-8; otherwise read as Latin-1 (what Windows DAQ
/// software often writes: "m/s²" as B2) and returned as UTF-8, so that every
/// column name can be written into a TOML manifest and matched again.
std::string as_utf8(std::string_view text);

}  // namespace fourbar
