#include "acquire/manifest_placeholders.hpp"

#include <string>

#include "common/error.hpp"

namespace fourbar {

namespace {

void check_node(const toml::node& node, const std::string& key, const std::filesystem::path& file);

void check_table(const toml::table& t, const std::string& prefix, const std::filesystem::path& file) {
  for (const auto& [k, v] : t) check_node(v, prefix + std::string(k.str()), file);
}

void check_node(const toml::node& node, const std::string& key, const std::filesystem::path& file) {
  if (const auto* s = node.as_string()) {
    if (std::string_view(s->get()).substr(0, kFillIn.size()) == kFillIn)
      throw InputError(file.string() + ":" + std::to_string(node.source().begin.line) + ": " + key + " is still \"" +
                       std::string(kFillIn) +
                       "\" (the manifest template's placeholder); replace it with the value the comment on that line "
                       "asks for");
  } else if (const auto* t = node.as_table()) {
    check_table(*t, key + ".", file);
  } else if (const auto* a = node.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i) check_node(*a->get(i), key + "[" + std::to_string(i) + "]", file);
  }
}

}  // namespace

void reject_placeholders(const toml::table& doc, const std::filesystem::path& file) { check_table(doc, "", file); }

}  // namespace fourbar
