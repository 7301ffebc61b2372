// fairsurf — the back-end independent part of the linear solvers: pattern bookkeeping, timing,
// residual checks and iterative refinement.
#include <fairsurf/solve/linear_solver.h>

#include <fairsurf/mesh/errors.h>

#include "linear_solver_backends.h"
#include "stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace fairsurf {

namespace detail {

std::string short_scientific(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1e", value);
  std::string text = buffer;
  const auto e = text.find('e');
  if (e == std::string::npos) return text;  // inf, nan
  std::string mantissa = text.substr(0, e);
  if (mantissa.ends_with(".0")) mantissa.resize(mantissa.size() - 2);
  const int exponent = std::stoi(text.substr(e + 1));
  return mantissa + "e" + std::to_string(exponent);
}

}  // namespace detail

namespace {

using detail::short_scientific;

using detail::Clock;
using detail::seconds_since;

bool same_pattern(const SparseRowMatrix& a, const SparseRowMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
}

void check_options(const LinearSolverOptions& o) {
  const auto fail = [](const std::string& what) { throw InvalidArgument("make_linear_solver: " + what); };
  if (!(o.residual_tolerance > 0)) fail("residual tolerance must be positive");
  if (o.max_refinement_steps < 0) fail("max refinement steps must be non-negative");
  const bool mumps = o.kind == LinearSolverKind::mumps || o.kind == LinearSolverKind::mumps_mpi;
  if (!mumps && !o.mumps_controls.empty()) fail(std::string("MUMPS controls given to ") + to_string(o.kind));
  for (const auto& [k, value] : o.mumps_controls)
    if (k < 1 || k > 60 || k <= 5 || k == 18 || k == 20 || k == 21)
      fail("ICNTL(" + std::to_string(k) + ") = " + std::to_string(value) +
           ": not a MUMPS control to pass through (1..60, except 1-5, 18, 20, 21, which the library sets)");
  if (o.kind != LinearSolverKind::gmres) return;
  if (o.gmres_restart <= 0) fail("GMRES restart must be positive");
  if (!(o.gmres_tolerance > 0)) fail("GMRES tolerance must be positive");
  if (o.gmres_max_iterations <= 0) fail("GMRES max iterations must be positive");
  if (!(o.ilut_drop_tolerance >= 0)) fail("ILUT drop tolerance must be non-negative");
  if (o.ilut_fill_factor <= 0) fail("ILUT fill factor must be positive");
}

}  // namespace

const char* to_string(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::mumps: return "mumps";
    case LinearSolverKind::umfpack: return "umfpack";
    case LinearSolverKind::gmres: return "gmres";
    case LinearSolverKind::mumps_mpi: return "mumps-mpi";
  }
  return "unknown";
}

LinearSolverKind parse_linear_solver_kind(const std::string& name) {
  for (auto kind : {LinearSolverKind::mumps, LinearSolverKind::umfpack, LinearSolverKind::gmres,
                    LinearSolverKind::mumps_mpi})
    if (name == to_string(kind)) return kind;
  throw InvalidArgument("parse_linear_solver_kind: unknown solver '" + name +
                        "' (valid: mumps, umfpack, gmres, mumps-mpi)");
}

LinearSolver::LinearSolver(const LinearSolverOptions& options) : options_(options) {}

LinearSolver::~LinearSolver() = default;

void LinearSolver::analyze(const SparseRowMatrix& A) {
  if (A.rows() != A.cols() || A.rows() == 0)
    throw InvalidArgument("analyze: " + std::string(name()) +
                          ": the matrix must be square and non-empty, got " + std::to_string(A.rows()) +
                          " by " + std::to_string(A.cols()));
  const auto start = Clock::now();
  analyzed_ = factorized_ = false;
  matrix_ = A;
  matrix_.makeCompressed();
  analyze_pattern();
  analyzed_ = true;
  report_.analyze_seconds = seconds_since(start);
}

