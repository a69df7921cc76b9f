#include "acquire/manifest_placeholders.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace fourbar {

namespace {

struct Placeholder {
  std::size_t line;
  std::string key;
};

void check_node(const toml::node& node, const std::string& key, std::vector<Placeholder>& found);

void check_table(const toml::table& t, const std::string& prefix, std::vector<Placeholder>& found) {
  for (const auto& [k, v] : t) check_node(v, prefix + std::string(k.str()), found);
}

void check_node(const toml::node& node, const std::string& key, std::vector<Placeholder>& found) {
  if (const auto* s = node.as_string()) {
    if (std::string_view(s->get()).substr(0, kFillIn.size()) == kFillIn)
      found.push_back({static_cast<std::size_t>(node.source().begin.line), key});
  } else if (const auto* t = node.as_table()) {
    check_table(*t, key + ".", found);
  } else if (const auto* a = node.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i) check_node(*a->get(i), key + "[" + std::to_string(i) + "]", found);
  }
}

}  // namespace

void reject_placeholders(const toml::table& doc, const std::filesystem::path& file) {
  std::vector<Placeholder> found;
  check_table(doc, "", found);
  if (found.empty()) return;
  // The first in the file, not in the table's (alphabetical) order.
  const auto first = std::min_element(found.begin(), found.end(),
                                      [](const Placeholder& a, const Placeholder& b) { return a.line < b.line; });
  throw InputError(file.string() + ":" + std::to_string(first->line) + ": " + first->key + " is still \"" +
                   std::string(kFillIn) + "\" (the manifest template's placeholder); replace it with the value the "
                   "comment on that line asks for" +
                   (found.size() > 1 ? " (" + std::to_string(found.size()) + " placeholders are left in the file)" : ""));
}

}  // namespace fourbar
