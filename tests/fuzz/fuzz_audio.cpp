// Fuzz target: the libsndfile-backed recording front end
// (acquire/reader_registry.cpp, acquire/sndfile_reader.cpp): format chosen
// by magic bytes, header checks (truncation, rate, frame count), then every
// frame read twice. The file is named .wav; content decides the format.
#include <cmath>
#include <vector>

#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  const auto file = fuzz::workspace().write("fuzz_recording.wav", data, size);
  try {
    const auto reader = open_recording(file);
    const auto channels = static_cast<std::size_t>(reader->info().channels);
    if (channels == 0 || !(reader->info().sample_rate_hz > 0)) std::abort();
    std::vector<double> block(channels * 64);
    for (int pass = 0; pass < 2; ++pass) {
      std::uint64_t frames = 0;
      while (const std::size_t n = reader->read(block)) {
        frames += n;
        if (frames > reader->info().frames) std::abort();  // never more than the header promised
      }
      reader->rewind();
    }
  } catch (const InputError&) {
  }
  return 0;
}
