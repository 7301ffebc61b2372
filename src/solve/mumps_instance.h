// fairsurf — private: one MUMPS instance (DMUMPS_STRUC_C) with the library's settings, shared by the
// mumps and mumps-mpi back ends (linear_solver_mumps.cpp) and by the ranks that serve mumps-mpi
// (distributed.h): every process of an instance must make the same calls in the same order.
#pragma once

#include <fairsurf/solve/linear_solver.h>

#include <dmumps_c.h>

#include <map>
#include <string>

namespace fairsurf::detail {

/// MumpsSettings::ordering for FillOrdering::nested_dissection: resolved at each analysis by
/// MumpsInstance::choose_ordering.
inline constexpr int kNestedDissection = 7;
/// Up to this many unknowns MUMPS's own choice is a minimum degree ordering (AMF or QAMD; its
/// threshold for unsymmetric matrices).
inline constexpr int kLargestMinimumDegreeSystem = 5000;

/// What every process of one instance is created with.
struct MumpsSettings {
  int communicator = 0;  ///< Fortran handle of the processes' communicator
  int sym = 0;           ///< 0: unsymmetric LU; 2: general symmetric LDLᵀ
  /// ICNTL(7) asked for: 6 QAMD, or kNestedDissection (MumpsInstance::choose_ordering)
  int ordering = kNestedDissection;
  const char* name = "mumps";  ///< the back end, for messages
  std::map<int, int> controls{};  ///< LinearSolverOptions::mumps_controls, set after the library's
};

/// The settings `options` ask for (symmetric: LDLᵀ; minimum_degree: QAMD), named after options.kind.
MumpsSettings mumps_settings(const LinearSolverOptions& options, int communicator);

/// MUMPS's codes for "increase the workspace and retry" (INFOG(1) = −8, −9, −14, −15, −17, −20).
bool is_workspace_error(int code);
/// "SCOTCH", "QAMD", ... for INFOG(7).
std::string ordering_name(int code);

class MumpsInstance {
 public:
  /// Initializes (job −1) silent (ICNTL(1..4): the library never prints), with the host taking
  /// part in the factorization (PAR = 1), a centralized matrix on the host (ICNTL(18) = 0) and
  /// sequential analysis there (ICNTL(28) = 1). Throws NumericalError if MUMPS refuses.
  explicit MumpsInstance(const MumpsSettings& settings);
  ~MumpsInstance();  // job −2
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;

  DMUMPS_STRUC_C& id() { return id_; }
  /// ICNTL(k), INFO(k), INFOG(k) in the 1-based numbering of the MUMPS manual.
  int& icntl(int k) { return id_.icntl[k - 1]; }
  int info(int k) const { return id_.info[k - 1]; }
  int infog(int k) const { return id_.infog[k - 1]; }

  /// Sets ICNTL(7) for an analysis of `unknowns` unknowns, unless the caller's controls set it. For
  /// kNestedDissection: MUMPS's own choice (AMF or QAMD) up to kLargestMinimumDegreeSystem unknowns,
  /// PORD above. MUMPS would take SCOTCH there, which Debian's build seeds from the clock, so the same
  /// matrix was ordered, hence rounded, differently in every run; PORD is deterministic and as good on
  /// the step matrix (docs/solvers.md, "Orderings"), but on tiny graphs it can fail and exit the process
  /// (a 4 by 4 matrix: "no valid number of stages in multisector"), so it is kept for large systems.
  void choose_ordering(int unknowns);

  /// Runs MUMPS's `job` (1 analyze, 2 factorize, 3 solve); returns INFOG(1), the same on every rank.
  int call(int job);
  /// Throws NumericalError "PHASE: NAME: <reason> (INFOG(1) = …, INFOG(2) = …)" if INFOG(1) < 0.
  void check(const char* phase) const;

 private:
  DMUMPS_STRUC_C id_{};
  const char* name_;
  int ordering_;         ///< MumpsSettings::ordering
  bool ordering_given_;  ///< the caller's controls set ICNTL(7)
};

}  // namespace fairsurf::detail
