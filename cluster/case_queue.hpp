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

}  // namespace fourbar
