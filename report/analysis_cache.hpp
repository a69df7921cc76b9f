#pragma once
// The analysis cache of `fourbar report`: one JSON file per recording (the
// record of its analysis and comparison), named by the SHA-256 of its inputs
// and settings. A record read from the cache must be the record that was
// computed, or a report from the cache would differ from a fresh one.

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

namespace fourbar {

/// The record cached in `file`; nullopt when there is none, it is damaged
/// (it is then recomputed), or it is not an analysed record with its set-up
/// check, the orders of its spectral magnification and the views.
std::optional<nlohmann::json> read_cached_record(const std::filesystem::path& file);

/// Writes `record` to `file` (atomically) when it reads back equal: JSON has
/// no NaN or infinity (they would come back as null) and holds only UTF-8
/// (text from a file name in another encoding cannot be written). Such a
/// record is not cached and is computed again next time: false.
bool write_cached_record(const std::filesystem::path& file, const nlohmann::json& record);

}  // namespace fourbar
