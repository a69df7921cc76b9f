#pragma once
// Numbers in the files fourbar writes (CSV cells, TOML values): the shortest
// decimal that reads back to the same double (std::to_chars without a
// precision: 0.0254, 350, 1e-07), one formatter for every writer.

#include <string>

namespace fourbar {

/// Appends the shortest round-trip decimal of `v` to `out` (finite or not:
/// "inf", "nan"; the CSV writer refuses non-finite values before this).
void append_double(std::string& out, double v);

/// Shortest round-trip decimal form of `v`.
std::string format_double(double v);

/// A value a person wrote in a file (0.0254 mm, 350 rpm) that came back from
/// SI through a unit conversion carries the conversion's rounding in its
/// last digit (0.025400000000000002): 15 significant digits give back the
/// decimal the file holds, then the shortest form of that. Only for such
/// input values, never for computed ones (it rounds away their 16th and 17th
/// digits).
std::string format_input_decimal(double v);

}  // namespace fourbar
