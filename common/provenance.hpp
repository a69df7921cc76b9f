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

  /// Lines for the `#` header of a CSV file.
  std::vector<std::string> comment_lines() const;
  /// A JSON object {tool, version, command, inputs}.
  nlohmann::json to_json() const;
};

}  // namespace fourbar
