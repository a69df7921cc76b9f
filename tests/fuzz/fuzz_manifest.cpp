// Fuzz target: the recording manifest loader (acquire/manifest.cpp). A
// manifest that loads must also survive its own round trip: written back by
// manifest_to_toml (what the virtual rig does) it loads again to the same text.
#include <cstdlib>

#include "acquire/manifest.hpp"
#include "common/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  const auto& ws = fuzz::workspace();
  const auto file = ws.write("fuzz_manifest.toml", data, size);
  Manifest m;
  try {
    m = load_manifest(file);
  } catch (const InputError&) {
    return 0;
  }
  const std::string text = manifest_to_toml(m, ws.dir());
  const auto again = ws.write("fuzz_manifest_again.toml", reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  const Manifest m2 = load_manifest(again);  // must not throw
  if (manifest_to_toml(m2, ws.dir()) != text) std::abort();
  return 0;
}
