#include "acquire/block_read_ahead.hpp"

namespace fourbar {

BlockReadAhead::BlockReadAhead(Reader& reader, std::size_t block_frames)
    : reader_(reader), channels_(static_cast<std::size_t>(reader.info().channels)), slots_(kSlots) {
  for (Slot& s : slots_) s.values.resize(block_frames * channels_);
  reader_.rewind();  // here, so a recording that cannot be rewound fails as without the thread
  thread_ = std::thread([this] { read_all(); });
}

BlockReadAhead::~BlockReadAhead() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void BlockReadAhead::read_all() {
  for (std::uint64_t k = 0;; ++k) {
    Slot* slot = nullptr;
    {
      std::unique_lock lock(mutex_);
      // A slot is free once the block read kSlots before it has been used and released.
      changed_.wait(lock, [&] { return stop_ || k < used_ - (in_use_ ? 1 : 0) + kSlots; });
      if (stop_) return;
      slot = &slots_[k % kSlots];
    }
    bool last = false;
    try {
      slot->count = reader_.read(slot->values) * channels_;
      slot->error = nullptr;
      last = slot->count == 0;
    } catch (...) {
      slot->count = 0;
      slot->error = std::current_exception();
      last = true;
    }
    {
      const std::lock_guard lock(mutex_);
      ++filled_;
    }
    changed_.notify_all();
    if (last) return;
  }
}

std::span<const double> BlockReadAhead::next() {
  if (at_end_) return {};  // the reading thread is done: asked again after the end
  std::unique_lock lock(mutex_);
  in_use_ = false;  // the previous block is done with
  changed_.notify_all();
  changed_.wait(lock, [&] { return filled_ > used_; });
  Slot& slot = slots_[used_ % kSlots];
  ++used_;
  in_use_ = true;
  if (slot.error) std::rethrow_exception(slot.error);
  at_end_ = slot.count == 0;
  return {slot.values.data(), slot.count};
}

}  // namespace fourbar
