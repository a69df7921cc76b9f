// Fuzz target: the delimited-text recording reader (acquire/csv_reader.cpp)
// through the recording front end (open_recording). The first byte picks the
// manifest options (sample_rate_hz, time_column) the reader is given; the
// rest is the file. Every frame is read twice (the pipeline rewinds).
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  if (size < 1) return 0;
  ReaderOptions opt;
  if (data[0] & 1) opt.sample_rate_hz = (data[0] & 2) ? 1000.0 : 0.5;
  if (data[0] & 4) opt.time_column = (data[0] & 8) ? "t" : "time [ms]";
  const auto file = fuzz::workspace().write("fuzz_recording.csv", data + 1, size - 1);
  try {
    const auto reader = open_recording(file, opt);
    fuzz::read_all_twice(*reader);
  } catch (const InputError&) {
  }
  return 0;
}
