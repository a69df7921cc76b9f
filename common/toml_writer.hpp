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

}  // namespace fourbar
