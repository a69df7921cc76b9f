#pragma once
// The MPI session of this process, when it was started by an MPI launcher
// (mpirun, mpiexec, srun): rank and size of MPI_COMM_WORLD. Started any other
// way, or built without MPI, the process is a session of one rank and MPI is
// never initialised, so the same binary runs on a laptop and on a cluster.

#include <string>

namespace fourbar {

class MpiSession {
 public:
  /// The process's session: MPI is initialised on the first call when a
  /// launcher started the process (and finalised at exit).
  static const MpiSession& get();

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// More than one rank: work is spread over the ranks.
  bool distributed() const { return size_ > 1; }
  /// Rank 0 (also the only rank without MPI): the one that reads back,
  /// writes outputs and talks to the user.
  bool leader() const { return rank_ == 0; }
  /// "3 MPI ranks" or "no MPI" (for messages).
  std::string describe() const;
  /// Collective (every rank calls it): whether `text` is the same on every
  /// rank as on rank 0 — inputs each rank derived on its own, checked before
  /// the ranks rely on them being equal. Always true without a distributed session.
  bool same_on_every_rank(const std::string& text) const;

  /// Ends every rank at once (MPI_Abort) when one fails while the others
  /// may be waiting for it; a no-op without a distributed session.
  static void abort_all(int exit_code);

  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  MpiSession();
  int rank_ = 0, size_ = 1;
  bool initialised_ = false;
};

/// Whether the environment says an MPI launcher started this process.
bool launched_by_mpi();

}  // namespace fourbar
