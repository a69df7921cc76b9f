// Fuzz target: the UFF dataset 58/58b reader (acquire/uff_reader.cpp) called
// directly (through open_recording, a mutated file that starts like another
// format would test that format's reader). The first byte picks the
// manifest's sample_rate_hz (none, or one the file may contradict); the rest
// is the file. Every frame is read twice (the pipeline rewinds).
#include <vector>

#include "acquire/uff_reader.hpp"
#include "common/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  if (size < 1) return 0;
  ReaderOptions opt;
  if (data[0] & 1) opt.sample_rate_hz = (data[0] & 2) ? 1000.0 : 65536.0;
  const auto file = fuzz::workspace().write("fuzz_recording.uff", data + 1, size - 1);
  try {
    const auto reader = open_uff_reader(file, opt);
    const auto channels = static_cast<std::size_t>(reader->info().channels);
    std::vector<double> block(channels * 7);
    for (int pass = 0; pass < 2; ++pass) {
      std::uint64_t frames = 0;
      while (const std::size_t n = reader->read(block)) frames += n;
      if (frames != reader->info().frames) std::abort();  // the promised frame count is what reads back
      reader->rewind();
    }
  } catch (const InputError&) {
  }
  return 0;
}
