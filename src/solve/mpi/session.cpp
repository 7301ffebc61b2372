// fairsurf — distributed::Session in MPI builds: starting and ending MPI, and the serving ranks' loop.
#include <fairsurf/mesh/errors.h>
#include <fairsurf/solve/distributed.h>

#include "../mumps_instance.h"
#include "cluster.h"

#include <cstdlib>
#include <map>
#include <memory>

namespace fairsurf::distributed {

namespace {

using detail::ServeCommand;

using Instances = std::map<int, std::unique_ptr<detail::MumpsInstance>>;

// Runs one of rank 0's MUMPS jobs on this rank's copy of the instance.
void serve_job(Instances& instances, const ServeCommand& command) {
  if (command.job == -1) {
    try {
      instances[command.instance] = std::make_unique<detail::MumpsInstance>(detail::MumpsSettings{
          .communicator = MPI_Comm_c2f(MPI_COMM_WORLD), .sym = command.sym, .ordering = command.ordering});
    } catch (const NumericalError&) {
      // INFOG(1) is global: rank 0 failed the same way, reports it and never uses this instance.
    }
    return;
  }
  if (command.job == -2) {
    instances.erase(command.instance);
    return;
  }
  detail::MumpsInstance& instance = *instances.at(command.instance);
  if (command.job == 2) instance.icntl(14) = command.workspace_relaxation;
  instance.call(command.job);  // a failure is global too: rank 0 throws it
}

}  // namespace

bool built_with_mpi() { return true; }

Session::Session(int& argc, char**& argv) {
  if (!detail::launched_by_mpirun()) return;  // one process: MPI starts only if a MUMPS solver needs it
  started_mpi_ = detail::start_mpi(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm_dup(MPI_COMM_WORLD, &detail::cluster().control);
}

Session::~Session() {
  if (detail::cluster().control == MPI_COMM_NULL) return;
  if (!is_worker() && !finished_) finish(1);  // an exception left rank 0's program: no success
  MPI_Comm_free(&detail::cluster().control);
  if (started_mpi_) MPI_Finalize();
}

int Session::serve() {
  if (!is_worker()) return 0;
  Instances instances;
  for (;;) {
    ServeCommand command;
    detail::broadcast(command);
    if (command.job == detail::kFinishJob) {
      // Rank 0 destroyed its solvers first; any left here are never freed collectively again.
      for (auto& entry : instances) static_cast<void>(entry.second.release());
      return command.exit_code;
    }
    serve_job(instances, command);
  }
}

void Session::finish(int exit_code) {
  finished_ = true;
  if (detail::cluster().control == MPI_COMM_NULL) return;
  ServeCommand command{.job = detail::kFinishJob, .exit_code = exit_code};
  detail::broadcast(command);
}

void Session::abort(int exit_code) {
  int running = 0;
  MPI_Initialized(&running);
  if (running) MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::exit(exit_code);
}

}  // namespace fairsurf::distributed
