// Fuzz target: the NI TDMS reader (acquire/tdms_structure.cpp, acquire/tdms_reader.cpp) called
// directly (through open_recording, a mutated file that starts like another
// format would test that format's reader). The first byte picks the
// manifest's sample_rate_hz (none, or one the file may contradict); the rest
// is the file. Every frame is read twice (the pipeline rewinds).
#include "acquire/tdms_reader.hpp"
#include "common/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  if (size < 1) return 0;
  ReaderOptions opt;
  if (data[0] & 1) opt.sample_rate_hz = (data[0] & 2) ? 1000.0 : 65536.0;
  const auto file = fuzz::workspace().write("fuzz_recording.tdms", data + 1, size - 1);
  try {
    const auto reader = open_tdms_reader(file, opt);
    fuzz::read_all_twice(*reader);
  } catch (const InputError&) {
  }
  return 0;
}
