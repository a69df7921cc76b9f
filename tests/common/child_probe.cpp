// A program for tests/common/test_child_process.cpp to run through
// run_program: it sends a result, crashes, exits, hangs or sends a result cut
// short, as its first argument says.
//   child_probe echo N SEED   N bytes of std::mt19937(SEED), framed
//   child_probe segv | abort | hang | none | partial | exit STATUS

#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "common/child_process.hpp"

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  const std::string mode = argv[1];
  if (mode == "echo" && argc == 4) {
    std::mt19937 rng(static_cast<unsigned>(std::atoi(argv[3])));
    std::string bytes(static_cast<std::size_t>(std::atol(argv[2])), '\0');
    for (char& c : bytes) c = static_cast<char>(rng());
    return fourbar::write_framed_result(STDOUT_FILENO, bytes) ? 0 : 4;
  }
  if (mode == "segv") std::raise(SIGSEGV);
  if (mode == "abort") std::abort();
  if (mode == "hang")
    for (;;) ::pause();
  if (mode == "none") return 0;
  if (mode == "partial") {
    const std::uint64_t n = 10;
    char head[sizeof n];
    std::memcpy(head, &n, sizeof n);
    return ::write(STDOUT_FILENO, head, sizeof head) == sizeof head && ::write(STDOUT_FILENO, "abc", 3) == 3 ? 0 : 4;
  }
  if (mode == "exit" && argc == 3) return std::atoi(argv[2]);
  return 2;
}
