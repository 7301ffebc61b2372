#include "command.h"

#include <fairsurf/io/io.h>
#include <fairsurf/mesh/mesh_attributes.h>
#include <fairsurf/solve/distributed.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <iostream>
#include <optional>
#include <system_error>

namespace fairsurf::cli {

std::vector<std::pair<int, CommandSetup>>& command_registry() {
  static std::vector<std::pair<int, CommandSetup>> registry;
  return registry;
}

CommandRegistration::CommandRegistration(int order, CommandSetup setup) {
  command_registry().emplace_back(order, setup);
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

namespace {

// One file under two names: the same target of links, or the same path once resolved (an output
// usually does not exist yet, so `equivalent` alone cannot tell).
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec_equivalent, ec_a, ec_b;
  if (std::filesystem::equivalent(a, b, ec_equivalent) && !ec_equivalent) return true;
  const auto resolved_a = std::filesystem::weakly_canonical(std::filesystem::absolute(a), ec_a);
  const auto resolved_b = std::filesystem::weakly_canonical(std::filesystem::absolute(b), ec_b);
  return !ec_a && !ec_b && resolved_a == resolved_b;
}

void check_extension(const std::string& command, const Output& out) {
  const std::string ext = lower_extension(out.path);
  if (out.kind == OutputKind::mesh && ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw CliError(kUsage, command + ": " + out.option + " '" + out.path +
                               "': unknown mesh extension (supported: .obj, .off, .ply, .stl)");
  if (out.kind == OutputKind::png && ext != ".png")
    throw CliError(kUsage, command + ": " + out.option + " '" + out.path +
                               "': render writes PNG images only; name the output .png");
}

void check_directory(const std::string& command, const Output& out) {
  const std::filesystem::path path(out.path);
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw CliError(kOutputError, command + ": " + out.option + " '" + out.path + "' is a directory");
  if (!std::filesystem::is_directory(dir, ec))
    throw CliError(kOutputError, command + ": " + out.option + " '" + out.path + "': the directory '" +
                                     dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw CliError(kOutputError, command + ": " + out.option + " '" + out.path + "': cannot write in '" +
                                     dir.string() + "' (" + std::strerror(errno) + ")");
}

}  // namespace

void check_outputs(const std::string& command, const std::vector<Output>& outputs,
                   const std::vector<std::filesystem::path>& inputs, bool force) {
  std::vector<Output> given;
  for (const Output& out : outputs)
    if (!out.path.empty()) given.push_back(out);
  for (const Output& out : given) check_extension(command, out);
  for (std::size_t i = 0; i < given.size(); ++i)
    for (std::size_t j = i + 1; j < given.size(); ++j)
      if (same_file(given[i].path, given[j].path))
        throw CliError(kUsage, command + ": " + given[i].option + " and " + given[j].option +
                                   " name the same file '" + given[j].path + "'");
  for (const Output& out : given)
    for (const auto& input : inputs)
      if (!force && !input.empty() && same_file(out.path, input))
        throw CliError(kOutputError, command + ": " + out.option + " would overwrite the input '" +
                                         input.string() + "' (pass --force to allow it)");
  for (const Output& out : given) check_directory(command, out);
}

std::optional<double> number_in(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::logic_error&) {
  }
  return std::nullopt;
}

CLI::Validator whole_number_at_least(int lowest) {
  const std::string range = "a whole number >= " + std::to_string(lowest);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto value = number_in(text);
        if (value && *value == std::floor(*value) && *value >= lowest && *value <= INT_MAX) return "";
        return "must be " + range + " (got '" + text + "')";
      },
      range);
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto value = number_in(text);
        if (value && std::isfinite(*value) && *value > 0) return "";
        return "must be a finite number > 0 (got '" + text + "')";
      },
      "a number > 0");
}

CLI::Validator non_negative_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto value = number_in(text);
        if (value && std::isfinite(*value) && *value >= 0) return "";
        return "must be a finite number >= 0 (got '" + text + "')";
      },
      "a number >= 0");
}

void drop_shape_properties(Mesh& mesh, const std::string& path) {
  std::string dropped;
  for (const std::string& name : kShapeProperties)
    if (mesh.vertex_scalars.erase(name) > 0) dropped += (dropped.empty() ? "" : ", ") + name;
  if (!dropped.empty())
    std::cerr << "fairsurf: note: " << path << ": dropped the vertex properties " << dropped
              << " (curvatures of the input's shape, stale once vertices move; run `fairsurf curvature` "
                 "on the output)\n";
}

void add_functions_option(CLI::App* cmd, std::vector<std::string>& functions) {
  cmd->add_option("--functions,--f", functions,
                  "Energy function(s) f(H,K) of the sixth-order flow, repeatable, one per --functions: H "
                  "(default), K, H2, absHpH:p, 4absHH+2K, k1, k2 or a formula in H and K (which may use eps and kappa, "
                  "the curvature scale: docs/energies.md)")
      ->allow_extra_args(false);
}

