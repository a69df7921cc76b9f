#pragma once
// Reading a recording's blocks on a thread of their own, a few blocks ahead
// of the one that uses them: the file read and the sample decoding
// (libsndfile, libmatio, CSV text) overlap the work on the previous blocks.
// The blocks come out in the file's order with the same values as a plain
// read, so nothing computed from them changes. A read that fails is
// reported (rethrown) when its block is asked for, after every block before
// it has been used — as without the thread.

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "acquire/reader.hpp"

namespace fourbar {

class BlockReadAhead {
 public:
  /// Rewinds `reader` and starts reading blocks of `block_frames`. The reader
  /// belongs to this object's thread until it is destroyed.
  BlockReadAhead(Reader& reader, std::size_t block_frames);
  ~BlockReadAhead();  ///< stops the reading (even half way) and joins
  BlockReadAhead(const BlockReadAhead&) = delete;
  BlockReadAhead& operator=(const BlockReadAhead&) = delete;

  /// The next block's interleaved values (empty at the end of the recording,
  /// and after it); valid until the next call. Rethrows what the read of that
  /// block threw (do not call again after that).
  std::span<const double> next();

 private:
  static constexpr std::size_t kSlots = 4;  ///< blocks in flight: the one in use and three read ahead
  struct Slot {
    std::vector<double> values;
    std::size_t count = 0;  ///< values read (0: the end)
    std::exception_ptr error;
  };
  void read_all();

  Reader& reader_;
  std::size_t channels_;
  std::vector<Slot> slots_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::uint64_t filled_ = 0, used_ = 0;  ///< slots filled by the reader, handed out (the one in use counts)
  bool stop_ = false, in_use_ = false;
  bool at_end_ = false;  ///< the consumer's: the end was handed out
  std::thread thread_;
};

}  // namespace fourbar
