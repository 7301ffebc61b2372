#include "cluster.h"

#include <cstdlib>
#include <mutex>

namespace fairsurf::detail {

bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

bool start_mpi(int* argc, char*** argv) {
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  int running = 0;
  MPI_Initialized(&running);
  if (running) return false;
  // Started without mpirun (a plain `fairsurf smooth`, Python, a test): OpenMPI would fork a daemon
  // for this one-process job, which isolated mode skips (0.3 s instead of 0.7 s here).
  if (!launched_by_mpirun()) setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &provided);
  return true;
}

Cluster& cluster() {
  static Cluster state;
  return state;
}

void broadcast(ServeCommand& command) {
  MPI_Bcast(&command, sizeof(ServeCommand) / sizeof(int), MPI_INT, 0, cluster().control);
}

}  // namespace fairsurf::detail
