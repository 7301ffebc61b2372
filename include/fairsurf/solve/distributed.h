// fairsurf — the linear solves of one program spread over the ranks of an MPI job (the mumps-mpi
// solver, docs/solvers.md and docs/scaling.md).
//
// Rank 0 runs the program: it reads, assembles, steps, writes, and calls its solvers as usual. Every
// other rank only serves: Session::serve() repeats rank 0's MUMPS calls (create, analyze, factorize,
// solve, destroy), taking part in MUMPS's collective work and holding a share of the factors, until
// rank 0 calls finish(). A program is written once for both:
//
//   fairsurf::distributed::Session session(argc, argv);
//   if (session.is_worker()) return session.serve();
//   const int code = run_the_program();   // solvers of kind mumps_mpi use every rank
//   session.finish(code);
//   return code;
//
// In a build without MPI (FAIRSURF_MPI off), or started without mpirun, the session has one rank and
// changes nothing.
#pragma once

namespace fairsurf::distributed {

/// Whether this build has MPI and the mumps-mpi solver.
bool built_with_mpi();

class Session {
 public:
  /// Starts MPI when the process was started by an MPI launcher (mpirun, mpiexec) in a build with
  /// MPI; otherwise a one-rank session that starts nothing. One Session per process.
  Session(int& argc, char**& argv);
  /// Ends MPI if this session started it (rank 0 must have called finish()).
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_worker() const { return rank_ > 0; }

  /// Ranks > 0: serve rank 0's solver calls until it calls finish(); returns the exit code it
  /// passed. Throws if serving fails on this rank (the caller then reports and calls abort()).
  int serve();
  /// Rank 0: ends every worker's serve() with `exit_code`. Call once, after every mumps-mpi solver
  /// has been destroyed.
  void finish(int exit_code);
  /// Any rank: ends every rank of the job now with `exit_code`, for a failure the others cannot see.
  [[noreturn]] void abort(int exit_code);

 private:
  int rank_ = 0;
  int size_ = 1;
  bool started_mpi_ = false;
  bool finished_ = false;
};

}  // namespace fairsurf::distributed
