// Fuzz target: the scene loader with its [clearance] table (sim/scene.cpp,
// sim/three_mode/settings.cpp) and the virtual rig's [recording] table
// (virtual_rig/recording_spec.cpp). The scene may name "rig.toml".
#include "common/error.hpp"
#include "fuzz_support.hpp"
#include "sim/scene.hpp"
#include "virtual_rig/recording_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  const auto file = fuzz::workspace().write("fuzz_scene.toml", data, size);
  try {
    const Scene scene = load_scene(file);
    if (scene.recording) (void)read_recording_spec(scene);
  } catch (const InputError&) {
  }
  return 0;
}
