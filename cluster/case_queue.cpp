#include "cluster/case_queue.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <exception>
#include <iostream>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "cluster/mpi_session.hpp"

#if FOURBAR_HAVE_MPI
#include <mpi.h>
#endif

namespace fourbar {

namespace {

/// The cases not handed out yet, shared by every taker of this process.
class CaseCursor {
 public:
  explicit CaseCursor(std::span<const std::size_t> cases) : cases_(cases) {}
  std::optional<std::size_t> take() {
    const std::size_t k = next_.fetch_add(1);
    if (k >= cases_.size()) return std::nullopt;
    return cases_[k];
  }

 private:
  std::span<const std::size_t> cases_;
  std::atomic<std::size_t> next_{0};
};

CaseQueueStats run_on_threads(std::span<const std::size_t> cases, unsigned threads, const CaseCompute& compute,
                              const CaseDone& done) {
  CaseCursor cursor(cases);
  std::mutex done_mutex;
  std::exception_ptr failure;
  auto worker = [&] {
    while (const auto i = cursor.take()) {
      try {
        std::string r = compute(*i);
        const std::lock_guard lock(done_mutex);
        if (!failure) done(*i, std::move(r));
      } catch (...) {  // `done` failed (an output that cannot be written): stop taking cases
        const std::lock_guard lock(done_mutex);
        if (!failure) failure = std::current_exception();
        while (cursor.take()) {
        }
      }
    }
  };
  threads = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max<std::size_t>(1, cases.size()))));
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
  }
  if (failure) std::rethrow_exception(failure);
  return {cases.size(), cases.size(), 1, threads};
}

#if FOURBAR_HAVE_MPI

enum Tag : int { kRequest = 1, kWork = 2, kStop = 3, kResult = 4 };

/// A case as the worker ranks get it: its index, and its description when it has one.
using WorkerCompute = std::function<std::string(std::size_t index, const std::string& description)>;

/// Every rank but 0: ask, compute, send the result back (which asks again).
CaseQueueStats run_worker_rank(const MpiSession& mpi, const WorkerCompute& compute) {
  CaseQueueStats stats{0, 0, mpi.size(), 1};
  MPI_Send(nullptr, 0, MPI_BYTE, 0, kRequest, MPI_COMM_WORLD);
  std::string message, work;
  for (;;) {
    MPI_Status status;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    work.resize(static_cast<std::size_t>(bytes));
    MPI_Recv(work.data(), bytes, MPI_BYTE, 0, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (status.MPI_TAG == kStop) break;
    std::uint64_t index = 0;
    std::memcpy(&index, work.data(), sizeof index);
    std::string result = compute(static_cast<std::size_t>(index), work.substr(sizeof index));
    message.resize(sizeof index + result.size());
    std::memcpy(message.data(), &index, sizeof index);
    std::memcpy(message.data() + sizeof index, result.data(), result.size());
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_BYTE, 0, kResult, MPI_COMM_WORLD);
    ++stats.computed_here;
  }
  return stats;
}

