#pragma once
// The manifest template's placeholder. `fourbar inspect --manifest-template`
// writes `"FILL IN"` for every value only the technician knows (rig file,
// sensitivities, positions, axis signs, crank offset and direction); a
// manifest that still holds one is refused, naming the key, so an unfilled
// template can never be analysed with a made-up value.

#include <filesystem>
#include <string_view>

#include <toml++/toml.h>

namespace fourbar {

inline constexpr std::string_view kFillIn = "FILL IN";

/// InputError `file:line: key is still "FILL IN" …` for the first string
/// value (at any depth, array tables included) that begins with kFillIn.
void reject_placeholders(const toml::table& doc, const std::filesystem::path& file);

}  // namespace fourbar
