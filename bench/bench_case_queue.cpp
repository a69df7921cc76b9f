// The case queue's own cost per case (what a rank spends not computing:
// asking for a case, waiting for the answer, sending the result back), with
// cases that sleep for a fixed time and 16-byte results (a sweep point's are
// ~150 bytes). Run it alone for threads, or under `mpirun -np N` for ranks:
//   ./build/bench/bench_case_queue [CASES] [CASE_US]
//   mpirun --oversubscribe -np 3 ./build/bench/bench_case_queue [CASES] [CASE_US]
// Overhead per case = (wall time × workers − time spent in cases) / cases.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "cluster/case_queue.hpp"
#include "cluster/mpi_session.hpp"

#if FOURBAR_HAVE_MPI
#include <mpi.h>
#endif

int main(int argc, char** argv) {
  using namespace fourbar;
  using clock = std::chrono::steady_clock;
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 2000;
  const int case_us = argc > 2 ? std::atoi(argv[2]) : 1000;
  std::vector<std::size_t> cases(n);
  std::iota(cases.begin(), cases.end(), 0);
  const MpiSession& mpi = MpiSession::get();
  std::atomic<double> busy_s{0};
  std::size_t received = 0;
  const auto t0 = clock::now();
  run_case_queue(
      cases, 2,
      [&](std::size_t i) {
        const auto a = clock::now();
        std::this_thread::sleep_for(std::chrono::microseconds(case_us));
        busy_s = busy_s + std::chrono::duration<double>(clock::now() - a).count();
        return std::string(16, static_cast<char>(i));
      },
      [&](std::size_t, std::string&& r) { received += r.size() == 16; });
  const double wall = std::chrono::duration<double>(clock::now() - t0).count();
  double busy = busy_s;
#if FOURBAR_HAVE_MPI
  if (mpi.distributed()) {
    double total = 0;
    MPI_Reduce(&busy, &total, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    busy = total;
  }
#endif
  const int workers = mpi.distributed() ? mpi.size() : 2;
  if (mpi.leader())
    std::printf("%zu cases of %d us on %s (%d workers): wall %.3f s, overhead %.1f us per case\n", n, case_us,
                mpi.describe().c_str(), workers, wall, 1e6 * (wall * workers - busy) / double(n));
  return received == n || !mpi.leader() ? 0 : 1;
}
