// `fairsurf repair IN -o OUT [--json] [--force] [operation switches]`: runs repair (repair.h) and
// writes the result, then says what changed and which validation findings are left
// (docs/repair.md).
#include "command.h"
#include "repair_report.h"

#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/validate.h>

#include <iostream>
#include <memory>

namespace fairsurf::cli {
namespace {

struct RepairArgs {
  std::string input, output;
  bool json = false, force = false;
  bool no_merge = false, no_stitch = false, no_duplicate_faces = false, no_degenerate = false;
  bool no_split_vertices = false, no_resolve_edges = false, no_orient = false, keep_fins = false;
  bool keep_unreferenced = false;
  RepairOptions options;
};

RepairOptions repair_options(const RepairArgs& args) {
  RepairOptions o = args.options;
  o.merge_duplicate_vertices = !args.no_merge;
  o.stitch_borders = !args.no_stitch;
  o.remove_duplicate_faces = !args.no_duplicate_faces;
  o.fix_degenerate_faces = !args.no_degenerate;
  o.split_non_manifold_vertices = !args.no_split_vertices;
  o.resolve_non_manifold_edges = !args.no_resolve_edges;
  o.orient = !args.no_orient;
  o.remove_small_components = o.min_component_faces > 0;
  o.remove_loose_fins = !args.keep_fins;
  o.remove_unreferenced_vertices = !args.keep_unreferenced;
  return o;
}

// Findings of the output, as "2 inconsistently oriented edges, ..." / {key: count}.
std::string remaining_text(const ValidationReport& report) {
  std::string out;
  for (const auto& named : named_findings(report)) {
    const int n = named.finding->count;
    if (n > 0) out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + (n == 1 ? named.singular : named.plural);
  }
  return out.empty() ? "none" : out;
}

nlohmann::json remaining_json(const ValidationReport& report) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& named : named_findings(report))
    if (named.finding->count > 0) j[named.key] = named.finding->count;
  return j;
}

void run_repair(const RepairArgs& args) {
  check_outputs("repair", {{"-o", args.output, OutputKind::mesh}}, {args.input}, args.force);
  Mesh mesh = read_input(args.input);
  const RepairReport report = repair(mesh, repair_options(args));
  if (mesh.num_faces() == 0)
    throw InvalidMeshError("repair: " + args.input + " has no valid face, nothing to write");
  const ValidationReport left = validate(mesh);
  write_mesh_output(args.output, mesh);
  if (args.json) {
    nlohmann::json j = to_json(report);
    j["file"] = args.input;
    j["output"] = args.output;
    j["remaining_findings"] = remaining_json(left);
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << "repaired " << args.input << ": " << describe(report) << "; " << report.input_vertices << " -> "
            << report.output_vertices << " vertices, " << report.input_faces << " -> " << report.output_faces
            << " faces; findings left: " << remaining_text(left) << "; wrote " << args.output << "\n";
}

void setup_repair(CLI::App& app) {
  auto args = std::make_shared<RepairArgs>();
  CLI::App* cmd = app.add_subcommand(
      "repair", "Repair a mesh: merge, remove bad faces, split non-manifold parts, orient (docs/repair.md)");
  cmd->add_option("input", args->input, "Input mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("-o,--output", args->output, "Output mesh")->required();
  cmd->add_flag("--json", args->json, "Print the report as JSON");
  cmd->add_flag("--force", args->force, "Allow the output to overwrite the input");
  cmd->add_flag("--no-merge", args->no_merge, "Keep duplicate vertices apart");
  cmd->add_option("--merge-tolerance", args->options.merge_tolerance,
                  "Also merge vertices closer than this times the mean edge length (default 0: exact only)")
      ->check(non_negative_number());
  cmd->add_flag("--no-stitch", args->no_stitch, "Do not stitch coincident borders");
  cmd->add_option("--stitch-tolerance", args->options.stitch_tolerance,
                  "Stitch border vertices closer than this times the mean edge length (default 0: "
                  "coincident ones only)")
      ->check(non_negative_number());
  cmd->add_flag("--no-duplicate-faces", args->no_duplicate_faces, "Keep duplicate faces");
  cmd->add_flag("--no-degenerate", args->no_degenerate, "Keep zero-area and near-degenerate faces");
  cmd->add_option("--needle-tolerance", args->options.needle_tolerance,
                  "A degenerate face is a needle (collapsed) when its shortest edge is at most this "
                  "times its longest (default 1e-6); otherwise a cap (flipped)")
      ->check(non_negative_number());
  cmd->add_flag("--no-split-vertices", args->no_split_vertices, "Do not split non-manifold vertices");
  cmd->add_flag("--no-resolve-edges", args->no_resolve_edges, "Do not detach the extra faces of non-manifold edges");
  cmd->add_flag("--no-orient", args->no_orient, "Do not flip faces to a consistent orientation");
  cmd->add_option("--min-component-faces", args->options.min_component_faces,
                  "Remove components with fewer faces (default 2: lone triangles; 0 keeps all)")
      ->check(whole_number_at_least(0));
  cmd->add_flag("--keep-fins", args->keep_fins,
                "Keep loose fins: pieces with no vertex inside, and faces hanging by one edge, that a split "
                "cut loose from a surface");
  cmd->add_flag("--keep-unreferenced", args->keep_unreferenced, "Keep vertices no face uses");
  cmd->callback([args] { run_repair(*args); });
}

const CommandRegistration registration(85, setup_repair);

}  // namespace
}  // namespace fairsurf::cli
