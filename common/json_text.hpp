#pragma once
// JSON outputs as text. nlohmann::json::dump throws on a string that is not
// UTF-8 — a recording named in another encoding (Latin-1 "Messung_\xE4.wav",
// copied from a DAQ PC) would end a whole `fourbar report` with an internal
// error. Here such bytes are written as U+FFFD instead: the name stays
// recognisable and every other output is written.

#include <string>

#include <nlohmann/json.hpp>

namespace fourbar {

/// `j` as JSON text (`indent` < 0: one line), invalid UTF-8 replaced by U+FFFD.
inline std::string json_text(const nlohmann::json& j, int indent = -1) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace fourbar
