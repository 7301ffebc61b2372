// fairsurf — the MUMPS back end: sequential MUMPS (Debian's libmumps-seq) LU with automatic ordering.
//
// MUMPS takes the matrix as 1-based coordinates (irn, jcn, a). The row-major CSR order of the
// stored matrix is a valid coordinate order, so the index arrays are built once at analysis and `a`
// points at the stored values themselves: a refactorization copies nothing.
#include <fairsurf/errors.h>

#include "linear_solver_backends.h"

#include <dmumps_c.h>

#include <string>
#include <vector>

namespace fairsurf::detail {

namespace {

constexpr int kUseCommWorld = -987654;  // MUMPS's code for MPI_COMM_WORLD (a stub in libmpiseq)
constexpr int kMaxWorkspaceRetries = 4;

/// ICNTL(k) and INFOG(k) in the 1-based numbering of the MUMPS manual.
int& icntl(DMUMPS_STRUC_C& id, int k) { return id.icntl[k - 1]; }
int infog(const DMUMPS_STRUC_C& id, int k) { return id.infog[k - 1]; }

std::string describe_error(int code) {
  switch (code) {
    case -6: return "structurally singular matrix";
    case -10: return "numerically singular matrix";
    case -13: return "out of memory";
    case -8:
    case -9:
    case -14:
    case -15:
    case -17:
    case -20: return "internal workspace too small";
    default: return "error";
  }
}

bool is_workspace_error(int code) {
  return code == -8 || code == -9 || code == -14 || code == -15 || code == -17 || code == -20;
}

std::string ordering_name(int code) {
  switch (code) {
    case 0: return "AMD";
    case 2: return "AMF";
    case 3: return "SCOTCH";
    case 4: return "PORD";
    case 5: return "METIS";
    case 6: return "QAMD";
    default: return "MUMPS ordering " + std::to_string(code);
  }
}

class MumpsSolver final : public LinearSolver {
 public:
  explicit MumpsSolver(const LinearSolverOptions& options) : LinearSolver(options) {
    id_.job = -1;
    id_.par = 1;  // the host takes part in the factorization (the only process)
    id_.sym = options.symmetric ? 2 : 0;  // general symmetric (LDLᵀ with pivoting), or unsymmetric
    id_.comm_fortran = kUseCommWorld;
    dmumps_c(&id_);
    if (infog(id_, 1) < 0) {
      const int code = infog(id_, 1);
      id_.job = -2;
      dmumps_c(&id_);
      throw NumericalError(
          "make_linear_solver: mumps: initialization failed (INFOG(1) = " + std::to_string(code) + ")");
    }
    // The library never prints: no error, diagnostic or global-information output.
    icntl(id_, 1) = -1;
    icntl(id_, 2) = -1;
    icntl(id_, 3) = -1;
    icntl(id_, 4) = 0;
    icntl(id_, 7) = options.ordering == FillOrdering::minimum_degree ? 6 : 7;  // QAMD, or MUMPS chooses
  }

  ~MumpsSolver() override {
    id_.job = -2;
    dmumps_c(&id_);
  }

 private:
  void analyze_pattern() override {
    const SparseRowMatrix& A = matrix();
    rows_.clear();
    cols_.clear();
    passed_.clear();
    for (int i = 0; i < A.outerSize(); ++i)
      for (int k = A.outerIndexPtr()[i]; k < A.outerIndexPtr()[i + 1]; ++k) {
        const int j = A.innerIndexPtr()[k];
        if (id_.sym != 0 && j > i) continue;  // MUMPS would add (j, i) to (i, j): lower triangle only
        rows_.push_back(i + 1);
        cols_.push_back(j + 1);
        passed_.push_back(k);
      }
    values_.resize(passed_.size());
    id_.n = static_cast<int>(A.rows());
    id_.nnz = static_cast<MUMPS_INT8>(passed_.size());
    id_.irn = rows_.data();
    id_.jcn = cols_.data();
    run(1, "analyze");
    set_ordering(ordering_name(infog(id_, 7)));
  }

  void factorize_values() override {
    for (int attempt = 0;; ++attempt) {
      const double* all = matrix().valuePtr();
      for (std::size_t e = 0; e < passed_.size(); ++e) values_[e] = all[passed_[e]];
      id_.a = values_.data();
      id_.job = 2;
      dmumps_c(&id_);
      if (!is_workspace_error(infog(id_, 1)) || attempt == kMaxWorkspaceRetries) break;
      icntl(id_, 14) *= 2;  // more workspace relaxation (percent), kept for later steps
    }
    check("factorize");
  }

  int apply_inverse(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override {
    x = rhs;  // MUMPS overwrites the right-hand side with the solution
    id_.rhs = x.data();
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    run(3, "solve");
    return 0;
  }

  void run(int job, const char* phase) {
    id_.job = job;
    dmumps_c(&id_);
    check(phase);
  }

  void check(const char* phase) const {
    const int code = infog(id_, 1);
    if (code >= 0) return;
    throw NumericalError(std::string(phase) + ": mumps: " + describe_error(code) + " (INFOG(1) = " +
                         std::to_string(code) + ", INFOG(2) = " + std::to_string(infog(id_, 2)) + ")");
  }

  DMUMPS_STRUC_C id_{};
  std::vector<int> rows_, cols_;  // 1-based coordinates of the entries passed to MUMPS
  std::vector<int> passed_;       // their positions in the stored matrix's values
  std::vector<double> values_;    // their values
};

}  // namespace

std::unique_ptr<LinearSolver> make_mumps_solver(const LinearSolverOptions& options) {
  return std::make_unique<MumpsSolver>(options);
}

}  // namespace fairsurf::detail
