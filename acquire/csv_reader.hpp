#pragma once
// Delimited-text recordings (CSV, TSV, semicolon-separated exports).
//
// Layout: optional `#` comment lines and blank lines anywhere; one header row
// of column names; then one row per sample. The delimiter is whichever of
// tab, `;` or `,` the header uses (in that order of preference); with `;` or
// tab, a decimal comma ("1,25") is accepted too. A time column (named `t`,
// `time`, `time_s`, `time [s]`, or `time_ms`/`time [ms]` in milliseconds, or
// the manifest's `time_column`) gives the sample rate and must be uniform to
// within half a sample; without it the manifest's `sample_rate_hz` is
// required. Every other column is a channel, named by its header. A cell
// that is not a finite number is an error naming file:line:column.

#include <span>

#include "acquire/reader.hpp"

namespace fourbar {

/// True for the extensions .csv, .tsv and .txt.
bool csv_claims(const std::filesystem::path& file, std::span<const unsigned char> head);

std::unique_ptr<Reader> open_csv_reader(const std::filesystem::path& file, const ReaderOptions& options);

}  // namespace fourbar
