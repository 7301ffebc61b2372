// fairsurf — command-line entry point. Parses, runs one subcommand, maps failures to exit codes.
// Under `mpirun -n N`, rank 0 runs the command and the other ranks serve its mumps-mpi solves
// (distributed.h); every rank exits with rank 0's code.
#include "blas_threads.h"
#include "command.h"

#include <fairsurf/mesh/errors.h>
#include <fairsurf/solve/distributed.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

namespace {

int report(fairsurf::cli::ExitCode code, const char* what) {
  std::cerr << "fairsurf: error: " << what << "\n";
  return code;
}

// A parse error as one line, naming the command whose arguments were wrong and where to look.
int report_parse_error(const CLI::App& app, const CLI::ParseError& e) {
  std::string where = "fairsurf";
  for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) {
    sub = sub->get_subcommands().front();
    where += " " + sub->get_name();
  }
  std::cerr << "fairsurf: error: " << (where == "fairsurf" ? "" : where.substr(9) + ": ") << e.what() << " (see `"
            << where << " --help`)\n";
  return fairsurf::cli::kUsage;
}

// `fairsurf help [COMMAND]`: the same text as `fairsurf [COMMAND] --help`.
void add_help_command(CLI::App& app) {
  auto command = std::make_shared<std::string>();
  CLI::App* help = app.add_subcommand("help", "Print this help, or a command's: fairsurf help COMMAND");
  help->add_option("command", *command, "The command to describe");
  help->callback([&app, command] {
    if (command->empty()) {
      // app.help() would describe the selected subcommand, i.e. `help` itself.
      std::cout << app.get_formatter()->make_help(&app, "fairsurf", CLI::AppFormatMode::Normal);
      return;
    }
    for (const CLI::App* sub : app.get_subcommands({}))
      if (sub->get_name() == *command) {
        std::cout << sub->help();
        return;
      }
    throw fairsurf::cli::CliError(fairsurf::cli::kUsage, "help: unknown command '" + *command + "'");
  });
}

int run(int argc, char** argv) {
  using namespace fairsurf::cli;
  CLI::App app{"fairsurf: fair surfaces on triangle meshes with sixth-order geometric flows"};
  app.set_version_flag("--version", FAIRSURF_VERSION);
  app.require_subcommand(0, 1);
  app.footer("Threads: OpenMP loops follow OMP_NUM_THREADS; OpenBLAS runs one thread unless OPENBLAS_NUM_THREADS, "
             "GOTO_NUM_THREADS or OMP_NUM_THREADS is set (docs/cli.md, Threads).");
  auto& registry = command_registry();
  std::sort(registry.begin(), registry.end());
  for (const auto& entry : registry) entry.second(app);
  add_help_command(app);

  try {
    app.parse(argc, argv);
    if (app.get_subcommands().empty()) throw CliError(kUsage, "a command is required (`fairsurf help` lists them)");
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) return report_parse_error(app, e);
    return app.exit(e);  // --help, --version
  } catch (const CliError& e) {
    return report(e.code, e.what());
  } catch (const fairsurf::InvalidArgument& e) {
    return report(kUsage, e.what());
  } catch (const fairsurf::IoError& e) {
    return report(kInputError, e.what());
  } catch (const fairsurf::RepairableMeshError& e) {
    const std::string message = std::string(e.what()) + " (run with --repair, or `fairsurf repair`)";
    return report(kInvalidMesh, message.c_str());
  } catch (const fairsurf::InvalidMeshError& e) {
    return report(kInvalidMesh, e.what());
  } catch (const fairsurf::NumericalError& e) {
    return report(kNumerical, e.what());
  } catch (const std::bad_alloc&) {
    return report(kNumerical, "out of memory");
  } catch (const std::exception& e) {
    return report(kNumerical, e.what());
  }
  return kOk;
}

// A rank > 0: serves rank 0's solves and exits with its code. A failure only this rank sees (rank 0
// waits for it in a collective call) ends the whole job.
int serve(fairsurf::distributed::Session& session) {
  try {
    return session.serve();
  } catch (const std::exception& e) {
    std::cerr << "fairsurf: error: rank " << session.rank() << ": " << e.what() << "\n";
    session.abort(fairsurf::cli::kNumerical);
  }
}

}  // namespace

int main(int argc, char** argv) {
  fairsurf::cli::use_one_blas_thread_unless_asked();
  fairsurf::distributed::Session session(argc, argv);
  if (session.is_worker()) return serve(session);
  const int code = run(argc, argv);
  session.finish(code);
  return code;
}
