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
