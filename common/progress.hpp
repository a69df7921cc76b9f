#pragma once
// A one-line progress bar on stderr, shown only when stderr is a terminal
// (so logs, pipes and tests see nothing), redrawn at most ten times a second.

#include <chrono>
#include <cstdint>
#include <string>

namespace fourbar {

class Progress {
 public:
  /// `enabled` false (or stderr not a terminal) makes every call a no-op.
  Progress(std::string label, std::uint64_t total, bool enabled = true);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void set_label(std::string label);
  void update(std::uint64_t done);
  /// Erases the bar.
  void finish();

 private:
  std::string label_;
  std::uint64_t total_;
  bool active_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace fourbar
