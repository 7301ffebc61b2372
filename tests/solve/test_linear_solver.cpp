#include <fairsurf/mesh/errors.h>
#include <fairsurf/solve/linear_solver.h>

#include <gtest/gtest.h>

#include "step_matrix_proxy.h"

#include <random>
#include <string>
#include <vector>

using namespace fairsurf;

namespace {

const LinearSolverKind kAllKinds[] = {LinearSolverKind::mumps, LinearSolverKind::umfpack,
                                      LinearSolverKind::gmres};

std::string kind_name(const testing::TestParamInfo<LinearSolverKind>& info) { return to_string(info.param); }

/// A random n by n non-symmetric matrix, `per_row` off-diagonal entries a row in [-1, 1], made
/// strictly diagonally dominant (so well conditioned) with a random sign on the diagonal.
SparseRowMatrix random_dominant_matrix(int n, int per_row, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> column(0, n - 1);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    double row_sum = 0;
    for (int k = 0; k < per_row; ++k) {
      const int j = column(rng);
      if (j == i) continue;
      const double a = value(rng);
      entries.emplace_back(i, j, a);
      row_sum += std::abs(a);
    }
    entries.emplace_back(i, i, (value(rng) < 0 ? -1.0 : 1.0) * (row_sum + 1.0));
  }
  SparseRowMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

Eigen::VectorXd random_vector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = value(rng);
  return v;
}

double row_sum_norm(const SparseRowMatrix& A) {
  return (A.cwiseAbs() * Eigen::VectorXd::Ones(A.cols())).maxCoeff();
}

double relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& exact) {
  return (x - exact).norm() / exact.norm();
}

class LinearSolverTest : public testing::TestWithParam<LinearSolverKind> {
 protected:
  std::unique_ptr<LinearSolver> make(LinearSolverOptions options = {}) {
    options.kind = GetParam();
    return make_linear_solver(options);
  }
};

}  // namespace

TEST_P(LinearSolverTest, RandomWellConditionedSystemsReachTheTolerance) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const SparseRowMatrix A = random_dominant_matrix(800, 8, seed);
    const Eigen::VectorXd exact = random_vector(800, 100 + seed);
    const Eigen::VectorXd b = A * exact;
    auto solver = make();
    solver->analyze(A);
    solver->factorize(A);
    const Eigen::VectorXd x = solver->solve(b);
    EXPECT_LE(solver->report().backward_error, 1e-12);
    EXPECT_NEAR((b - A * x).norm() / b.norm(), solver->report().relative_residual, 1e-14);
    EXPECT_LT(relative_error(x, exact), 1e-9) << "seed " << seed;
    EXPECT_FALSE(solver->report().ordering.empty());
  }
}

TEST_P(LinearSolverTest, SymmetricSystemsSolvedFromTheLowerTriangle) {
  // A + Aᵀ of a diagonally dominant matrix is symmetric, indefinite and still dominant.
  const SparseRowMatrix B = random_dominant_matrix(800, 8, 5);
  const SparseRowMatrix A = SparseRowMatrix(B + SparseRowMatrix(B.transpose()));
  const Eigen::VectorXd exact = random_vector(800, 105);
  const Eigen::VectorXd b = A * exact;
  LinearSolverOptions options;
  options.symmetric = true;
  auto solver = make(options);
  solver->analyze(A);
  solver->factorize(A);
  const Eigen::VectorXd x = solver->solve(b);
  EXPECT_LE(solver->report().backward_error, 1e-12);
  EXPECT_LT(relative_error(x, exact), 1e-9);
}

TEST_P(LinearSolverTest, MinimumDegreeOrderingSolvesTheStepMatrixProxy) {
  // The step matrix proxy at τ = 1 (entries up to ~1e11), analyzed with the ordering fills use.
  const SparseRowMatrix A = test::step_matrix_proxy(24, 1.0);
  const Eigen::VectorXd exact = random_vector(static_cast<int>(A.rows()), 11);
  const Eigen::VectorXd b = A * exact;
  LinearSolverOptions options;
  options.ordering = FillOrdering::minimum_degree;
  options.ilut_drop_tolerance = 1e-8;
  options.ilut_fill_factor = 60;
  auto solver = make(options);
  solver->analyze(A);
  solver->factorize(A);
  solver->solve(b);
  EXPECT_LE(solver->report().backward_error, 1e-12);
  EXPECT_EQ(solver->report().ordering, GetParam() == LinearSolverKind::mumps ? "QAMD" : "AMD");
}