/// Rank 0: serves the other ranks from the main thread (the only one that
/// calls MPI) while a thread of its own computes cases too.
CaseQueueStats run_leader_rank(const MpiSession& mpi, std::span<const std::size_t> cases, const CaseCompute& compute,
                               const CaseDone& done, const std::vector<std::string>* descriptions = nullptr) {
  CaseCursor cursor(cases);
  std::mutex local_mutex;
  std::deque<std::pair<std::size_t, std::string>> local_results;
  std::atomic<bool> local_finished{false};
  std::size_t computed_here = 0;
  using Clock = std::chrono::steady_clock;
  auto ns_now = [] { return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count(); };
  // The compute thread's cases so far: their time, and when the running one began.
  std::atomic<std::int64_t> local_case_ns{0}, local_case_began_ns{ns_now()};
  std::jthread local([&] {
    while (const auto i = cursor.take()) {
      local_case_began_ns = ns_now();
      std::string r = compute(*i);
      local_case_ns += ns_now() - local_case_began_ns.load();
      const std::lock_guard lock(local_mutex);
      local_results.emplace_back(*i, std::move(r));
      ++computed_here;
    }
    local_finished = true;
  });
  // Idle, the main thread naps between looks, from kShortestNap doubling up
  // to a hundredth of the mean case (at most kLongestNap): a rank waits for
  // its next case at most ~1 % of a case, and while long cases run the server
  // wakes 20 times less often than with the shortest nap (each wake-up takes
  // the compute thread's core for a moment: mpirun binds a rank to one core).
  constexpr auto kShortestNap = std::chrono::microseconds(50), kLongestNap = std::chrono::microseconds(1000);
  auto nap = kShortestNap;
  auto longest_nap = [&] {  // the mean case, the running one counted with its time so far
    std::int64_t done_here = 0;
    {
      const std::lock_guard lock(local_mutex);
      done_here = static_cast<std::int64_t>(computed_here);
    }
    const std::int64_t mean_ns = (local_case_ns.load() + (ns_now() - local_case_began_ns.load())) / (done_here + 1);
    return std::clamp(std::chrono::microseconds(mean_ns / 100000), kShortestNap, kLongestNap);
  };

  int serving = mpi.size() - 1;
  std::vector<char> buffer;
  std::string work;
  auto drain_local = [&] {
    std::deque<std::pair<std::size_t, std::string>> ready;
    {
      const std::lock_guard lock(local_mutex);
      ready.swap(local_results);
    }
    for (auto& [i, r] : ready) done(i, std::move(r));
    return !ready.empty();
  };
  try {
    for (;;) {
      bool progressed = drain_local();
      int waiting = 0;
      MPI_Status status;
      if (serving > 0) MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
      if (waiting) {
        int bytes = 0;
        MPI_Get_count(&status, MPI_BYTE, &bytes);
        buffer.resize(static_cast<std::size_t>(bytes));
        MPI_Recv(buffer.data(), bytes, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (status.MPI_TAG == kResult) {
          std::uint64_t index = 0;
          std::memcpy(&index, buffer.data(), sizeof index);
          done(static_cast<std::size_t>(index),
               std::string(buffer.data() + sizeof index, buffer.size() - sizeof index));
        }
        if (const auto next = cursor.take()) {
          const std::uint64_t index = *next;
          work.assign(reinterpret_cast<const char*>(&index), sizeof index);
          if (descriptions) work += (*descriptions)[*next];
          MPI_Send(work.data(), static_cast<int>(work.size()), MPI_BYTE, status.MPI_SOURCE, kWork, MPI_COMM_WORLD);
        } else {
          MPI_Send(nullptr, 0, MPI_BYTE, status.MPI_SOURCE, kStop, MPI_COMM_WORLD);
          --serving;
        }
        progressed = true;
      }
      if (serving == 0 && local_finished) {
        local.join();
        drain_local();
        break;
      }
      if (progressed) {
        nap = kShortestNap;
      } else {
        std::this_thread::sleep_for(nap);
        nap = std::min(2 * nap, longest_nap());
      }
    }
  } catch (const std::exception& e) {
    // `done` failed (an output that cannot be written); the other ranks and
    // the compute thread would wait for ever.
    std::cerr << "fourbar: rank 0: " << e.what() << "; stopping every rank\n";
    MpiSession::abort_all(1);
    throw;
  }
  return {cases.size(), computed_here, mpi.size(), 1};
}

#endif

}  // namespace

CaseQueueStats run_case_queue(std::span<const std::size_t> cases, unsigned threads, const CaseCompute& compute,
                              const CaseDone& done) {
#if FOURBAR_HAVE_MPI
  const MpiSession& mpi = MpiSession::get();
  if (mpi.distributed()) {
    return mpi.leader() ? run_leader_rank(mpi, cases, compute, done)
                        : run_worker_rank(mpi, [&](std::size_t i, const std::string&) { return compute(i); });
  }
#endif
  return run_on_threads(cases, threads, compute, done);
}

namespace {
#if FOURBAR_HAVE_MPI
/// Rank 0 tells the others whether another batch of described cases follows.
void announce_batch(bool another) {
  int go = another ? 1 : 0;
  MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
}
#endif
}  // namespace

CaseQueueStats run_described_cases(const std::vector<std::string>& descriptions, unsigned threads,
                                   const DescribedCaseCompute& compute, const CaseDone& done) {
  std::vector<std::size_t> cases(descriptions.size());
  for (std::size_t i = 0; i < cases.size(); ++i) cases[i] = i;
  const CaseCompute by_index = [&](std::size_t i) { return compute(descriptions[i]); };
#if FOURBAR_HAVE_MPI
  const MpiSession& mpi = MpiSession::get();
  if (mpi.distributed()) {
    if (!mpi.leader()) throw std::logic_error("run_described_cases on a rank other than 0 (serve_described_cases there)");
    announce_batch(true);
    return run_leader_rank(mpi, cases, by_index, done, &descriptions);
  }
#endif
  return run_on_threads(cases, threads, by_index, done);
}

void serve_described_cases(const DescribedCaseCompute& compute) {
#if FOURBAR_HAVE_MPI
  const MpiSession& mpi = MpiSession::get();
  if (!mpi.distributed() || mpi.leader()) return;
  for (;;) {
    int go = 0;
    MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (!go) return;
    run_worker_rank(mpi, [&](std::size_t, const std::string& description) { return compute(description); });
  }
#else
  (void)compute;
#endif
}

void end_described_cases() {
#if FOURBAR_HAVE_MPI
  const MpiSession& mpi = MpiSession::get();
  if (mpi.distributed() && mpi.leader()) announce_batch(false);
#endif
}

}  // namespace fourbar
