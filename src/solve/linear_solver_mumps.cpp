// fairsurf — the MUMPS back ends: MUMPS LU with a deterministic ordering (PORD or QAMD), on this
// process alone (mumps) or with the factors spread over MPI ranks that follow this one's calls
// (mumps-mpi, MumpsTeam).
//
// MUMPS takes the matrix as 1-based coordinates (irn, jcn, a), centralized on this process (the
// host). The row-major CSR order of the stored matrix is a valid coordinate order, so the index
// arrays are built once at analysis, and an unsymmetric factorization reads the stored values in
// place (MUMPS never writes `a`); only LDLᵀ copies the lower triangle's values. On the host of a
// distributed solve that copy would be 12 bytes a non-zero beside the factors (docs/scaling.md).
#include "linear_solver_backends.h"
#include "mumps_instance.h"

#include <optional>
#include <string>
#include <vector>

namespace fairsurf::detail {

namespace {

constexpr int kMaxWorkspaceRetries = 4;

class MumpsSolver final : public LinearSolver {
 public:
  MumpsSolver(const LinearSolverOptions& options, MumpsTeam team) : LinearSolver(options), team_(std::move(team)) {
    team_.announce(-1, 0);
    instance_.emplace(mumps_settings(options, team_.communicator));
  }

  ~MumpsSolver() override {
    team_.announce(-2, 0);
    instance_.reset();
  }

 private:
  void analyze_pattern() override {
    const SparseRowMatrix& A = matrix();
    rows_.clear();
    cols_.clear();
    passed_.clear();
    const bool lower_only = options().symmetric;  // MUMPS would add (j, i) to (i, j)
    for (int i = 0; i < A.outerSize(); ++i)
      for (int k = A.outerIndexPtr()[i]; k < A.outerIndexPtr()[i + 1]; ++k) {
        const int j = A.innerIndexPtr()[k];
        if (lower_only && j > i) continue;
        rows_.push_back(i + 1);
        cols_.push_back(j + 1);
        if (lower_only) passed_.push_back(k);
      }
    values_.resize(passed_.size());
    DMUMPS_STRUC_C& id = instance_->id();
    id.n = static_cast<int>(A.rows());
    id.nnz = static_cast<MUMPS_INT8>(rows_.size());
    id.irn = rows_.data();
    id.jcn = cols_.data();
    instance_->choose_ordering(id.n);
    run(1, "analyze");
    set_ordering(ordering_name(instance_->infog(7)));
  }

  void factorize_values() override {
    const double* all = matrix().valuePtr();
    if (options().symmetric) {
      for (std::size_t e = 0; e < passed_.size(); ++e) values_[e] = all[passed_[e]];
      instance_->id().a = values_.data();
    } else {
      instance_->id().a = const_cast<double*>(all);  // dmumps_c's struct is not const-correct
    }
    for (int attempt = 0;; ++attempt) {
      team_.announce(2, instance_->icntl(14));
      const int code = instance_->call(2);
      if (!is_workspace_error(code) || attempt == kMaxWorkspaceRetries) break;
      instance_->icntl(14) *= 2;  // more workspace relaxation (percent), kept for later steps
    }
    instance_->check("factorize");
    set_factor_memory(instance_->infog(21), instance_->infog(22));
  }

  int apply_inverse(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override {
    x = rhs;  // MUMPS overwrites the right-hand side with the solution
    DMUMPS_STRUC_C& id = instance_->id();
    id.rhs = x.data();
    id.nrhs = 1;
    id.lrhs = id.n;
    run(3, "solve");
    return 0;
  }

  void run(int job, const char* phase) {
    team_.announce(job, 0);
    instance_->call(job);
    instance_->check(phase);
  }

  MumpsTeam team_;
  std::optional<MumpsInstance> instance_;  // created after the team heard of it, destroyed before
  std::vector<int> rows_, cols_;  // 1-based coordinates of the entries passed to MUMPS
  std::vector<int> passed_;       // LDLᵀ: their positions in the stored matrix's values
  std::vector<double> values_;    // LDLᵀ: their values
};

}  // namespace

std::unique_ptr<LinearSolver> make_mumps_solver(const LinearSolverOptions& options, MumpsTeam team) {
  return std::make_unique<MumpsSolver>(options, std::move(team));
}

std::unique_ptr<LinearSolver> make_mumps_solver(const LinearSolverOptions& options) {
  return make_mumps_solver(options, MumpsTeam{.communicator = mumps_self_communicator()});
}

}  // namespace fairsurf::detail
