// fairsurf — the mumps-mpi back end: rank 0's MumpsSolver on MPI_COMM_WORLD, announcing each MUMPS
// job to the ranks that serve the Session (session.cpp), which run the same job on the same instance.
#include <fairsurf/mesh/errors.h>

#include "../linear_solver_backends.h"
#include "../mumps_instance.h"
#include "cluster.h"

#include <string>

namespace fairsurf::detail {

namespace {

// Without a serving Session on the other ranks, the first collective MUMPS call would wait forever.
void check_served(const char* name) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank != 0)
    throw InvalidArgument(std::string("make_linear_solver: ") + name + ": only rank 0 creates solvers; rank " +
                          std::to_string(rank) + " serves them (distributed::Session::serve)");
  if (size > 1 && cluster().control == MPI_COMM_NULL)
    throw InvalidArgument(std::string("make_linear_solver: ") + name + ": the MPI job has " + std::to_string(size) +
                          " ranks but no distributed::Session serves on ranks 1.." + std::to_string(size - 1));
}

}  // namespace

int mumps_self_communicator() {
  start_mpi(nullptr, nullptr);
  return MPI_Comm_c2f(MPI_COMM_SELF);
}

std::unique_ptr<LinearSolver> make_mumps_mpi_solver(const LinearSolverOptions& options) {
  start_mpi(nullptr, nullptr);
  check_served(to_string(options.kind));
  MumpsTeam team{.communicator = MPI_Comm_c2f(MPI_COMM_WORLD)};
  if (cluster().control != MPI_COMM_NULL) {
    const MumpsSettings settings = mumps_settings(options, team.communicator);
    // MUMPS takes ICNTL from the host at each job, so the pass-through controls stay on rank 0.
    const ServeCommand created{
        .instance = cluster().next_instance++, .sym = settings.sym, .ordering = settings.ordering};
    team.announce = [created](int job, int workspace_relaxation) {
      ServeCommand command = created;
      command.job = job;
      command.workspace_relaxation = workspace_relaxation;
      broadcast(command);
    };
  }
  return make_mumps_solver(options, std::move(team));
}

}  // namespace fairsurf::detail
