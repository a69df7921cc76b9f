#pragma once
// Work that may crash or hang (a library reading a damaged file) run in a
// child process, so that whatever goes wrong there cannot touch this
// process's memory: fork() without exec, the child runs `work` and sends
// the bytes it returns back through a pipe, then ends with _exit (no atexit
// handlers, no destructors of the parent's objects). The parent waits at
// most `limit`; a child killed by a signal, ending with a non-zero status,
// running past the limit (then killed) or sending a result cut short is a
// failure described in words, never an exception.
//
// Fork safety: the child holds only the calling thread. glibc makes malloc,
// stdio's list of files and the dynamic loader's lock usable in a forked
// child of a threaded process; any other lock another thread held at the
// fork stays held in the child, so `work` must not need such a lock — at
// worst it waits until the limit and the run is reported as not finished.
// The forks of one process are serialised with the pipe's creation, so no
// child inherits the write end of another child's pipe (which would delay
// that parent's end of data). In the child, SIGINT/SIGTERM/SIGHUP and the
// crash signals get their default actions back and a sanitizer's death
// callback is cleared: the parent's interrupt cleanup and a fuzzer's crash
// handler (which would record the child's crash as the parent's) stay in
// the parent.

#include <chrono>
#include <functional>
#include <string>

namespace fourbar {

struct ChildResult {
  bool ok = false;
  std::string bytes;    ///< what `work` returned, when ok
  std::string failure;  ///< otherwise how the child ended, e.g. "killed by signal 11 (Segmentation fault)"
};

/// Runs `work` in a forked child and returns what it returned. `work` must
/// not throw (an exception ends the child with status 3, a failure).
/// Throws RunError only when no child can be started (fork or pipe fails).
ChildResult run_in_child_process(const std::function<std::string()>& work, std::chrono::milliseconds limit);

}  // namespace fourbar
