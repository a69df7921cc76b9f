// The case queue on threads: every case computed exactly once, every result
// handed to `done` exactly once and unchanged, whatever the number of
// threads and however uneven the cases' cost; an output failure in `done`
// stops the queue and reaches the caller. (The MPI path is run end to end by
// tests/cli/test_sweep_command.cpp under mpirun.)
#include "cluster/case_queue.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "cluster/mpi_session.hpp"

namespace fourbar {
namespace {

TEST(CaseQueue, EveryCaseOnceWithItsOwnResult) {
  std::vector<std::size_t> cases(200);
  std::iota(cases.begin(), cases.end(), 1000);
  std::mt19937 gen(7);
  std::vector<int> cost_us(2000);
  for (int& c : cost_us) c = std::uniform_int_distribution<int>(0, 300)(gen);  // uneven, as chaotic cases are
  for (unsigned threads : {1u, 2u, 5u, 64u}) {
    std::vector<std::atomic<int>> computed(2000);
    std::map<std::size_t, std::string> results;
    const CaseQueueStats stats = run_case_queue(
        cases, threads,
        [&](std::size_t i) {
          ++computed[i];
          std::this_thread::sleep_for(std::chrono::microseconds(cost_us[i]));
          return "result of " + std::to_string(i);
        },
        [&](std::size_t i, std::string&& r) { EXPECT_TRUE(results.emplace(i, std::move(r)).second) << i; });
    EXPECT_EQ(stats.cases, cases.size());
    EXPECT_EQ(stats.computed_here, cases.size());
    EXPECT_EQ(stats.ranks, 1);
    ASSERT_EQ(results.size(), cases.size()) << threads << " threads";
    for (std::size_t i : cases) {
      EXPECT_EQ(computed[i].load(), 1) << "case " << i << ", " << threads << " threads";
      EXPECT_EQ(results[i], "result of " + std::to_string(i));
    }
  }
}

TEST(CaseQueue, NoCasesIsNoWork) {
  int calls = 0;
  const auto stats = run_case_queue({}, 4, [&](std::size_t) { return std::string(++calls, 'x'); },
                                    [&](std::size_t, std::string&&) { ++calls; });
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(stats.cases, 0u);
}

TEST(CaseQueue, AFailingOutputStopsTheQueueAndReachesTheCaller) {
  std::vector<std::size_t> cases(100);
  std::iota(cases.begin(), cases.end(), 0);
  std::atomic<int> computed{0};
  EXPECT_THROW(run_case_queue(
                   cases, 3,
                   [&](std::size_t i) {
                     ++computed;
                     std::this_thread::sleep_for(std::chrono::microseconds(200));
                     return std::to_string(i);
                   },
                   [&](std::size_t i, std::string&&) {
                     if (i == 10) throw std::runtime_error("disk full");
                   }),
               std::runtime_error);
  EXPECT_LT(computed.load(), 100) << "the queue stops taking cases once an output failed";
}

TEST(MpiSession, WithoutALauncherThereIsOneRankAndNoMpi) {
  if (launched_by_mpi()) GTEST_SKIP() << "this test process itself runs under an MPI launcher";
  const MpiSession& s = MpiSession::get();
  EXPECT_EQ(s.size(), 1);
  EXPECT_TRUE(s.leader());
  EXPECT_FALSE(s.distributed());
  EXPECT_EQ(s.describe(), "no MPI");
}

}  // namespace
}  // namespace fourbar