void LinearSolver::factorize(const SparseRowMatrix& A) {
  if (!analyzed_)
    throw InvalidArgument("factorize: " + std::string(name()) + ": analyze() has not been called");
  const auto start = Clock::now();
  factorized_ = false;
  SparseRowMatrix compressed;
  const SparseRowMatrix* source = &A;
  if (!A.isCompressed()) {
    compressed = A;
    compressed.makeCompressed();
    source = &compressed;
  }
  if (!same_pattern(*source, matrix_))
    throw InvalidArgument("factorize: " + std::string(name()) +
                          ": the sparsity pattern differs from the analyzed one; call analyze() again");
  std::copy(source->valuePtr(), source->valuePtr() + source->nonZeros(), matrix_.valuePtr());
  matrix_norm_inf_ = 0;
  for (Eigen::Index i = 0; i < matrix_.outerSize(); ++i) {
    double row_sum = 0;
    for (auto k = matrix_.outerIndexPtr()[i]; k < matrix_.outerIndexPtr()[i + 1]; ++k)
      row_sum += std::abs(matrix_.valuePtr()[k]);
    matrix_norm_inf_ = std::max(matrix_norm_inf_, row_sum);
  }
  factorize_values();
  factorized_ = true;
  report_.factorize_seconds = seconds_since(start);
}

double LinearSolver::measure_residual(const Eigen::VectorXd& b, const Eigen::VectorXd& x,
                                      Eigen::VectorXd& residual) {
  residual.noalias() = b - matrix_ * x;
  report_.relative_residual = residual.norm() / b.norm();
  report_.backward_error = residual.lpNorm<Eigen::Infinity>() /
                           (matrix_norm_inf_ * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
  return options_.residual_measure == ResidualMeasure::backward_error ? report_.backward_error
                                                                      : report_.relative_residual;
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) {
  if (!factorized_)
    throw InvalidArgument("solve: " + std::string(name()) + ": factorize() has not succeeded");
  if (b.size() != matrix_.rows())
    throw InvalidArgument("solve: " + std::string(name()) + ": right-hand side of size " +
                          std::to_string(b.size()) + " for a matrix of size " +
                          std::to_string(matrix_.rows()));
  const auto start = Clock::now();
  report_.refinement_steps = report_.iterations = 0;
  report_.relative_residual = report_.backward_error = 0;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  if (b.norm() == 0) {
    report_.solve_seconds = seconds_since(start);
    return x;
  }
  report_.iterations += apply_inverse(b, x);
  Eigen::VectorXd residual, correction(b.size());
  double measured = measure_residual(b, x, residual);
  report_.relative_residual_before_refinement = report_.relative_residual;
  report_.backward_error_before_refinement = report_.backward_error;
  // A tiny backward error alone does not make x useful: for a (numerically) singular A, a huge x
  // solves a nearby matrix. An x no better than x = 0 (‖r‖ ≥ ‖b‖) is rejected too.
  const auto accepted = [&] {
    return measured <= options_.residual_tolerance && report_.relative_residual < 1;
  };
  while (!accepted() && std::isfinite(measured) && report_.refinement_steps < options_.max_refinement_steps) {
    report_.iterations += apply_inverse(residual, correction);
    x += correction;
    measured = measure_residual(b, x, residual);
    ++report_.refinement_steps;
  }
  report_.solve_seconds = seconds_since(start);
  const std::string prefix = "solve: " + std::string(name()) + ": ";
  const std::string steps = " after " + std::to_string(report_.refinement_steps) + " refinements";
  if (!(measured <= options_.residual_tolerance))
    throw NumericalError(prefix +
                         (options_.residual_measure == ResidualMeasure::backward_error
                              ? "backward error "
                              : "relative residual ") +
                         short_scientific(measured) + " above tolerance " +
                         short_scientific(options_.residual_tolerance) + steps);
  if (!accepted())
    throw NumericalError(prefix + "relative residual " + short_scientific(report_.relative_residual) + steps +
                         ": the solution is no better than zero (numerically singular matrix?)");
  return x;
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options) {
  check_options(options);
  switch (options.kind) {
    case LinearSolverKind::mumps: return detail::make_mumps_solver(options);
    case LinearSolverKind::umfpack: return detail::make_umfpack_solver(options);
    case LinearSolverKind::gmres: return detail::make_gmres_solver(options);
    case LinearSolverKind::mumps_mpi: return detail::make_mumps_mpi_solver(options);
  }
  throw InvalidArgument("make_linear_solver: unknown solver kind");
}

}  // namespace fairsurf
