// fairsurf — the UMFPACK back end: LU through the 64-bit interface (umfpack_dl_*; the 32-bit one
// runs out of index space near 655k unknowns of the step matrix), METIS ordering where the library
// has it, AMD otherwise.
//
// UMFPACK takes compressed columns. The transposition of the stored row-major matrix is computed once
// at analysis as a map from row-major to column-major value positions; a refactorization only
// scatters the new values through it.
#include <fairsurf/mesh/errors.h>

#include "linear_solver_backends.h"

#include <umfpack.h>

#include <string>
#include <vector>

namespace fairsurf::detail {

namespace {

using Index = SuiteSparse_long;

std::string describe_status(Index status) {
  switch (status) {
    case UMFPACK_WARNING_singular_matrix: return "singular matrix";
    case UMFPACK_ERROR_out_of_memory: return "out of memory";
    case UMFPACK_ERROR_invalid_matrix: return "invalid matrix";
    case UMFPACK_ERROR_ordering_failed: return "ordering failed";
    default: return "error";
  }
}

std::string ordering_name(double code) {
  switch (static_cast<int>(code)) {
    case UMFPACK_ORDERING_CHOLMOD: return "CHOLMOD";
    case UMFPACK_ORDERING_AMD: return "AMD";
    case UMFPACK_ORDERING_METIS: return "METIS";
    case UMFPACK_ORDERING_NONE: return "none";
    default: return "UMFPACK ordering " + std::to_string(static_cast<int>(code));
  }
}

class UmfpackSolver final : public LinearSolver {
 public:
  explicit UmfpackSolver(const LinearSolverOptions& options) : LinearSolver(options) {
    umfpack_dl_defaults(control_);
    control_[UMFPACK_IRSTEP] = 0;  // refinement is done (and reported) by LinearSolver::solve
  }

  ~UmfpackSolver() override { free_factors(); }

 private:
  void analyze_pattern() override {
    free_factors();
    build_columns();
    const bool minimum_degree = options().ordering == FillOrdering::minimum_degree;
    control_[UMFPACK_ORDERING] = minimum_degree ? UMFPACK_ORDERING_AMD : UMFPACK_ORDERING_METIS;
    Index status = symbolic();
    if (status != UMFPACK_OK && !minimum_degree) {  // METIS missing from this UMFPACK build, or failing: AMD instead
      control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
      status = symbolic();
    }
    check("analyze", status);
    set_ordering(ordering_name(info_[UMFPACK_ORDERING_USED]));
  }

  void factorize_values() override {
    scatter_values();
    free_numeric();
    const Index status = umfpack_dl_numeric(column_offsets_.data(), row_indices_.data(), values_.data(),
                                            symbolic_, &numeric_, control_, info_);
    check("factorize", status);
  }

  int apply_inverse(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override {
    x.resize(rhs.size());
    const Index status = umfpack_dl_solve(UMFPACK_A, column_offsets_.data(), row_indices_.data(),
                                          values_.data(), x.data(), rhs.data(), numeric_, control_, info_);
    check("solve", status);
    return 0;
  }

  /// Column-major pattern of the stored matrix and the position of each row-major value in it.
  void build_columns() {
    const SparseRowMatrix& A = matrix();
    const Index n = A.rows(), nnz = A.nonZeros();
    column_offsets_.assign(n + 1, 0);
    for (Index k = 0; k < nnz; ++k) ++column_offsets_[A.innerIndexPtr()[k] + 1];
    for (Index j = 0; j < n; ++j) column_offsets_[j + 1] += column_offsets_[j];
    std::vector<Index> next(column_offsets_.begin(), column_offsets_.end() - 1);
    row_indices_.resize(nnz);
    column_position_.resize(nnz);
    values_.assign(nnz, 0.0);
    for (Index i = 0; i < n; ++i)  // rows in ascending order, so each column's rows come out sorted
      for (Index k = A.outerIndexPtr()[i]; k < A.outerIndexPtr()[i + 1]; ++k) {
        const Index position = next[A.innerIndexPtr()[k]]++;
        row_indices_[position] = i;
        column_position_[k] = position;
      }
  }

  void scatter_values() {
    const double* row_major = matrix().valuePtr();
    for (std::size_t k = 0; k < column_position_.size(); ++k) values_[column_position_[k]] = row_major[k];
  }

  /// The analyzed matrix's values are passed too: without them UMFPACK cannot see that the diagonal
  /// dominates and picks its unsymmetric strategy, whose backward error on the step matrix is 1e-11
  /// instead of 1e-15.
  Index symbolic() {
    const Index n = matrix().rows();
    free_factors();
    scatter_values();
    return umfpack_dl_symbolic(n, n, column_offsets_.data(), row_indices_.data(), values_.data(), &symbolic_,
                               control_, info_);
  }

  void check(const char* phase, Index status) const {
    // Warnings 2 and 3 only say that the determinant under- or overflowed: the factors are fine.
    if (status == UMFPACK_OK || status == UMFPACK_WARNING_determinant_underflow ||
        status == UMFPACK_WARNING_determinant_overflow)
      return;
    throw NumericalError(std::string(phase) + ": umfpack: " + describe_status(status) + " (status " +
                         std::to_string(status) + ")");
  }

  void free_numeric() {
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    numeric_ = nullptr;
  }

  void free_factors() {
    free_numeric();
    if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
    symbolic_ = nullptr;
  }

  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  std::vector<Index> column_offsets_, row_indices_, column_position_;
  std::vector<double> values_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver(const LinearSolverOptions& options) {
  return std::make_unique<UmfpackSolver>(options);
}

}  // namespace fairsurf::detail
