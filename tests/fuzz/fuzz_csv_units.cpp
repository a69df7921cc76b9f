// Fuzz target: units in text exports (acquire/csv_units.cpp: `name [unit]`
// headers and the units row) through the text reader, then the manifest
// template written from the inspection. Properties: the reader either opens
// or fails with InputError; a channel keeps a non-empty bare name and, when
// the export gives units, one unit per channel; the template (any column
// name, quoted with toml_quoted) parses as TOML and load_manifest refuses it
// for its "FILL IN" placeholders.
#include <string>
#include <vector>

#include "acquire/csv_units.hpp"
#include "acquire/inspect.hpp"
#include "acquire/manifest.hpp"
#include "acquire/manifest_template.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "common/toml_section.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  // The pure functions on the first line.
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string first = text.substr(0, text.find('\n'));
  const NameAndUnit nu = split_unit(first);
  if (!nu.unit.empty() && nu.name.empty()) std::abort();
  std::vector<std::string_view> cells;
  for (std::size_t at = 0; at <= first.size();) {
    const std::size_t end = std::min(first.find(',', at), first.size());
    cells.push_back(std::string_view(first).substr(at, end - at));
    at = end + 1;
  }
  (void)is_units_row(cells);

  const auto file = fuzz::workspace().write("fuzz_export.csv", data, size);
  std::unique_ptr<Reader> reader;
  RecordingInspection r;
  try {
    reader = open_recording(file, {1000.0, {}, {}});
    const auto& info = reader->info();
    for (const auto& n : info.channel_names)
      if (n.empty()) std::abort();
    if (!info.channel_units.empty() && info.channel_units.size() != info.channel_names.size()) std::abort();
    r = inspect_recording(*reader);
  } catch (const InputError&) {
    return 0;
  }
  const std::string tmpl = manifest_template(r, {1000.0, {}, {}});
  const auto manifest =
      fuzz::workspace().write("fuzz_export.toml", reinterpret_cast<const std::uint8_t*>(tmpl.data()), tmpl.size());
  try {
    (void)parse_toml_file(manifest);
  } catch (const InputError&) {
    std::abort();  // the template must be valid TOML whatever the column names
  }
  try {
    (void)load_manifest(manifest);
    std::abort();  // an unfilled template must be refused
  } catch (const InputError& e) {
    if (std::string(e.what()).find("FILL IN") == std::string::npos) std::abort();
  }
  return 0;
}
