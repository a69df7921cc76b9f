#include "common/provenance.hpp"

#include "common/version.hpp"

namespace fourbar {

std::vector<std::string> Provenance::comment_lines() const {
  std::vector<std::string> lines{std::string("made by fourbar ") + kVersion + ": " + command};
  for (const auto& p : inputs) lines.push_back("input: " + p.string());
  return lines;
}

std::vector<std::string> Provenance::csv_comment_lines() const {
  return csv_comments ? comment_lines() : std::vector<std::string>{};
}

nlohmann::json Provenance::to_json() const {
  nlohmann::json j;
  j["tool"] = "fourbar";
  j["version"] = kVersion;
  j["command"] = command;
  j["inputs"] = nlohmann::json::array();
  for (const auto& p : inputs) j["inputs"].push_back(p.string());
  return j;
}

}  // namespace fourbar
