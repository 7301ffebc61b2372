// fairsurf — the iterative back end: restarted GMRES preconditioned by ILUT, both from Eigen's
// unsupported IterativeSolvers module. The ILUT's AMD ordering is computed once per pattern, the
// incomplete factors once per step.
#include <fairsurf/mesh/errors.h>

#include "linear_solver_backends.h"

#include <unsupported/Eigen/IterativeSolvers>

#include <string>

namespace fairsurf::detail {

namespace {

class GmresSolver final : public LinearSolver {
 public:
  explicit GmresSolver(const LinearSolverOptions& options) : LinearSolver(options) {
    gmres_.set_restart(options.gmres_restart);
    gmres_.setTolerance(options.gmres_tolerance);
    gmres_.setMaxIterations(options.gmres_max_iterations);
    gmres_.preconditioner().setDroptol(options.ilut_drop_tolerance);
    gmres_.preconditioner().setFillfactor(options.ilut_fill_factor);
  }

 private:
  // GMRES keeps a reference to the matrix it is given: it is the stored copy, whose value array is
  // refreshed in place by LinearSolver::factorize.
  void analyze_pattern() override {
    gmres_.analyzePattern(matrix());
    set_ordering("AMD");
  }

  void factorize_values() override {
    gmres_.factorize(matrix());
    if (gmres_.preconditioner().info() != Eigen::Success)
      throw NumericalError("factorize: gmres: the incomplete LU factorization failed");
  }

  int apply_inverse(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override {
    x = gmres_.solve(rhs);
    const int iterations = static_cast<int>(gmres_.iterations());
    if (gmres_.info() != Eigen::Success || !x.allFinite())
      throw NumericalError("solve: gmres: not converged after " + std::to_string(iterations) +
                           " iterations (estimated relative residual " + short_scientific(gmres_.error()) +
                           ", tolerance " + short_scientific(options().gmres_tolerance) + ")");
    return iterations;
  }

  Eigen::GMRES<SparseRowMatrix, Eigen::IncompleteLUT<double>> gmres_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_gmres_solver(const LinearSolverOptions& options) {
  return std::make_unique<GmresSolver>(options);
}

}  // namespace fairsurf::detail
