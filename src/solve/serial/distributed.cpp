// fairsurf — the one-process stand-ins of distributed.h for a build without MPI (FAIRSURF_MPI off):
// sequential MUMPS, and a Session of one rank.
#include <fairsurf/mesh/errors.h>
#include <fairsurf/solve/distributed.h>

#include "../linear_solver_backends.h"

#include <cstdlib>

namespace fairsurf {

namespace detail {

int mumps_self_communicator() {
  return -987654;  // MUMPS's code for MPI_COMM_WORLD, a stub in libmpiseq
}

std::unique_ptr<LinearSolver> make_mumps_mpi_solver(const LinearSolverOptions&) {
  throw InvalidArgument(
      "make_linear_solver: mumps-mpi: this fairsurf was built without MPI (configure with "
      "-DFAIRSURF_MPI=ON, with OpenMPI and libmumps-ptscotch-dev installed); use mumps");
}

}  // namespace detail

namespace distributed {

bool built_with_mpi() { return false; }

Session::Session(int&, char**&) {}

Session::~Session() = default;

int Session::serve() { return 0; }

void Session::finish(int) { finished_ = true; }

void Session::abort(int exit_code) { std::exit(exit_code); }

}  // namespace distributed

}  // namespace fairsurf
