// `fairsurf convert IN -o OUT [--ascii] [--force]`: reads a mesh in one format and writes it in
// another (formats by extension), reporting what reading ignored or repaired.
#include "command.h"

#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>

#include <iostream>
#include <memory>

namespace fairsurf::cli {
namespace {

struct ConvertArgs {
  std::string input;
  std::string output;
  bool ascii = false;
  bool force = false;
};

void run_convert(const ConvertArgs& args) {
  check_outputs("convert", {{"-o", args.output, OutputKind::mesh}}, {args.input}, args.force);
  const Mesh mesh = read_input(args.input);
  WriteOptions options;
  options.binary = !args.ascii;
  write_mesh_output(args.output, mesh, options);
  if (lower_extension(args.output) == ".stl")
    std::cout << "wrote " << args.output << ": " << mesh.num_faces()
              << " triangles (STL stores 3 corners per triangle, no shared vertices)\n";
  else
    std::cout << "wrote " << args.output << ": " << mesh.num_vertices() << " vertices, " << mesh.num_faces()
              << " triangles\n";
}

void setup_convert(CLI::App& app) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a mesh between OBJ, OFF, PLY and STL (by extension)");
  cmd->add_option("input", args->input, "Input mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("-o,--output", args->output, "Output mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_flag("--ascii", args->ascii, "Write PLY and STL as ASCII instead of binary");
  cmd->add_flag("--force", args->force, "Allow the output to overwrite the input");
  cmd->callback([args] { run_convert(*args); });
}

const CommandRegistration registration(90, setup_convert);

}  // namespace
}  // namespace fairsurf::cli
