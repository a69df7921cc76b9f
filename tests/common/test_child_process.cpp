// run_program (common/child_process.hpp), with tests/common/child_probe.cpp
// as the program: its result arrives byte for byte (binary, larger than a
// pipe's buffer); a crash, an exit status, a hang and a result cut short are
// failures in words; a program that cannot be started is a RunError naming
// it; several threads starting programs at once each get their own result.

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <thread>
#include <vector>

#include "common/child_process.hpp"
#include "common/error.hpp"

namespace fourbar {
namespace {

using std::chrono::milliseconds;

std::string probe_bytes(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::string bytes(n, '\0');
  for (char& c : bytes) c = static_cast<char>(rng());
  return bytes;
}

ChildResult probe(std::vector<std::string> args, milliseconds limit = milliseconds(60'000)) {
  args.insert(args.begin(), CHILD_PROBE);
  return run_program(args, limit);
}

TEST(ChildProcess, ResultArrivesByteForByte) {
  // Far more than a pipe holds: the parent reads while the child writes.
  const ChildResult r = probe({"echo", "3000000", "17"});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_TRUE(r.bytes == probe_bytes(3'000'000, 17));
  const ChildResult empty = probe({"echo", "0", "1"});
  ASSERT_TRUE(empty.ok) << empty.failure;
  EXPECT_EQ(empty.bytes, "");
}

TEST(ChildProcess, CrashExitHangAndShortResultAreFailures) {
  const ChildResult crash = probe({"segv"});
  EXPECT_FALSE(crash.ok);
#if defined(__SANITIZE_ADDRESS__)
  // The probe's own AddressSanitizer catches the fault, reports it and aborts.
  EXPECT_EQ(crash.failure, "killed by signal 6 (Aborted)");
#else
  EXPECT_EQ(crash.failure, "killed by signal 11 (Segmentation fault)");
#endif
  EXPECT_EQ(probe({"abort"}).failure, "killed by signal 6 (Aborted)");
  EXPECT_EQ(probe({"exit", "7"}).failure, "ended with exit status 7");
  const ChildResult hang = probe({"hang"}, milliseconds(300));
  EXPECT_FALSE(hang.ok);
  EXPECT_EQ(hang.failure, "did not finish within 300 ms (stopped)");
  // Programs that end as if all were well but sent nothing, or part of a result.
  EXPECT_EQ(probe({"none"}).failure, "sent no result (0 bytes)");
  EXPECT_EQ(probe({"partial"}).failure, "sent a result of 3 bytes, announced 10");
}

TEST(ChildProcess, AProgramThatCannotStartIsARunErrorNamingIt) {
  try {
    run_program({"/nonexistent/fourbar-probe"}, milliseconds(1000));
    FAIL() << "no error";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot run /nonexistent/fourbar-probe: No such file or directory"),
              std::string::npos)
        << e.what();
  }
}

// posix_spawn copies nothing of this process and runs no fork handlers, so
// threads may start programs at once (the sanitized build runs this too).
TEST(ChildProcess, ThreadsStartingProgramsAtOnceGetTheirOwnResults) {
  constexpr int kThreads = 4, kRuns = 5;
  std::vector<std::thread> threads;
  std::vector<int> good(kThreads, 0);
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([t, &good] {
      for (int i = 0; i < kRuns; ++i) {
        const std::size_t n = 100'000 + 1000 * static_cast<std::size_t>(t) + static_cast<std::size_t>(i);
        const auto seed = static_cast<unsigned>(10 * t + i);
        const ChildResult r = probe({"echo", std::to_string(n), std::to_string(seed)});
        good[static_cast<std::size_t>(t)] += r.ok && r.bytes == probe_bytes(n, seed);
      }
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(good[static_cast<std::size_t>(t)], kRuns) << "thread " << t;
}

}  // namespace
}  // namespace fourbar
