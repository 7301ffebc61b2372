// The mumps-mpi solver's time per step and memory per rank, under `mpirun -n N` (bench/bench_mumps_mpi.sh
// runs 1, 2 and 4 ranks at 164k and 655k unknowns). The matrix is bench_linear_solver's proxy of the
// flow's step matrix on the unit icosphere (bench/support/step_matrix_sphere.h: 37 non-zeros a row,
// non-symmetric, τ = 1e-2), assembled on rank 0 as the flow assembles its own.
//
//   bench_mumps_mpi SUBDIVISIONS STEPS SOLVER      (SOLVER: mumps, the sequential path, or mumps-mpi)
//
// Rank 0 analyzes once, then refactorizes and solves STEPS times, and prints one "result" line: the
// mean refactorize + solve time, MUMPS's factorization memory on its busiest rank and on all ranks
// (INFOG(21), INFOG(22)), rank 0's resident memory with the matrix assembled (before the solver),
// and its peak. Every other rank prints its own peak once served ("rank R peak_mb X").
#include <fairsurf/solve/distributed.h>
#include <fairsurf/solve/linear_solver.h>

#include "process_memory.h"
#include "step_matrix_sphere.h"

#include <cstdio>
#include <random>
#include <string>

namespace {

constexpr double kTau = 1e-2;
constexpr double kMegabyte = 1 << 20;

void print_peak(int rank) {
  std::printf("rank %d peak_mb %.0f\n", rank, static_cast<double>(fairsurf::bench::peak_bytes()) / kMegabyte);
  std::fflush(stdout);
}

void run(int subdivisions, int steps, const std::string& solver_name, int ranks) {
  const fairsurf::SparseRowMatrix A = fairsurf::bench::sphere_step_matrix_proxy(subdivisions, kTau);
  const double assembled_mb = static_cast<double>(fairsurf::bench::proc_status_bytes("VmRSS:")) / kMegabyte;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> value(-1, 1);
  Eigen::VectorXd b(A.rows());
  for (auto& v : b) v = value(rng);

  fairsurf::LinearSolverOptions options;
  options.kind = fairsurf::parse_linear_solver_kind(solver_name);
  auto solver = fairsurf::make_linear_solver(options);
  solver->analyze(A);
  const double analyze_s = solver->report().analyze_seconds;
  double step_s = 0;
  for (int step = 0; step < steps; ++step) {
    solver->factorize(A);
    solver->solve(b);
    step_s += solver->report().factorize_seconds + solver->report().solve_seconds;
  }
  const auto& r = solver->report();
  std::printf(
      "result solver %s ranks %d unknowns %ld nnz_per_row %.1f ordering %s analyze_s %.2f step_s %.2f "
      "factor_mb_busiest %.0f factor_mb_all %.0f backward_error %.1e assembled_mb %.0f\n",
      solver_name.c_str(), ranks, static_cast<long>(A.rows()), static_cast<double>(A.nonZeros()) / A.rows(),
      r.ordering.c_str(), analyze_s, step_s / steps, r.factor_megabytes_busiest_rank, r.factor_megabytes_all_ranks,
      r.backward_error, assembled_mb);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  fairsurf::distributed::Session session(argc, argv);
  if (session.is_worker()) {
    const int code = session.serve();
    print_peak(session.rank());
    return code;
  }
  int code = 0;
  if (argc != 4) {
    std::fprintf(stderr, "usage: bench_mumps_mpi SUBDIVISIONS STEPS mumps|mumps-mpi\n");
    code = 1;
  } else {
    try {
      run(std::stoi(argv[1]), std::stoi(argv[2]), argv[3], session.size());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_mumps_mpi: %s\n", e.what());
      code = 4;
    }
  }
  session.finish(code);
  print_peak(0);
  return code;
}
