// fairsurf — private: the back ends behind make_linear_solver (include/fairsurf/solve/linear_solver.h).
#pragma once

#include <fairsurf/solve/linear_solver.h>

#include <functional>
#include <memory>
#include <string>

namespace fairsurf::detail {

/// Scientific notation without padding, for messages: 3.2e-4, 1e-10.
std::string short_scientific(double value);

/// The processes a MUMPS solver factorizes with: their communicator (Fortran handle), and what tells
/// the others each MUMPS job this process is about to run (−1 create, 1 analyze, 2 factorize with
/// ICNTL(14) = workspace_relaxation, 3 solve, −2 destroy), so that they run it too.
struct MumpsTeam {
  int communicator = 0;
  std::function<void(int job, int workspace_relaxation)> announce = [](int, int) {};
};

/// The Fortran communicator of this process alone: MPI_COMM_SELF with MPI (started on first use
/// if no distributed::Session did), the sequential MUMPS's stand-in for MPI_COMM_WORLD without.
int mumps_self_communicator();

std::unique_ptr<LinearSolver> make_mumps_solver(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> make_mumps_solver(const LinearSolverOptions& options, MumpsTeam team);
/// MUMPS over every rank of the distributed::Session (src/mpi); throws InvalidArgument without MPI.
std::unique_ptr<LinearSolver> make_mumps_mpi_solver(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> make_umfpack_solver(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> make_gmres_solver(const LinearSolverOptions& options);

}  // namespace fairsurf::detail
