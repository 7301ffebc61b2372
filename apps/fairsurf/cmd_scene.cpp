// fairsurf scene: write one of the paper's scenes (scenes.h) for `fair` or `blend`.
#include <fairsurf/applications/scenes.h>
#include <fairsurf/io/io.h>

#include <cstdio>
#include <memory>

#include "command.h"

namespace fairsurf::cli {
namespace {

struct SceneArgs {
  std::string name, output;
  double edge_length = SceneOptions{}.edge_length;
  bool force = false;
};

void run_scene(const SceneArgs& args) {
  check_outputs("scene", {{"-o", args.output, OutputKind::mesh}}, {}, args.force);
  SceneOptions options;
  options.edge_length = args.edge_length;
  const Scene scene = make_scene(args.name, options);
  if (!scene.free_vertices.empty() && lower_extension(args.output) != ".ply")
    throw CliError(kUsage, "scene: " + args.name + " marks its free region with the vertex property 'free', "
                               "which only PLY carries; name the output .ply (got '" + args.output + "')");
  write_mesh_output(args.output, scene.mesh);
  std::printf("%s\n", scene.description.c_str());
  if (!scene.free_vertices.empty())
    std::printf("free region: %zu of %d vertices (vertex property 'free'; fairsurf fair %s -o OUT "
                "--region-property free)\n",
                scene.free_vertices.size(), scene.mesh.num_vertices(), args.output.c_str());
  else
    std::printf("loops to blend: %zu and %zu vertices (fairsurf blend %s -o OUT picks them)\n",
                scene.blend_loops[0].size(), scene.blend_loops[1].size(), args.output.c_str());
  std::printf("wrote %s: %d vertices, %d triangles\n", args.output.c_str(), scene.mesh.num_vertices(),
              scene.mesh.num_faces());
}

void setup_scene(CLI::App& app) {
  auto args = std::make_shared<SceneArgs>();
  CLI::App* cmd = app.add_subcommand("scene", "Write one of the paper's scenes: fig3, fig4, fig7, fig8, sphere-cap");
  cmd->add_option("name", args->name, "fig3, fig4 (blend), fig7, fig8, sphere-cap (fair)")->required();
  cmd->add_option("-o,--output", args->output, "Output mesh (.ply keeps the 'free' property)")->required();
  cmd->add_option("--edge-length", args->edge_length, "Target edge length in scene units (default 0.1)")
      ->check(positive_number());
  cmd->add_flag("--force", args->force, "Accepted for symmetry with the other commands (a scene has no input)");
  cmd->callback([args] { run_scene(*args); });
}

const CommandRegistration registration(70, setup_scene);

}  // namespace
}  // namespace fairsurf::cli