void add_other_functions_option(CLI::App* cmd, std::vector<std::string>& functions) {
  cmd->add_option("--other-functions", functions,
                  "Also weigh the flow with these energy functions on the held-out rings, one per "
                  "--other-functions, and run it with them where they predict the rings better (e.g. "
                  "--other-functions H --other-functions K/kappa; docs/fill.md)")
      ->allow_extra_args(false);
}

void add_solver_options(CLI::App* cmd, SolverArgs& args) {
  cmd->add_option("--solver", args.name,
                  "Linear solver: mumps (default, also 'lu'), umfpack, gmres, or mumps-mpi (MUMPS with its "
                  "factors on every rank of `mpirun -n N fairsurf ...`)");
  cmd->add_option("--mumps-controls,--mumps-icntl", args.mumps_controls,
                  "K=V: set MUMPS's control ICNTL(K) to V (mumps, mumps-mpi; repeatable; e.g. 7=0 for AMD, "
                  "28=2 for a parallel analysis)")
      ->allow_extra_args(false);
}

namespace {

// "K=V" as the pair (K, V), both whole numbers.
std::pair<int, int> mumps_control(const std::string& text) {
  const auto equals = text.find('=');
  const auto k = number_in(text.substr(0, equals));
  const auto v = equals == std::string::npos ? std::nullopt : number_in(text.substr(equals + 1));
  if (!k || !v || *k != std::floor(*k) || *v != std::floor(*v) || std::abs(*k) > INT_MAX || std::abs(*v) > INT_MAX)
    throw InvalidArgument("--mumps-controls: expected K=V with whole numbers, e.g. 7=0 (got '" + text + "')");
  return {static_cast<int>(*k), static_cast<int>(*v)};
}

}  // namespace

void apply_solver_args(const SolverArgs& args, LinearSolverOptions& options) {
  options.kind = parse_linear_solver_kind(args.name == "lu" ? "mumps" : args.name);
  if (options.kind == LinearSolverKind::mumps_mpi && !distributed::built_with_mpi())
    throw InvalidArgument(
        "--solver mumps-mpi: this fairsurf was built without MPI (configure with -DFAIRSURF_MPI=ON, with "
        "openmpi-bin, libopenmpi-dev and libmumps-ptscotch-dev installed); use --solver mumps");
  for (const std::string& text : args.mumps_controls) options.mumps_controls.insert(mumps_control(text));
}

bool has_vertex_data(const Mesh& mesh) { return !mesh.vertex_scalars.empty() || mesh.vertex_colors.rows() > 0; }

void note_vertex_data_dropped(bool input_had, const Mesh& output, const std::string& path,
                              const std::string& command) {
  if (input_had && !has_vertex_data(output))
    std::cerr << "fairsurf: note: " << path << ": the output has no vertex properties or colours: the new "
              << "vertices have none, so " << command << " drops them all\n";
}

void write_mesh_output(const std::string& path, const Mesh& mesh, const WriteOptions& options,
                       std::vector<std::string>* notes) {
  WriteReport report;
  write_output([&] { write_mesh(path, mesh, options, &report); });
  if (notes) notes->insert(notes->end(), report.notes.begin(), report.notes.end());
  else
    for (const auto& note : report.notes) std::cerr << "fairsurf: note: " << path << ": " << note << "\n";
}

void refresh_normals(Mesh& mesh, const Vertices& before, const std::string& path) {
  if (before.rows() == 0 || mesh.FN.rows() == 0) return;
  const int recomputed = refresh_moved_normals(mesh, before);
  if (recomputed > 0)
    std::cerr << "fairsurf: note: " << path << ": recomputed " << recomputed << " of " << mesh.N.rows()
              << " normals from the faces around them: their vertices moved\n";
}

void note_new_faces(const Mesh& mesh, int input_faces, const std::string& path, const std::string& command) {
  const int added = mesh.num_faces() - input_faces;
  std::string lacking;
  if (mesh.FTC.rows() > 0) lacking = "texture coordinates";
  if (mesh.FN.rows() > 0) lacking += lacking.empty() ? "normals" : " or normals";
  if (added <= 0 || lacking.empty()) return;
  std::cerr << "fairsurf: note: " << path << ": the " << added << " faces " << command << " added have no "
            << lacking << "; the input's faces keep theirs\n";
}

Mesh read_input(const std::string& path) {
  ReadReport report;
  Mesh mesh = read_mesh(path, &report);
  for (const auto& note : report.notes) std::cerr << "fairsurf: note: " << path << ": " << note << "\n";
  return mesh;
}

}  // namespace fairsurf::cli
