#pragma once
// The manifest a technician starts from: `fourbar inspect REC
// --manifest-template` writes what the data tell (channels, the crank-pulse
// channel and its polarity, roles a column name gives, units, the rate's
// source) and a "FILL IN" placeholder (manifest_placeholders.hpp) with a
// comment for every value only the set-up can tell. load_manifest refuses
// the file until each placeholder is replaced.

#include <filesystem>
#include <string>

#include "acquire/inspect.hpp"

namespace fourbar {

/// `options` are those the recording was opened with (a rate given on the
/// command line is written into the template). Strings through toml_quoted.
std::string manifest_template(const RecordingInspection& inspection, const ReaderOptions& options);

}  // namespace fourbar
