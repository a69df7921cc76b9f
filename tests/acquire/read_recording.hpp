#pragma once
// Reading a recording through fourbar's Reader in the acquire tests: every
// sample in blocks of a chosen size, and the InputError a file gives.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "acquire/reader.hpp"
#include "common/error.hpp"

namespace fourbar::testing {

/// Every sample of `r` (frame-interleaved), read in blocks of `block_frames`
/// frames (small blocks exercise the readers' block boundaries).
inline std::vector<double> read_all(Reader& r, std::size_t block_frames) {
  const auto c = static_cast<std::size_t>(r.info().channels);
  std::vector<double> all, block(c * block_frames);
  for (std::size_t n; (n = r.read(block)) > 0;) all.insert(all.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(c * n));
  return all;
}

/// The InputError message of opening `f` and reading it to the end in blocks
/// of `block_frames` frames, "" when there is none.
inline std::string read_error_of(const std::filesystem::path& f, const ReaderOptions& o = {}, std::size_t block_frames = 1000) {
  try {
    auto r = open_recording(f, o);
    read_all(*r, block_frames);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// The InputError message of opening `f` (its header only), "(no error)"
/// when there is none.
inline std::string open_error_of(const std::filesystem::path& f, const ReaderOptions& o = {}) {
  try {
    open_recording(f, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace fourbar::testing
