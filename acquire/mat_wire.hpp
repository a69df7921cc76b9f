#pragma once
// How fourbar-read-mat (acquire/read_mat_main.cpp) hands a MATLAB file's
// contents, or the error reading it raised, back to fourbar: a tag byte,
// then the description and the channels with every double as its bytes (bit
// for bit, -0 and subnormals included), or the error's message. Both sides
// are the same build, so the layout needs no version.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "acquire/mat_contents.hpp"

namespace fourbar {

/// The program's side: what `read` returns, or the InputError, RunError,
/// bad_alloc or other exception it throws, as bytes.
std::string encode_mat_result(const std::function<MatContents()>& read);

/// fourbar's side: the contents (their `info.file` set to `file`); the
/// error the bytes hold is thrown again as its type with its message;
/// nothing when the bytes are not exactly one encoded, self-consistent result.
std::optional<MatContents> decode_mat_result(std::string_view bytes, const std::filesystem::path& file);

}  // namespace fourbar
