// Fuzz target: the rig loader (mechanism/rig.cpp, common/toml_section.cpp).
#include "common/error.hpp"
#include "fuzz_support.hpp"
#include "mechanism/rig.hpp"
#include "mechanism/rig_report.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  const auto file = fuzz::workspace().write("fuzz_rig.toml", data, size);
  try {
    const Rig rig = load_rig(file);
    (void)report_rig(rig);  // a loaded rig must be usable: the report walks a whole turn
  } catch (const InputError&) {
  }
  return 0;
}
