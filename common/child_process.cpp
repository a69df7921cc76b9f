#include "common/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace fourbar {

namespace {

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

std::string seconds_text(std::chrono::milliseconds limit) {
  const auto ms = limit.count();
  return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

/// Starts argv[0] with its stdout on `out_fd`: the pid.
pid_t spawn(const std::vector<std::string>& argv, int out_fd, int other_fd) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawnattr_t attr;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_adddup2(&files, out_fd, STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addclose(&files, other_fd);
  posix_spawnattr_init(&attr);
  // The parent's handlers (interrupt cleanup, a fuzzer's crash report) are
  // gone after exec anyway; ignored signals would stay ignored: reset them.
  sigset_t defaults, none;
  sigemptyset(&defaults);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGSEGV, SIGBUS, SIGABRT, SIGILL, SIGFPE, SIGPIPE}) sigaddset(&defaults, sig);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = -1;
  const int err = ::posix_spawn(&pid, args[0], &files, &attr, args.data(), environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&files);
  if (err != 0) throw RunError("cannot run " + argv[0] + ": " + std::strerror(err));
  return pid;
}

}  // namespace

bool write_framed_result(int fd, std::string_view bytes) {
  const std::uint64_t n = bytes.size();
  char head[sizeof n];
  std::memcpy(head, &n, sizeof n);
  return write_all(fd, head, sizeof head) && write_all(fd, bytes.data(), bytes.size());
}

ChildResult run_program(const std::vector<std::string>& argv, std::chrono::milliseconds limit) {
  using Clock = std::chrono::steady_clock;
  if (argv.empty()) throw RunError("run_program: no program");
  int fds[2];
  // O_CLOEXEC: no other child started meanwhile (from another thread)
  // inherits this pipe's write end, which would delay the end of data.
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw RunError(std::string("cannot start a child process: pipe: ") + std::strerror(errno));
  pid_t pid = -1;
  try {
    pid = spawn(argv, fds[1], fds[0]);
  } catch (...) {
    ::close(fds[0]), ::close(fds[1]);
    throw;
  }
  ::close(fds[1]);
  const auto deadline = Clock::now() + limit;
  std::string got;
  bool timed_out = false;
  std::string read_error;
  for (bool eof = false; !eof;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(std::clamp<long long>(left, 1, 1000)));
    if (r < 0 && errno != EINTR) {
      read_error = std::string("poll: ") + std::strerror(errno);
      break;
    }
    if (r <= 0) continue;
    char buf[65536];
    const ssize_t k = ::read(fds[0], buf, sizeof buf);
    if (k < 0 && errno != EINTR && errno != EAGAIN) {
      read_error = std::string("read: ") + std::strerror(errno);
      break;
    }
    if (k == 0) eof = true;
    if (k > 0) got.append(buf, static_cast<std::size_t>(k));
  }
  ::close(fds[0]);

  // The child has closed its end (it ends right after) or must be stopped.
  if (timed_out || !read_error.empty()) ::kill(pid, SIGKILL);
  int status = 0;
  for (bool killed = timed_out || !read_error.empty();;) {
    const pid_t w = ::waitpid(pid, &status, killed ? 0 : WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) return {false, {}, std::string("cannot learn how the child process ended: ") + std::strerror(errno)};
    if (Clock::now() >= deadline) {
      ::kill(pid, SIGKILL);
      killed = timed_out = true;
      continue;
    }
    ::usleep(1000);
  }

  ChildResult res;
  if (timed_out) res.failure = "did not finish within " + seconds_text(limit) + " (stopped)";
  else if (!read_error.empty()) res.failure = "its result could not be read (" + read_error + ")";
  else if (WIFSIGNALED(status))
    res.failure = "killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                  (sigdescr_np(WTERMSIG(status)) ? sigdescr_np(WTERMSIG(status)) : "unknown") + ")";
  else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    res.failure = "ended with exit status " + std::to_string(WEXITSTATUS(status));
  else if (got.size() < sizeof(std::uint64_t))
    res.failure = "sent no result (" + std::to_string(got.size()) + " bytes)";
  else {
    std::uint64_t n = 0;
    std::memcpy(&n, got.data(), sizeof n);
    if (n != got.size() - sizeof n)
      res.failure = "sent a result of " + std::to_string(got.size() - sizeof n) + " bytes, announced " +
                    std::to_string(n);
  }
  if (res.failure.empty()) {
    res.ok = true;
    res.bytes = got.substr(sizeof(std::uint64_t));
  }
  return res;
}

}  // namespace fourbar
