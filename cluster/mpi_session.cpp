#include "cluster/mpi_session.hpp"

#include <cstdlib>

#if FOURBAR_HAVE_MPI
#include <mpi.h>
#endif

namespace fourbar {

bool launched_by_mpi() {
  // Open MPI's mpirun, PMIx launchers (srun --mpi=pmix, prterun), MPICH/Hydra (PMI).
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(var) != nullptr) return true;
  return false;
}

MpiSession::MpiSession() {
#if FOURBAR_HAVE_MPI
  if (!launched_by_mpi()) return;
  int provided = 0;
  // Only the main thread calls MPI; the rank's compute thread does not.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
}

MpiSession::~MpiSession() {
#if FOURBAR_HAVE_MPI
  if (initialised_) MPI_Finalize();
#endif
}

const MpiSession& MpiSession::get() {
  static MpiSession session;
  return session;
}

std::string MpiSession::describe() const {
  if (!initialised_) return "no MPI";
  return std::to_string(size_) + (size_ == 1 ? " MPI rank" : " MPI ranks");
}

bool MpiSession::same_on_every_rank(const std::string& text) const {
#if FOURBAR_HAVE_MPI
  if (!distributed()) return true;
  unsigned long long length = text.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  std::string leaders = leader() ? text : std::string(length, '\0');
  MPI_Bcast(leaders.data(), static_cast<int>(length), MPI_BYTE, 0, MPI_COMM_WORLD);
  int same = leaders == text ? 1 : 0, all = 0;
  MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
#else
  (void)text;
  return true;
#endif
}

void MpiSession::abort_all(int exit_code) {
#if FOURBAR_HAVE_MPI
  int up = 0, down = 0;
  MPI_Initialized(&up);
  MPI_Finalized(&down);
  int size = 1;
  if (up && !down) MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1) MPI_Abort(MPI_COMM_WORLD, exit_code);
#else
  (void)exit_code;
#endif
}

}  // namespace fourbar
