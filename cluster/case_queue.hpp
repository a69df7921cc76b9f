#pragma once
// A dynamic work queue of independent cases (sweep grid points, fit
// evaluations): each case computed exactly once, by whichever worker is free
// next, so cases that differ 10× in cost (chaotic clearance motion) still
// keep every core busy.
//
// Without MPI the workers are threads of this process. Under an MPI launcher
// with more than one rank (cluster/mpi_session.hpp) rank 0 hands out one case
// at a time to the ranks that ask and computes on a thread of its own; every
// other rank computes one case at a time (start one rank per core).
// Results travel as bytes in the caller's own encoding, so a result read on
// rank 0 is bit for bit the one computed on any rank.

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace fourbar {

/// Computes case `index`; returns its result as bytes. Must not throw: a case
/// that fails encodes its failure in the result (the other cases go on).
using CaseCompute = std::function<std::string(std::size_t index)>;
/// Receives a finished case on rank 0, one call at a time, in the order the
/// cases finish (not the order of `cases`).
using CaseDone = std::function<void(std::size_t index, std::string&& result)>;

struct CaseQueueStats {
  std::size_t cases = 0;          ///< cases handed out in this run
  std::size_t computed_here = 0;  ///< of these, computed by this process
  int ranks = 1;                  ///< MPI ranks that took part (1 without MPI)
  unsigned threads = 1;           ///< compute threads per rank
};

/// Computes every case of `cases` once and hands each result to `done` on
/// rank 0 (other ranks never call `done`). Returns on every rank when all
/// cases are done. `threads` applies without MPI (at least 1); under MPI each
/// rank computes one case at a time.
CaseQueueStats run_case_queue(std::span<const std::size_t> cases, unsigned threads, const CaseCompute& compute,
                              const CaseDone& done);

/// Computes the case a description gives (a case only rank 0 knows, such as
/// a fit's next evaluations, chosen as the search goes); returns its result as
/// bytes. Must not throw for a case that fails (encode the failure); an
/// exception is a fault of the run (every rank is stopped).
using DescribedCaseCompute = std::function<std::string(const std::string& description)>;

/// Batches of described cases: rank 0 calls run_described_cases for each
/// batch as its work needs them and end_described_cases once at the end;
/// every other rank calls serve_described_cases, which computes cases of
/// every batch and returns after end_described_cases. Each case travels with
/// its description, so the other ranks need to know nothing of the search.
/// Without a distributed session the batch runs on `threads` threads (the
/// other two calls return at once).
CaseQueueStats run_described_cases(const std::vector<std::string>& descriptions, unsigned threads,
                                   const DescribedCaseCompute& compute, const CaseDone& done);
void serve_described_cases(const DescribedCaseCompute& compute);
void end_described_cases();

}  // namespace fourbar
