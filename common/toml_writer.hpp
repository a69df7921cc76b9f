#pragma once
// Writing TOML values for fourbar to read again: one quoting rule for every
// writer (manifests, scenes, session settings, manifest templates).

#include <string>
#include <string_view>

namespace fourbar {

/// `text` as a TOML basic string, quotes included: `"` and `\` escaped, the
/// control characters TOML forbids in strings (U+0000–U+001F, U+007F) written
/// as their escapes (\b \t \n \f \r, else \uXXXX). Bytes ≥ 0x80 are copied
/// as they are (the caller's text is UTF-8, as every TOML file is).
std::string toml_quoted(std::string_view text);

/// `v` as a TOML number that reads back as the same double: the shortest
/// round-trip decimal (std::to_chars), with ".0" added where the digits
/// alone would be a TOML integer beyond its 64-bit range (1.2345678901234568e20
/// is shortest as "123456789012345683968"). inf, -inf, nan as TOML spells them.
std::string toml_number(double v);

/// A value kept in SI units but written in the file's unit (mm, degrees,
/// ms): the shortest TOML number `x` near `in_unit` for which the reader's
/// own conversion `to_si(x)` gives back `si` exactly. 0.258 mm is kept as
/// 0.000258 m; 0.000258 · 1000 is 0.25800000000000006, but "0.258" reads
/// back to the same metres, so "0.258" is written. When no double within
/// four units in the last place of `in_unit` converts back exactly (an SI
/// value no decimal in that unit can produce), `in_unit` itself.
std::string toml_number_in_unit(double si, double in_unit, double (*to_si)(double));

}  // namespace fourbar
