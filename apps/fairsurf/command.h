// The CLI's plumbing: subcommand registration, exit codes, and the rules every command follows for
// input and output paths. The library computes; this layer talks (prints, maps errors to codes).
#pragma once

#include <fairsurf/errors.h>
#include <fairsurf/mesh.h>

#include <CLI/CLI.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace fairsurf::cli {

/// Documented exit codes (docs/cli.md).
enum ExitCode : int {
  kOk = 0,
  kUsage = 1,         ///< bad flags or arguments
  kInputError = 2,    ///< missing, unreadable, malformed or truncated input file
  kInvalidMesh = 3,   ///< the mesh fails a requirement of the command
  kNumerical = 4,     ///< a fit, a solve or a flow failed
  kOutputError = 5,   ///< output refused (would overwrite an input) or could not be written
};

/// Thrown by commands for a failure that belongs to the CLI itself (not the library).
class CliError : public std::runtime_error {
 public:
  CliError(ExitCode code, const std::string& message) : std::runtime_error(message), code(code) {}
  ExitCode code;
};

/// A subcommand adds itself to the parent app; `order` fixes its place in --help.
using CommandSetup = void (*)(CLI::App& app);
struct CommandRegistration {
  CommandRegistration(int order, CommandSetup setup);
};
std::vector<std::pair<int, CommandSetup>>& command_registry();

/// Refuses to write `output` over any of `inputs` unless `force`; throws CliError(kOutputError).
void check_output_path(const std::filesystem::path& output,
                       const std::vector<std::filesystem::path>& inputs, bool force);

/// Runs `write`, which writes one output file; an IoError from it becomes exit code 5 (an input
/// error would be 2).
template <class Write>
void write_output(Write&& write) {
  try {
    write();
  } catch (const IoError& e) {
    throw CliError(kOutputError, e.what());
  }
}

/// Reads a mesh with read_mesh and prints each of the reader's notes to standard error as
/// "fairsurf: note: PATH: ..." (fanned polygons, ignored lines, welded STL corners).
Mesh read_input(const std::string& path);

}  // namespace fairsurf::cli
