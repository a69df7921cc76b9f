#pragma once
// The header row of a text export below a metadata preamble. DAQ software
// writes a few lines above the header ("Exported by …", "Start;27.11.2026
// 10:15:32", "Sample rate;12800;Hz"); the header is the first row that is
// followed by data rows of as many cells, all numbers (after an optional
// units row), or the line the manifest's `header_line` names. The preamble's
// sample rate and start, where it states them, are kept.

#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fourbar {

struct CsvPreamble {
  std::size_t header_line = 0;               ///< 1-based line of the header row; 0: none found
  std::optional<double> sample_rate_hz;      ///< the preamble's sample rate
  std::size_t rate_line = 0;                 ///< the line that states it
  std::string started_at;                    ///< the preamble's start date/time, as written
  std::size_t preamble_lines = 0;            ///< non-blank lines above the header (comments included)
};

/// Reads `in` from its start (and leaves it there again). `header_line`:
/// the manifest's, 1-based; InputError naming `file` when it lies beyond
/// the file or on a blank line.
CsvPreamble find_csv_header(std::istream& in, const std::string& file, std::optional<std::size_t> header_line);

/// The delimiter a header row uses: tab, else ';', else ','.
char csv_delimiter(std::string_view header);

}  // namespace fourbar
