#pragma once
// Work that may crash or hang (a library reading a damaged file) run as a
// program of its own, so that whatever goes wrong there cannot touch this
// process's memory: posix_spawn (no copy of this process, no fork handlers,
// safe from any thread), the child's signals at their defaults, stdin from
// /dev/null, stdout a pipe to this process. The program writes its result
// framed (write_framed_result: an 8-byte length, then the bytes) and exits
// 0. The parent waits at most `limit`; a child killed by a signal, ending
// with a non-zero status, running past the limit (then killed) or sending a
// result cut short is a failure described in words, never an exception.

#include <chrono>
#include <string>
#include <string_view>
#include <vector>

namespace fourbar {

struct ChildResult {
  bool ok = false;
  std::string bytes;    ///< the program's framed result, when ok
  std::string failure;  ///< otherwise how the child ended, e.g. "killed by signal 11 (Segmentation fault)"
};

/// Runs the program at `argv[0]` (a path, not searched in PATH) with `argv`
/// and returns the result it wrote. Throws RunError only when the program
/// cannot be started (naming it and why: missing, not executable, no pipe).
ChildResult run_program(const std::vector<std::string>& argv, std::chrono::milliseconds limit);

/// The program's side: `bytes` with its length before it (host byte order)
/// to `fd`. False when the write fails.
bool write_framed_result(int fd, std::string_view bytes);

}  // namespace fourbar
