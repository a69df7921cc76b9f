#include "common/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <mutex>

#include "common/error.hpp"

// Set by AddressSanitizer and friends (libFuzzer registers its crash report
// here); absent in a normal build.
extern "C" void __sanitizer_set_death_callback(void (*)(void)) __attribute__((weak));

namespace fourbar {

namespace {

std::mutex g_fork_mutex;  // pipe creation, fork and closing the parent's write end

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

[[noreturn]] void run_child(int fd, const std::function<std::string()>& work) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGSEGV, SIGBUS, SIGABRT, SIGILL, SIGFPE, SIGPIPE})
    std::signal(sig, SIG_DFL);
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
  std::string out;
  try {
    out = work();
  } catch (...) {
    ::_exit(3);
  }
  const std::uint64_t n = out.size();
  char head[sizeof n];
  std::memcpy(head, &n, sizeof n);
  if (!write_all(fd, head, sizeof head) || !write_all(fd, out.data(), out.size())) ::_exit(4);
  ::_exit(0);
}

std::string seconds_text(std::chrono::milliseconds limit) {
  const auto ms = limit.count();
  return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

}  // namespace

ChildResult run_in_child_process(const std::function<std::string()>& work, std::chrono::milliseconds limit) {
  using Clock = std::chrono::steady_clock;
  int fds[2];
  pid_t pid = -1;
  {
    const std::lock_guard lock(g_fork_mutex);
    if (::pipe2(fds, O_CLOEXEC) != 0)
      throw RunError(std::string("cannot start a child process: pipe: ") + std::strerror(errno));
    pid = ::fork();
    if (pid == 0) {
      ::close(fds[0]);
      run_child(fds[1], work);
    }
    const int fork_errno = errno;
    ::close(fds[1]);
    if (pid < 0) {
      ::close(fds[0]);
      throw RunError(std::string("cannot start a child process: fork: ") + std::strerror(fork_errno));
    }
  }

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
