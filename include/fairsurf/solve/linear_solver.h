// fairsurf — sparse linear systems A x = b (non-symmetric in general): one interface, three back ends.
//
// Made for the flow's step matrix (I − τ (P′Q)_FF) of method.md §5: non-symmetric, a 3-ring stencil
// (≈ 37 non-zeros a row), entries growing like τ/h⁶, the sparsity pattern fixed while the mesh
// connectivity is. So the work is split the way the flow uses it:
//   analyze(A)    once per sparsity pattern (ordering, symbolic factorization),
//   factorize(A)  once per step (numeric factorization; the pattern must be the analyzed one),
//   solve(b)      one or more right-hand sides per step.
// Every solve checks its residual r = b − A x and refines iteratively (x += A⁻¹ r with the same
// factorization) until the chosen residual measure is under the tolerance; a solve that stays above
// it throws NumericalError rather than returning an inaccurate x. The default measure is the normwise
// backward error, not ‖r‖/‖b‖: with entries of size τ/h⁶ even the exact solution, rounded to
// doubles, has ‖r‖/‖b‖ up to about 1e-16 ‖A‖‖x‖/‖b‖ (3e-7 on a 576-unknown proxy of the step matrix,
// more than 1 on fine meshes at large τ), while a stable solve always reaches a backward error near
// 1e-16. Both figures are reported.
//
// Back ends (docs/solvers.md has the measured comparison):
//   mumps    sequential MUMPS LU (LDLᵀ with options.symmetric), nested dissection (PORD on large
//            systems) or QAMD (options.ordering). The default and the fastest.
//   mumps-mpi the same MUMPS factorization with its factors distributed over the MPI ranks of a
//            distributed::Session (distributed.h); rank 0 calls the solver, the others serve it.
//            Only in builds with FAIRSURF_MPI (make_linear_solver throws InvalidArgument otherwise).
//   umfpack  UMFPACK LU, 64-bit interface (umfpack_dl_*), METIS ordering, AMD if METIS is missing.
//   gmres    restarted GMRES preconditioned by incomplete LU with threshold (Eigen's ILUT).
//            Needs near-complete fill once τ ≫ h⁶ (the defaults: drop 1e-6, fill factor 40).
// A solver object is not thread-safe; use one per thread.
#pragma once

#include <fairsurf/geometry/sparse.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <map>
#include <memory>
#include <string>

namespace fairsurf {

enum class LinearSolverKind { mumps, umfpack, gmres, mumps_mpi };

/// "mumps", "umfpack", "gmres" or "mumps-mpi".
const char* to_string(LinearSolverKind kind);
/// Inverse of to_string; throws InvalidArgument naming the valid kinds.
LinearSolverKind parse_linear_solver_kind(const std::string& name);

/// How solve() measures the residual r = b − A x it checks against the tolerance.
enum class ResidualMeasure {
  backward_error,  ///< ‖r‖∞ / (‖A‖∞ ‖x‖∞ + ‖b‖∞): the smallest relative change of A and b that x solves
  relative_residual,  ///< ‖r‖₂ / ‖b‖₂: meaningful only for well-scaled systems
};

/// The fill-reducing ordering of the direct back ends' analysis (GMRES ignores it).
enum class FillOrdering {
  /// MUMPS: PORD (ICNTL(7) = 4) above 5000 unknowns, MUMPS's own minimum degree choice (AMF or
  /// QAMD) up to that; UMFPACK: METIS. Not MUMPS's own choice above 5000 (SCOTCH in Debian's build),
  /// which orders the same matrix differently in every run, so that outputs differed in round-off
  /// from run to run. PORD is deterministic and as fast on the step matrix (docs/solvers.md,
  /// "Orderings").
  nested_dissection,
  /// Approximate minimum degree (MUMPS QAMD, UMFPACK AMD). On a hole patch's systems (∆³ or the
  /// step matrix) its analysis is far cheaper than nested dissection's and the factorization no
  /// slower (docs/fill.md, benchmark); on very large systems prefer nested_dissection.
  minimum_degree,
};

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::mumps;
  FillOrdering ordering = FillOrdering::nested_dissection;
  /// A is symmetric (to round-off): MUMPS then factors LDLᵀ from its lower triangle, about half
  /// the work of LU; residuals and refinement still use the whole A. UMFPACK and GMRES ignore it.
  bool symmetric = false;
  ResidualMeasure residual_measure = ResidualMeasure::backward_error;
  /// Accept x once the residual measure is at most this.
  double residual_tolerance = 1e-12;
  /// Iterative refinement steps allowed after the first solve.
  int max_refinement_steps = 3;
  /// mumps and mumps-mpi only: MUMPS's own controls passed through, ICNTL(k) = v (MUMPS 5.5 manual),
  /// set after the library's settings (on rank 0: MUMPS reads controls on its host): e.g. {7, 0} AMD ordering, {14, 50} workspace
  /// relaxation, {28, 2} parallel analysis with PT-Scotch. The controls the library owns are refused
  /// (InvalidArgument): 1–4 (output: the library never prints), 5 (matrix format), 18 (where the
  /// matrix is), 20 and 21 (where the right-hand side and solution are); k must be 1..60.
  std::map<int, int> mumps_controls{};
  // GMRES + ILUT only.
  int gmres_restart = 50;             ///< Krylov subspace dimension before a restart
  /// GMRES's own (preconditioned) relative residual target; the backward-error check above, with
  /// refinement, is what accepts the solution.
  double gmres_tolerance = 1e-8;
  int gmres_max_iterations = 1000;    ///< per GMRES call (each refinement step is one call)
  /// ILUT drops entries below this times the row norm; with the fill factor below, the smallest
  /// preconditioner with which GMRES converges on the sixth-order step (method.md §5: ILU needs
  /// near-complete fill there; drop 1e-5 and fill 20 stall near a relative residual of 1e-4).
  double ilut_drop_tolerance = 1e-6;
  int ilut_fill_factor = 40;  ///< ILUT keeps at most this times the row's non-zeros
};

