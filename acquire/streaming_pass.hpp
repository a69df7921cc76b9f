#pragma once
// Reading a whole recording once, block by block, with the progress bar:
// what each of acquire's three passes (scan, pulses, samples) is built on.
// A recording that ends before the frames it announced is bad input.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "acquire/block_read_ahead.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"

namespace fourbar {

/// acquire's passes over the recording, in the order they run.
enum class AcquirePass { scan = 0, pulses = 1, samples = 2 };
inline constexpr std::size_t kAcquirePasses = 3;

/// What every pass reads with. `progress` runs over all passes
/// (kAcquirePasses × the recording's frames).
struct BlockStream {
  Reader& reader;
  std::size_t block_frames;  ///< frames per read
  Progress& progress;
  /// Read on a thread of its own, ahead of the work (block_read_ahead.hpp):
  /// for a caller that may use more than one core. Same blocks, same values.
  bool read_ahead = false;
  /// The scan pass may split its channels over two threads (channel_scan.cpp).
  bool split_scan = false;
};

/// Rewinds and reads the whole recording, calling
/// `per_block(interleaved_values, frames, first_frame)` for each block.
/// InputError when the recording ends early (truncated).
template <class PerBlock>
void for_each_block(const BlockStream& stream, AcquirePass pass, PerBlock&& per_block) {
  static constexpr const char* kLabels[kAcquirePasses] = {"acquire: scan   ", "acquire: pulses ",
                                                          "acquire: angles "};
  Reader& reader = stream.reader;
  const auto pass_index = static_cast<std::size_t>(pass);
  const std::uint64_t done_before_frames = pass_index * reader.info().frames;
  stream.progress.set_label(kLabels[pass_index]);
  const auto channels = static_cast<std::size_t>(reader.info().channels);
  std::uint64_t first = 0;
  if (stream.read_ahead) {
    BlockReadAhead ahead(reader, stream.block_frames);
    for (;;) {
      const std::span<const double> block = ahead.next();
      const std::size_t got = block.size() / channels;
      if (got == 0) break;
      per_block(block, got, first);
      first += got;
      stream.progress.update(done_before_frames + first);
    }
  } else {
    std::vector<double> block(stream.block_frames * channels);
    reader.rewind();
    for (;;) {
      const std::size_t got = reader.read(block);
      if (got == 0) break;
      per_block(std::span<const double>(block.data(), got * channels), got, first);
      first += got;
      stream.progress.update(done_before_frames + first);
    }
  }
  if (first != reader.info().frames)
    throw InputError(reader.info().file.string() + ": the recording ended at frame " + std::to_string(first) +
                     " but announced " + std::to_string(reader.info().frames) + " (truncated); copy it again");
}

}  // namespace fourbar
