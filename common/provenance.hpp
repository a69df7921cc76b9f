#pragma once
// What made an output file: tool version, command line and input files.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fourbar {

struct Provenance {
  std::string command;                          ///< the command line as given
  std::vector<std::filesystem::path> inputs;    ///< every file read
  bool csv_comments = false;                    ///< --csv-comments: also as `#` lines above each CSV header

  /// The provenance as text lines ("made by fourbar VERSION: COMMAND", "input: FILE").
  std::vector<std::string> comment_lines() const;
  /// comment_lines() with --csv-comments, else none: what a CsvWriter puts above its header.
  std::vector<std::string> csv_comment_lines() const;
  /// A JSON object {tool, version, command, inputs}.
  nlohmann::json to_json() const;
};

}  // namespace fourbar
