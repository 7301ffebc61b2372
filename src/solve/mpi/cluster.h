// fairsurf — private, MPI builds: the state this process shares with the other ranks of its job,
// and the messages with which rank 0 drives the ranks that serve a distributed::Session.
#pragma once

#include <mpi.h>

namespace fairsurf::detail {

/// One message from rank 0 to the serving ranks: a MUMPS job on one solver instance, or the end.
struct ServeCommand {
  int instance = 0;              ///< which solver: numbered by rank 0 in creation order
  int job = 0;                   ///< MUMPS job (−1, 1, 2, 3, −2), or kFinishJob
  int sym = 0;                   ///< job −1: MumpsSettings::sym
  int ordering = 0;              ///< job −1: MumpsSettings::ordering
  int workspace_relaxation = 0;  ///< job 2: ICNTL(14)
  int exit_code = 0;             ///< kFinishJob: what serve() returns
};
constexpr int kFinishJob = 1000;

/// Whether an MPI launcher (OpenMPI's mpirun, PMIx or Hydra launchers) started this process.
bool launched_by_mpirun();

/// Starts MPI (MPI_THREAD_MULTIPLE: solvers may live on several threads) unless it runs already.
/// Returns whether this call started it.
bool start_mpi(int* argc, char*** argv);

struct Cluster {
  MPI_Comm control = MPI_COMM_NULL;  ///< rank 0 → servers; set while a Session with ranks runs
  int next_instance = 0;
};
Cluster& cluster();

/// Rank 0 sends `command` to every serving rank; on those, receives it into `command`.
void broadcast(ServeCommand& command);

}  // namespace fairsurf::detail
