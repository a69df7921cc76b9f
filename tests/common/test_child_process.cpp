// run_in_child_process: the child's result arrives byte for byte (binary,
// larger than a pipe's buffer); a crash, an exit status, a hang and a result
// cut short are failures in words; forks from several threads at once each
// get their own child's result.

#include <gtest/gtest.h>

#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <random>
#include <thread>

#include "common/child_process.hpp"

namespace fourbar {
namespace {

using std::chrono::milliseconds;

TEST(ChildProcess, ResultArrivesByteForByte) {
  std::mt19937 rng(17);
  std::string big(3'000'000, '\0');  // far more than a pipe holds: the parent reads while the child writes
  for (char& c : big) c = static_cast<char>(rng());
  const ChildResult r = run_in_child_process([&] { return big; }, milliseconds(60'000));
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_TRUE(r.bytes == big);
  const ChildResult empty = run_in_child_process([] { return std::string(); }, milliseconds(60'000));
  ASSERT_TRUE(empty.ok) << empty.failure;
  EXPECT_EQ(empty.bytes, "");
}

TEST(ChildProcess, TheChildsMemoryIsItsOwn) {
  int value = 1;
  const ChildResult r = run_in_child_process([&] {
    value = 2;
    return std::to_string(value);
  }, milliseconds(60'000));
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.bytes, "2");
  EXPECT_EQ(value, 1);
}

TEST(ChildProcess, CrashExitHangAndShortResultAreFailures) {
  const ChildResult crash = run_in_child_process([]() -> std::string { std::raise(SIGSEGV); return "x"; },
                                                 milliseconds(60'000));
  EXPECT_FALSE(crash.ok);
  EXPECT_EQ(crash.failure, "killed by signal 11 (Segmentation fault)");
  const ChildResult abort = run_in_child_process([]() -> std::string { std::abort(); }, milliseconds(60'000));
  EXPECT_EQ(abort.failure, "killed by signal 6 (Aborted)");
  const ChildResult status = run_in_child_process([]() -> std::string { ::_exit(7); }, milliseconds(60'000));
  EXPECT_EQ(status.failure, "ended with exit status 7");
  const ChildResult threw = run_in_child_process([]() -> std::string { throw std::runtime_error("x"); },
                                                 milliseconds(60'000));
  EXPECT_EQ(threw.failure, "ended with exit status 3");
  const ChildResult hang = run_in_child_process([]() -> std::string { for (;;) ::pause(); }, milliseconds(200));
  EXPECT_FALSE(hang.ok);
  EXPECT_EQ(hang.failure, "did not finish within 200 ms (stopped)");
  // A child that writes part of a result and ends as if all were well.
  const ChildResult short_result = run_in_child_process([]() -> std::string { ::_exit(0); }, milliseconds(60'000));
  EXPECT_EQ(short_result.failure, "sent no result (0 bytes)");
}

TEST(ChildProcess, ThreadsForkingAtOnceGetTheirOwnResults) {
#if defined(__SANITIZE_ADDRESS__)
  // g++ 12's AddressSanitizer allocator is not locked around fork(): a child
  // forked while another thread allocates can wait forever on the copied
  // allocator lock (seen in CI: 3 of 20 forks hung until the 60 s limit).
  // glibc's malloc takes its locks around fork(), so the normal build runs
  // this test; the sanitized build runs the single-threaded ones above.
  GTEST_SKIP() << "fork() from several threads deadlocks in the AddressSanitizer allocator; run in the normal build";
#endif
  constexpr int kThreads = 4, kRuns = 5;
  std::vector<std::thread> threads;
  std::vector<int> good(kThreads, 0);
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([t, &good] {
      for (int i = 0; i < kRuns; ++i) {
        const std::string want = std::string(100'000 + 1000 * t + i, static_cast<char>('a' + t));
        const ChildResult r = run_in_child_process([&] { return want; }, milliseconds(60'000));
        good[static_cast<std::size_t>(t)] += r.ok && r.bytes == want;
      }
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(good[static_cast<std::size_t>(t)], kRuns) << "thread " << t;
}

}  // namespace
}  // namespace fourbar
