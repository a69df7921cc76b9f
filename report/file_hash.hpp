#pragma once
// SHA-256 of files and text (OpenSSL libcrypto, EVP interface): checksums in
// the report and the keys of the report cache.

#include <filesystem>
#include <string>
#include <string_view>

namespace fourbar {

/// Lower-case hex SHA-256 of a file's bytes; InputError when it cannot be read.
std::string sha256_file(const std::filesystem::path& file);
/// Lower-case hex SHA-256 of `text`.
std::string sha256_text(std::string_view text);

}  // namespace fourbar
