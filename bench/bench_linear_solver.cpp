// Linear solvers on a proxy of the flow's step matrix (method.md §5) on the unit icosphere at 5 / 6 / 7
// subdivisions (10 242 / 40 962 / 163 842 unknowns, the sizes of method.md §5's reference timings):
// A = I + (τ/h⁶)(L³ + 0.3 L² D), 37 non-zeros a row, non-symmetric (bench/support/step_matrix_sphere.h),
// τ = 1e-2 as in the flow on a unit sphere. One analysis per case (analyze_s), then each iteration
// refactorizes and solves (the per-step cost; factorize_s and solve_s split it).
// GMRES + ILUT runs at 10k unknowns only: on this matrix it needs near-complete fill (method.md §5) and
// its ILUT alone costs seconds, so larger sizes would only burn minutes to report the same outcome.
#include <fairsurf/mesh/errors.h>
#include <fairsurf/solve/linear_solver.h>

#include <benchmark/benchmark.h>

#include "step_matrix_sphere.h"

#include <map>
#include <random>

namespace {

using fairsurf::LinearSolverKind;

constexpr double kTau = 1e-2;

const fairsurf::SparseRowMatrix& proxy(int subdivisions) {
  static std::map<int, fairsurf::SparseRowMatrix> cache;
  auto it = cache.find(subdivisions);
  if (it == cache.end())
    it = cache.emplace(subdivisions, fairsurf::bench::sphere_step_matrix_proxy(subdivisions, kTau)).first;
  return it->second;
}

void BM_RefactorAndSolve(benchmark::State& state) {
  const int subdivisions = static_cast<int>(state.range(0));
  fairsurf::LinearSolverOptions options;
  options.kind = static_cast<LinearSolverKind>(state.range(1));
  const auto& A = proxy(subdivisions);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> value(-1, 1);
  Eigen::VectorXd b(A.rows());
  for (auto& v : b) v = value(rng);
  auto solver = fairsurf::make_linear_solver(options);
  solver->analyze(A);
  double factorize = 0, solve = 0;
  for (auto _ : state) {
    try {
      solver->factorize(A);
      benchmark::DoNotOptimize(solver->solve(b));
    } catch (const fairsurf::Error& e) {
      state.SkipWithError(e.what());
      break;
    }
    factorize += solver->report().factorize_seconds;
    solve += solver->report().solve_seconds;
  }
  const auto& report = solver->report();
  const double iterations = static_cast<double>(state.iterations());
  state.SetLabel(std::string(solver->name()) + " " + report.ordering);
  state.counters["unknowns"] = static_cast<double>(A.rows());
  state.counters["nnz_per_row"] = static_cast<double>(A.nonZeros()) / static_cast<double>(A.rows());
  state.counters["analyze_s"] = report.analyze_seconds;
  state.counters["factorize_s"] = factorize / iterations;
  state.counters["solve_s"] = solve / iterations;
  state.counters["backward_error"] = report.backward_error;
  state.counters["rel_residual"] = report.relative_residual;
  state.counters["gmres_iters"] = report.iterations;
  state.counters["refinements"] = report.refinement_steps;
}

void cases(benchmark::internal::Benchmark* b) {
  for (int subdivisions : {5, 6, 7})
    for (auto kind : {LinearSolverKind::mumps, LinearSolverKind::umfpack, LinearSolverKind::gmres})
      if (kind != LinearSolverKind::gmres || subdivisions == 5) b->Args({subdivisions, static_cast<long>(kind)});
}

}  // namespace

BENCHMARK(BM_RefactorAndSolve)->Apply(cases)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);

BENCHMARK_MAIN();