/// Figures of the last analyze / factorize / solve.
struct SolveReport {
  double relative_residual_before_refinement = 0;  ///< ‖b − A x‖₂/‖b‖₂ after the first solve
  double relative_residual = 0;                    ///< the same for the returned x
  double backward_error_before_refinement = 0;  ///< ‖b − A x‖∞/(‖A‖∞‖x‖∞ + ‖b‖∞), first solve
  double backward_error = 0;                    ///< the same for the returned x
  int refinement_steps = 0;                     ///< refinement steps taken
  int iterations = 0;                           ///< GMRES iterations over all calls of the solve; 0 for LU
  double analyze_seconds = 0;
  double factorize_seconds = 0;
  double solve_seconds = 0;  ///< including residuals and refinement
  std::string ordering;      ///< fill-reducing ordering used ("METIS", "AMD", ...)
  /// MUMPS only (0 otherwise): memory the last factorization used on its busiest rank and on all
  /// ranks together, in MB (INFOG(21), INFOG(22)); equal with one process.
  double factor_megabytes_busiest_rank = 0;
  double factor_megabytes_all_ranks = 0;
};

/// Solver of A x = b for a square sparse non-symmetric A. Create with make_linear_solver.
class LinearSolver {
 public:
  virtual ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// Symbolic analysis of A's sparsity pattern (values are ignored). Throws InvalidArgument if A is
  /// not square or empty, NumericalError if the back end fails.
  void analyze(const SparseRowMatrix& A);
  /// Numeric factorization of A, whose pattern must be the one analyzed (InvalidArgument if not;
  /// analyze first). Throws NumericalError naming the back end and its error code if the
  /// factorization fails or A is singular. Keeps a copy of A for the residual checks.
  void factorize(const SparseRowMatrix& A);
  /// Returns x with A x = b, the residual checked and refined as the header comment says.
  /// Throws InvalidArgument if b has the wrong size or nothing is factorized, NumericalError if the
  /// residual stays above the tolerance (or GMRES does not converge).
  Eigen::VectorXd solve(const Eigen::VectorXd& b);

  /// Figures of the last calls (analyze and factorize times are kept until the next such call).
  const SolveReport& report() const { return report_; }
  const LinearSolverOptions& options() const { return options_; }
  /// "mumps", "umfpack", "gmres" or "mumps-mpi", as used in error messages.
  const char* name() const { return to_string(options_.kind); }

 protected:
  explicit LinearSolver(const LinearSolverOptions& options);
  /// The matrix last given to analyze or factorize (compressed); back ends read its values.
  const SparseRowMatrix& matrix() const { return matrix_; }
  void set_ordering(std::string ordering) { report_.ordering = std::move(ordering); }
  void set_factor_memory(double busiest_rank_megabytes, double all_ranks_megabytes) {
    report_.factor_megabytes_busiest_rank = busiest_rank_megabytes;
    report_.factor_megabytes_all_ranks = all_ranks_megabytes;
  }

 private:
  // Back-end steps. analyze_pattern and factorize_values see matrix() already set; apply_inverse
  // writes one (unrefined) solution of A x = rhs into x and returns the iterations it took.
  virtual void analyze_pattern() = 0;
  virtual void factorize_values() = 0;
  virtual int apply_inverse(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) = 0;

  /// Sets `residual` to b − A x, records both measures in `report_` and returns the checked one.
  double measure_residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x, Eigen::VectorXd& residual);

  LinearSolverOptions options_;
  SolveReport report_;
  SparseRowMatrix matrix_;
  double matrix_norm_inf_ = 0;  // ‖A‖∞ of the factorized matrix
  bool analyzed_ = false;
  bool factorized_ = false;
};

/// A solver of the kind options.kind. Throws InvalidArgument for invalid options (negative
/// tolerance or refinement steps, non-positive GMRES restart, iterations or fill factor), and for
/// mumps-mpi in a build without MPI or on an MPI job whose other ranks serve no Session.
std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options = {});

}  // namespace fairsurf
