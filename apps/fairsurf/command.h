// The CLI's plumbing: subcommand registration, exit codes, and the rules every command follows for
// input and output paths. The library computes; this layer talks (prints, maps errors to codes).
#pragma once

#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/solve/linear_solver.h>

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
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

/// The extension of `path` in lower case, with its dot (".ply"); formats are chosen by it.
std::string lower_extension(const std::filesystem::path& path);

/// What a command writes to a path: a mesh (.obj, .off, .ply, .stl), a PNG image, or a JSON log.
enum class OutputKind { mesh, png, json };
struct Output {
  std::string option;  ///< the flag that named it, for messages ("-o", "--log")
  std::string path;    ///< empty: not asked for, nothing to check
  OutputKind kind;
};

/// Checks every output of a command before any work, so that no run is thrown away at the end:
/// an extension the writer knows (exit 1), an existing writable directory and no directory at the
/// path itself (exit 5), no two outputs on one file (exit 1), and none over one of `inputs` (every
/// file the command reads: meshes, --fixed-vertices, --region; empty paths are skipped) unless `force` (exit 5).
void check_outputs(const std::string& command, const std::vector<Output>& outputs,
                   const std::vector<std::filesystem::path>& inputs, bool force);

/// CLI11 checks for numeric options; each names the valid range and the value given, e.g.
/// "--steps: must be a whole number >= 1 (got 0)".
/// The number in `text` if all of it is one (std::stod's syntax), else nothing.
std::optional<double> number_in(const std::string& text);

CLI::Validator whole_number_at_least(int lowest);
CLI::Validator positive_number();      ///< finite and > 0
CLI::Validator non_negative_number();  ///< finite and >= 0

/// The per-vertex properties derived from the shape (`fairsurf curvature` writes them): stale as
/// soon as a vertex moves.
inline const std::vector<std::string> kShapeProperties{"H", "K", "k1", "k2", "fit_status"};

/// For commands that move vertices: drops kShapeProperties from `mesh` and says so on standard error
/// ("fairsurf: note: PATH: dropped ..."), so that no output carries curvatures of the old shape.
void drop_shape_properties(Mesh& mesh, const std::string& path);

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

// Flags are named after the option field they set (docs/cli.md, "Flags and the fields they set");
// a flag's earlier name stays as its alias, so that old scripts keep working.

/// Adds --functions (alias --f) to `cmd`: the energy functions f_l of the sixth-order flow
/// (FlowOptions::functions), one per occurrence.
void add_functions_option(CLI::App* cmd, std::vector<std::string>& functions);
/// --other-functions F (repeatable): fill's and fair's FairRegionOptions::held_out_other_functions.
void add_other_functions_option(CLI::App* cmd, std::vector<std::string>& functions);

/// --solver and --mumps-controls, shared by the commands that solve.
struct SolverArgs {
  std::string name = "mumps";
  std::vector<std::string> mumps_controls;  ///< "K=V" each
};
/// Adds --solver to `cmd`: mumps (the default; also "lu"), umfpack, gmres, or mumps-mpi (the factors
/// spread over the ranks of `mpirun -n N fairsurf ...`, docs/solvers.md); and --mumps-controls K=V
/// (alias --mumps-icntl), repeatable, MUMPS's own controls passed through
/// (LinearSolverOptions::mumps_controls).
void add_solver_options(CLI::App* cmd, SolverArgs& args);
/// Sets the kind and MUMPS controls of `options` (keeping its ordering). InvalidArgument (exit 1) for
/// an unknown solver, mumps-mpi in a build without MPI, or a malformed --mumps-controls.
void apply_solver_args(const SolverArgs& args, LinearSolverOptions& options);

/// Whether `mesh` carries PLY vertex properties or colours.
bool has_vertex_data(const Mesh& mesh);

/// For fill and blend, which drop every vertex property and colour once they add vertices (the new
/// ones have no values): says so on standard error when the input had some and the output has none.
void note_vertex_data_dropped(bool input_had, const Mesh& output, const std::string& path,
                              const std::string& command);

/// Reads a mesh with read_mesh and prints each of the reader's notes to standard error as
/// "fairsurf: note: PATH: ..." (fanned polygons, ignored lines, welded STL corners).
Mesh read_input(const std::string& path);

/// Writes `mesh` to `path` as write_output does (exit 5 on failure) and prints each of the writer's
/// notes, what the format cannot hold, as "fairsurf: note: PATH: ..."; or, if `notes` is given (a
/// command whose output is JSON), appends them there instead.
void write_mesh_output(const std::string& path, const Mesh& mesh, const WriteOptions& options = {},
                       std::vector<std::string>* notes = nullptr);

/// For commands that move vertices: recomputes the stored normals of the moved vertices
/// (refresh_moved_normals; `before` the positions they belonged to, empty for none) and says so
/// ("fairsurf: note: PATH: recomputed N of M normals ...").
void refresh_normals(Mesh& mesh, const Vertices& before, const std::string& path);

/// For fill and blend, whose new faces have no texture coordinates, normals or polygon: says so
/// when the input's faces (the first `input_faces`) have some.
void note_new_faces(const Mesh& mesh, int input_faces, const std::string& path, const std::string& command);

}  // namespace fairsurf::cli
