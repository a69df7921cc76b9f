#pragma once
// A one-line progress bar on stderr, shown only when stderr is a terminal
// (so logs, pipes and tests see nothing), redrawn at most ten times a second:
// the share done, the time elapsed and an estimate of the time left
// (elapsed × remaining / done, once something is done).

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
  /// Whether the bar is drawn (enabled and stderr a terminal, not finished).
  bool active() const { return active_; }

 private:
  std::string label_;
  std::uint64_t total_;
  bool active_;
  std::chrono::steady_clock::time_point start_, last_{};
};

/// "label [#####     ]  50%  0:12 elapsed, ~0:12 left" (no estimate before
/// anything is done; h:mm:ss past an hour).
std::string progress_line(const std::string& label, std::uint64_t done, std::uint64_t total, double elapsed_s);

/// 0:07, 12:34, 1:02:03.
std::string clock_text(double seconds);

}  // namespace fourbar