TEST_P(LinearSolverTest, BadlyScaledStepMatrixProxyPassesTheResidualCheck) {
  // 24 by 24 torus grid, h = 1/24: τ/h⁶ ≈ 1.9e8 and the entries span about 2e8 .. 1e11.
  LinearSolverOptions options;
  options.ilut_drop_tolerance = 1e-8;
  options.ilut_fill_factor = 60;
  const SparseRowMatrix A = test::step_matrix_proxy(24, 1.0);
  ASSERT_EQ(A.nonZeros(), 37 * A.rows());
  const double largest = Eigen::Map<const Eigen::VectorXd>(A.valuePtr(), A.nonZeros()).cwiseAbs().maxCoeff();
  EXPECT_GT(largest, 1e10);
  auto solver = make(options);
  solver->analyze(A);
  solver->factorize(A);
  // A smooth right-hand side (a displacement of the whole torus) and a rough one.
  const Eigen::VectorXd rough = random_vector(static_cast<int>(A.rows()), 7);
  const Eigen::VectorXd smooth = Eigen::VectorXd::Ones(A.rows()) + 0.1 * A * rough / largest;
  for (const Eigen::VectorXd& b : {rough, smooth}) {
    const Eigen::VectorXd x = solver->solve(b);
    const Eigen::VectorXd r = b - A * x;
    const double backward_error =
        r.lpNorm<Eigen::Infinity>() /
        (row_sum_norm(A) * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
    EXPECT_LE(backward_error, options.residual_tolerance);
    EXPECT_NEAR(solver->report().backward_error, backward_error, 1e-18);
    EXPECT_GE(solver->report().backward_error_before_refinement, solver->report().backward_error);
    // ‖r‖/‖b‖ is far above round-off here: why it is not the default measure.
    EXPECT_GT(solver->report().relative_residual, 1e3 * backward_error);
  }
}

TEST_P(LinearSolverTest, RelativeResidualMeasureOnWellScaledSystems) {
  LinearSolverOptions options;
  options.residual_measure = ResidualMeasure::relative_residual;
  options.residual_tolerance = 1e-10;
  const SparseRowMatrix A = random_dominant_matrix(600, 8, 5);
  const Eigen::VectorXd b = random_vector(600, 6);
  auto solver = make(options);
  solver->analyze(A);
  solver->factorize(A);
  const Eigen::VectorXd x = solver->solve(b);
  EXPECT_LE((b - A * x).norm() / b.norm(), 1e-10);
}

TEST_P(LinearSolverTest, AnalyzeOnceFactorizeTwiceOnTheSamePattern) {
  const SparseRowMatrix A1 = random_dominant_matrix(500, 6, 11);
  SparseRowMatrix A2 = A1;
  // Same pattern, different values: scale each row differently and flip the diagonal signs.
  for (int i = 0; i < A2.outerSize(); ++i)
    for (SparseRowMatrix::InnerIterator it(A2, i); it; ++it)
      it.valueRef() *= (it.col() == i ? -2.0 : 0.5) * (1.0 + i % 3);
  const Eigen::VectorXd exact = random_vector(500, 12);
  auto solver = make();
  solver->analyze(A1);
  solver->factorize(A1);
  EXPECT_LT(relative_error(solver->solve(A1 * exact), exact), 1e-9);
  solver->factorize(A2);
  EXPECT_LT(relative_error(solver->solve(A2 * exact), exact), 1e-9);
  EXPECT_GT(relative_error(A1 * exact, A2 * exact), 0.1);  // the two systems really differ
}

// The same system solved by separate solvers gives the same x bit for bit, which the flows need for
// run-to-run identical outputs. MUMPS's own ordering choice (ICNTL(7) = 7) is SCOTCH above 5000
// unknowns of this matrix, and Debian's SCOTCH orders it differently from one analysis to the next
// (solutions 1.6e-10 apart within one process); the default is a deterministic nested dissection.
TEST(LinearSolver, TheDefaultOrderingGivesTheSameSolutionBitForBit) {
  const SparseRowMatrix A = test::step_matrix_proxy(96, 1e-2);  // 9216 unknowns
  const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), 31);
  for (LinearSolverKind kind : {LinearSolverKind::mumps, LinearSolverKind::umfpack}) {
    LinearSolverOptions options;
    options.kind = kind;
    std::vector<Eigen::VectorXd> solutions;
    for (int run = 0; run < 3; ++run) {
      auto solver = make_linear_solver(options);
      solver->analyze(A);
      solver->factorize(A);
      solutions.push_back(solver->solve(b));
      EXPECT_EQ(solver->report().ordering, kind == LinearSolverKind::mumps ? "PORD" : "METIS");
    }
    EXPECT_TRUE(solutions[1] == solutions[0]) << to_string(kind);
    EXPECT_TRUE(solutions[2] == solutions[0]) << to_string(kind);
  }
}

