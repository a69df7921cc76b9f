// Fuzz target: the MATLAB recording reader. fourbar reads .mat files in the
// program fourbar-read-mat (acquire/mat_reader.cpp); its code, libmatio's v5
// reading and fourbar's checks before it (acquire/mat_contents.cpp), runs
// here in the fuzzer's process for v4/v5 inputs, so that coverage guides
// the fuzzer and the sanitizers see it. v7.3 inputs (libhdf5, which has
// known heap overflows on damaged files) go through the recording front end
// as fourbar reads them: fourbar-read-mat, the result sent back, then
// `fourbar inspect`'s statistics over it. The first byte picks the manifest
// options (none, rate_variable "fs", sample_rate_hz); the rest is the file,
// named .mat. Every frame is read twice (the pipeline rewinds).
#include <vector>

#include "acquire/inspect.hpp"
#include "acquire/mat_contents.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  if (size < 1) return 0;
  ReaderOptions opt;
  if (data[0] & 1) opt.rate_variable = "fs";
  else if (data[0] & 2) opt.sample_rate_hz = 1000.0;
  const auto file = fuzz::workspace().write("fuzz_recording.mat", data + 1, size - 1);
  try {
    if (mat_header_version(file) != 0x0200) {
      const MatContents c = read_mat_contents(file, opt);
      const auto channels = static_cast<std::size_t>(c.info.channels);
      if (channels == 0 || !(c.info.sample_rate_hz > 0) || c.columns.size() != channels) std::abort();
      if (c.info.channel_names.size() != channels) std::abort();  // every channel is named
      for (const auto& col : c.columns)
        if (col.size() != c.info.frames) std::abort();
      return 0;
    }
    const auto reader = open_recording(file, opt);
    const auto channels = static_cast<std::size_t>(reader->info().channels);
    if (channels == 0 || !(reader->info().sample_rate_hz > 0)) std::abort();
    if (reader->info().channel_names.size() != channels) std::abort();  // every channel is named
    std::vector<double> block(channels * 5);
    for (int pass = 0; pass < 2; ++pass) {
      std::uint64_t frames = 0;
      while (const std::size_t n = reader->read(block)) frames += n;
      if (frames != reader->info().frames) std::abort();
      reader->rewind();
    }
    const RecordingInspection r = inspect_recording(*reader);
    if (r.channels.size() != channels) std::abort();
  } catch (const InputError&) {
  }
  return 0;
}
