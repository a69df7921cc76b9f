#pragma once
// Cells of the text formats acquire reads (CSV rows and preambles, UFF
// records): trimming and splitting, one definition for every reader.

#include <string_view>
#include <vector>

namespace fourbar {

/// `s` without leading and trailing white space.
std::string_view trim_space(std::string_view s);

/// A CSV cell: white space trimmed, then one pair of enclosing double quotes.
std::string_view trim_cell(std::string_view s);

/// The cells of one CSV line split at `delimiter`, each as trim_cell().
std::vector<std::string_view> split_cells(std::string_view line, char delimiter);

}  // namespace fourbar