TEST_P(LinearSolverTest, ChangedPatternThrowsInvalidArgument) {
  const SparseRowMatrix A = random_dominant_matrix(100, 4, 21);
  SparseRowMatrix B = A;
  B.coeffRef(0, 99 - (A.coeff(0, 99) != 0 ? 1 : 0)) += 1e-3;  // most likely a new entry
  B.makeCompressed();
  SparseRowMatrix bigger = random_dominant_matrix(101, 4, 21);
  auto solver = make();
  solver->analyze(A);
  if (B.nonZeros() != A.nonZeros()) {
    try {
      solver->factorize(B);
      FAIL() << "no exception";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.what()), std::string("factorize: ") + to_string(GetParam()) +
                                           ": the sparsity pattern differs from the analyzed one; "
                                           "call analyze() again");
    }
  }
  EXPECT_THROW(solver->factorize(bigger), InvalidArgument);
  // After a rejected pattern the analyzed one still works.
  solver->factorize(A);
  const Eigen::VectorXd exact = random_vector(100, 22);
  EXPECT_LT(relative_error(solver->solve(A * exact), exact), 1e-9);
}

TEST_P(LinearSolverTest, UsageErrorsThrowInvalidArgument) {
  auto solver = make();
  EXPECT_THROW(solver->factorize(random_dominant_matrix(10, 2, 1)), InvalidArgument);
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(10)), InvalidArgument);
  EXPECT_THROW(solver->analyze(SparseRowMatrix(3, 4)), InvalidArgument);
  solver->analyze(random_dominant_matrix(10, 2, 1));
  solver->factorize(random_dominant_matrix(10, 2, 1));
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(11)), InvalidArgument);
  EXPECT_EQ(solver->solve(Eigen::VectorXd::Zero(10)).norm(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllKinds, LinearSolverTest, testing::ValuesIn(kAllKinds), kind_name);

namespace {

/// A 4 by 4 matrix whose first and third rows are equal: singular, though its pattern is not. Any
/// elimination treats the two rows alike, so the singularity shows as an exact zero pivot.
SparseRowMatrix singular_matrix() {
  Eigen::MatrixXd dense(4, 4);
  dense << 2, 1, 0, 1,  //
      1, 3, 1, 0,       //
      2, 1, 0, 1,       //
      0, 1, 1, 4;
  SparseRowMatrix A = dense.sparseView();
  A.makeCompressed();
  return A;
}

std::string factorize_error(LinearSolverKind kind) {
  LinearSolverOptions options;
  options.kind = kind;
  auto solver = make_linear_solver(options);
  solver->analyze(singular_matrix());
  try {
    solver->factorize(singular_matrix());
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "no exception";
}

}  // namespace

TEST(LinearSolver, SingularMatrixThrowsNumericalErrorWithTheBackEndsCode) {
  EXPECT_EQ(factorize_error(LinearSolverKind::mumps),
            "factorize: mumps: numerically singular matrix (INFOG(1) = -10, INFOG(2) = 3)");
  EXPECT_EQ(factorize_error(LinearSolverKind::umfpack), "factorize: umfpack: singular matrix (status 1)");
}

TEST(LinearSolver, SingularMatrixMakesGmresFailToConverge) {
  LinearSolverOptions options;
  options.kind = LinearSolverKind::gmres;
  auto solver = make_linear_solver(options);
  solver->analyze(singular_matrix());
  solver->factorize(singular_matrix());  // ILUT replaces a zero pivot; the failure comes at solve
  try {
    // The right-hand side is inconsistent: GMRES returns an x of size 1e18 whose backward error is
    // round-off but whose residual is larger than b.
    solver->solve(Eigen::Vector4d(1, 0, 0, 0));
    FAIL() << "no exception";
  } catch (const NumericalError& e) {
    const std::string message = e.what();
    EXPECT_TRUE(message.starts_with("solve: gmres: relative residual ")) << message;
    EXPECT_TRUE(
        message.ends_with(" after 3 refinements: the solution is no better than zero "
                          "(numerically singular matrix?)"))
        << message;
  }
}

TEST(LinearSolver, TooWeakGmresThrowsNumericalError) {
  // No fill and a tiny Krylov space cannot solve the stiff proxy in 20 iterations.
  LinearSolverOptions options;
  options.kind = LinearSolverKind::gmres;
  options.gmres_restart = 5;
  options.gmres_max_iterations = 20;
  options.ilut_drop_tolerance = 0.5;
  options.ilut_fill_factor = 1;
  const SparseRowMatrix A = test::step_matrix_proxy(16, 1.0);
  auto solver = make_linear_solver(options);
  solver->analyze(A);
  solver->factorize(A);
  try {
    solver->solve(random_vector(static_cast<int>(A.rows()), 3));
    FAIL() << "no exception";
  } catch (const NumericalError& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with("solve: gmres: not converged after 20 iterations"))
        << e.what();
  }
}

namespace {

/// The message of the NumericalError thrown by solving the 24 by 24 step proxy with `options`.
std::string proxy_solve_error(LinearSolverOptions options) {
  auto solver = make_linear_solver(options);
  const SparseRowMatrix A = test::step_matrix_proxy(24, 1.0);
  solver->analyze(A);
  solver->factorize(A);
  try {
    solver->solve(random_vector(static_cast<int>(A.rows()), 5));
  } catch (const NumericalError& e) {
    EXPECT_EQ(solver->report().refinement_steps, options.max_refinement_steps);
    return e.what();
  }
  return "no exception";
}

}  // namespace

TEST(LinearSolver, ResidualAboveToleranceAfterRefinementThrowsWithTheFigures) {
  // A backward error below round-off cannot be reached.
  LinearSolverOptions options;
  options.residual_tolerance = 1e-30;
  options.max_refinement_steps = 2;
  std::string message = proxy_solve_error(options);
  EXPECT_TRUE(message.starts_with("solve: mumps: backward error ")) << message;
  EXPECT_TRUE(message.ends_with("e-17 above tolerance 1e-30 after 2 refinements") ||
              message.ends_with("e-16 above tolerance 1e-30 after 2 refinements"))
      << message;
  // On this stiff system ‖r‖/‖b‖ stalls near 3e-7 whatever the refinement.
  options.residual_measure = ResidualMeasure::relative_residual;
  options.residual_tolerance = 1e-10;
  options.max_refinement_steps = 3;
  message = proxy_solve_error(options);
  EXPECT_TRUE(message.starts_with("solve: mumps: relative residual ")) << message;
  EXPECT_TRUE(message.ends_with("e-7 above tolerance 1e-10 after 3 refinements")) << message;
}

TEST(LinearSolver, MumpsControlsArePassedThrough) {
  const SparseRowMatrix A = test::step_matrix_proxy(80, 1.0);  // 6400 unknowns: PORD by default
  LinearSolverOptions options;
  options.mumps_controls = {{7, 0}};  // AMD instead
  auto solver = make_linear_solver(options);
  solver->analyze(A);
  EXPECT_EQ(solver->report().ordering, "AMD");
  solver->factorize(A);
  EXPECT_LE(solver->report().factor_megabytes_busiest_rank, solver->report().factor_megabytes_all_ranks);
  EXPECT_GT(solver->report().factor_megabytes_busiest_rank, 0);
}

TEST(LinearSolver, MumpsControlsTheLibraryOwnsAreRefused) {
  LinearSolverOptions options;
  options.mumps_controls = {{3, 6}};  // diagnostics on standard output: the library never prints
  try {
    make_linear_solver(options);
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "make_linear_solver: ICNTL(3) = 6: not a MUMPS control to pass through (1..60, except "
                           "1-5, 18, 20, 21, which the library sets)");
  }
  options.mumps_controls = {{7, 0}};
  options.kind = LinearSolverKind::umfpack;
  EXPECT_THROW(make_linear_solver(options), InvalidArgument);
}

TEST(LinearSolver, KindNamesRoundTripAndUnknownNamesAreRejected) {
  for (auto kind : kAllKinds) EXPECT_EQ(parse_linear_solver_kind(to_string(kind)), kind);
  try {
    parse_linear_solver_kind("superlu");
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(),
                 "parse_linear_solver_kind: unknown solver 'superlu' (valid: mumps, umfpack, gmres, mumps-mpi)");
  }
  LinearSolverOptions bad;
  bad.max_refinement_steps = -1;
  EXPECT_THROW(make_linear_solver(bad), InvalidArgument);
}
