// fairsurf_mpi_probe MODE DIR — the library's mumps-mpi solver under `mpirun -n 2`, for the failures
// the CLI cannot be made to meet on purpose (tests/mpi/test_mpi.cpp). Rank 0 drives, rank 1 serves,
// as in apps/fairsurf/main.cpp. Every rank writes its exit code to DIR/rank-R.exit before returning.
//   singular  rank 0 factorizes a singular matrix: NumericalError, exit code 4 (kNumerical) on all.
//   dying     rank 1 dies (exit without MPI_Finalize) instead of serving; rank 0 then factorizes.
#include <fairsurf/mesh/errors.h>
#include <fairsurf/solve/distributed.h>
#include <fairsurf/solve/linear_solver.h>

#include <unistd.h>

#include <fstream>
#include <iostream>
#include <string>

namespace {

constexpr int kNumerical = 4;  // the CLI's code for a failed solve (docs/cli.md)

// diag(1, 0, 1): singular, with a pattern MUMPS analyzes without complaint.
fairsurf::SparseRowMatrix singular_matrix() {
  fairsurf::SparseRowMatrix A(3, 3);
  A.insert(0, 0) = 1;
  A.insert(1, 1) = 0;
  A.insert(2, 2) = 1;
  A.makeCompressed();
  return A;
}

int drive() {
  fairsurf::LinearSolverOptions options;
  options.kind = fairsurf::LinearSolverKind::mumps_mpi;
  try {
    auto solver = fairsurf::make_linear_solver(options);
    const auto A = singular_matrix();
    solver->analyze(A);
    solver->factorize(A);
  } catch (const fairsurf::NumericalError& e) {
    std::cerr << "fairsurf_mpi_probe: error: " << e.what() << "\n";
    return kNumerical;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  fairsurf::distributed::Session session(argc, argv);
  if (argc != 3) {
    std::cerr << "usage: fairsurf_mpi_probe singular|dying DIR\n";
    return 1;
  }
  const std::string mode = argv[1];
  if (mode == "dying" && session.rank() == 1) _exit(9);
  const int code = session.is_worker() ? session.serve() : drive();
  if (!session.is_worker()) session.finish(code);
  std::ofstream(std::string(argv[2]) + "/rank-" + std::to_string(session.rank()) + ".exit") << code << "\n";
  return code;
}
