// fairsurf blend: join two boundary loops (of one mesh, or of two meshes) by a fair tube (blend.h).
#include <fairsurf/applications/blend.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "command.h"
#include "flow_log.h"
#include "region_fairing_args.h"
#include "repair_report.h"

namespace fairsurf::cli {
namespace {

constexpr double kDegrees = 180.0 / M_PI;

struct BlendArgs {
  std::vector<std::string> inputs;
  std::string output;
  std::vector<int> loops;
  bool no_relax = false;
  bool no_descent_fallback = false;
  bool keep_flow = false;
  bool all = false;
  RegionFairingArgs fairing;
};

BlendOptions blend_options(const BlendArgs& args) {
  BlendOptions o;
  apply_region_fairing_args(args.fairing, o);
  o.patch.relax = !args.no_relax;
  apply_solver_args(args.fairing.solver, o.patch.solver);
  o.descent_fallback = !args.no_descent_fallback;
  apply_keep_flow(args.keep_flow, "blend", o);
  if (!args.loops.empty()) {
    o.loop_a = args.loops[0];
    o.loop_b = args.loops[1];
  }
  return o;
}

std::string border_text(const char* name, const BlendLoop& loop) {
  char text[300];
  std::snprintf(text, sizeof text,
                "loop %s = %d (%d vertices): max normal angle %.3g°, max H jump %.3g "
                "(the same fits on the untouched input read %.3g°, %.3g)",
                name, loop.index, loop.length, loop.border.max_normal_angle * kDegrees,
                loop.border.max_mean_curvature_jump, loop.reference.max_normal_angle * kDegrees,
                loop.reference.max_mean_curvature_jump);
  return text;
}

// A tube that folds back at a loop (blend.h's folds_back; spot 1519 z: 147° against 12.5°) is
// written; the user is told.
void warn_if_folded_back(const char* name, const BlendLoop& loop) {
  if (!folds_back(loop)) return;
  std::fprintf(stderr,
               "fairsurf: warning: the tube folds back at loop %s = %d: it turns the normal across the loop by "
               "%.3g° where the untouched input reads %.3g°; the two loops may not face each other (choose "
               "others with --loops; docs/blend.md)\n",
               name, loop.index, loop.border.max_normal_angle * kDegrees, loop.reference.max_normal_angle * kDegrees);
}

// "from the membrane", "from the Hermite tube (the membrane pinched off)", ...: what the tube
// written started from, and why not from the membrane where it could have.
std::string tube_start(const BlendReport& report, bool no_relax) {
  const std::string rings = report.straight_rings ? "the tube of straight rings (the Hermite tube crossed the mesh)"
                                                   : "the Hermite tube";
  if (report.relaxed) return "from the membrane" + (report.straight_rings ? " of " + rings : std::string());
  if (no_relax) return "from " + rings;
  if (report.rebuilt_without_membrane) return "from " + rings + " (built again without the membrane)";
  return "from " + rings + " (the membrane pinched off)";
}

nlohmann::json loop_json(const BlendLoop& loop) {
  return {{"index", loop.index},
          {"length", loop.length},
          {"continuity_measured", to_json(loop.border)},
          {"continuity_reference", to_json(loop.reference)}};
}

nlohmann::json report_json(const BlendReport& report) {
  return {{"loops_found", report.loops_found},
          {"automatic", report.automatic},
          {"loop_distance", report.loop_distance},
          {"loop_a", loop_json(report.a)},
          {"loop_b", loop_json(report.b)},
          {"tube_vertices", report.tube_vertices},
          {"tube_faces", report.tube_faces},
          {"tube_rings", report.tube_rings},
          {"hermite_quality", report.hermite_quality},
          {"membrane_quality", report.membrane_quality},
          {"relaxed", report.relaxed},
          {"straight_rings", report.straight_rings},
          {"rebuilt_without_membrane", report.rebuilt_without_membrane},
          {"fair", to_json(report.fair)},
          {"seconds", report.seconds}};
}

nlohmann::json unjoined_json(const UnjoinedLoops& pair) {
  return {{"loop_a", pair.loop_a}, {"loop_b", pair.loop_b}, {"length_a", pair.length_a},
          {"length_b", pair.length_b}, {"why", pair.why}, {"repairable", pair.repairable}};
}

// A single blend's report as blend --all's.
BlendAllReport one_blend(BlendReport blend) {
  BlendAllReport all;
  all.loops_left = blend.loops_found - 2;
  all.seconds = blend.seconds;
  all.blends.push_back(std::move(blend));
  return all;
}

// blend --all: the pairs that could not be joined, and the loops no other loop was left to join.
void print_left_open(const BlendAllReport& all) {
  for (const UnjoinedLoops& pair : all.unjoined)
    std::printf("loops %d and %d of the output (%d and %d vertices) stay open: %s\n", pair.loop_a, pair.loop_b,
                pair.length_a, pair.length_b, pair.why.c_str());
  const int alone = all.loops_left - 2 * static_cast<int>(all.unjoined.size());
  if (alone > 0) std::printf("%d loop left open: no other loop to join it to\n", alone);
}

// Where a pair could not be joined because its loops touch or pinch at a vertex: what repairs it.
std::string repair_hint(const BlendAllReport& all) {
  for (const UnjoinedLoops& pair : all.unjoined)
    if (pair.repairable) return "; loops that touch at a vertex: run with --repair, or `fairsurf repair`";
  return "";
}

// The three lines of one blend's summary: the pair, the tube and its fairing, each loop's border.
void print_blend(const BlendReport& report, bool no_relax) {
  const std::string start = tube_start(report, no_relax);
  std::printf("blended loops %d and %d of %d%s: tube of %d vertices, %d faces, %s; %s\n  %s\n  %s\n", report.a.index,
              report.b.index, report.loops_found, report.automatic ? " (closest pair)" : "", report.tube_vertices,
              report.tube_faces, start.c_str(), summary(report.fair).c_str(), border_text("a", report.a).c_str(),
              border_text("b", report.b).c_str());
}

void run_blend(const BlendArgs& args) {
  const RegionFairingArgs& f = args.fairing;
  const std::vector<std::filesystem::path> inputs(args.inputs.begin(), args.inputs.end());
  check_outputs("blend", {{"-o", args.output, OutputKind::mesh}, {"--log", f.log, OutputKind::json}}, inputs,
                f.force);
  const BlendOptions options = blend_options(args);
  Mesh mesh = read_input(args.inputs[0]);
  if (args.inputs.size() == 2) mesh = concatenate_meshes(mesh, read_input(args.inputs[1]));
  const std::string input_name = args.inputs.size() == 2 ? "the two inputs" : args.inputs[0];
  const bool had_vertex_data = has_vertex_data(mesh);
  const auto repaired = repair_input(mesh, f.repair, input_name);
  const int input_faces = mesh.num_faces();

  FlowCommandRun run("blend", f.log, f.quiet,
                     {{"command", "blend"},
                      {"inputs", args.inputs},
                      {"functions", f.functions},
                      {"keep_flow", args.keep_flow},
                      {"all", args.all},
                      {"repair", repair_json(repaired)}},
                     options.flow.step_kind);
  const BlendAllReport all = run.run(
      [&] {
        return args.all ? blend_all_loops(mesh, options, run.observer())
                        : one_blend(blend_loops(mesh, options, run.observer()));
      },
      mesh, args.output);
  const double seconds = all.seconds;
  for (const BlendReport& report : all.blends) {
    if (report.fair.method == FairMethod::flow) warn_if_not_parabolic(report.fair.flow);
    warn_if_folded_back("a", report.a);
    warn_if_folded_back("b", report.b);
    if (report.fair.checks_chose_linear)
      note_keep_flow("the tube is the linear one, which the angle or crease rule preferred to the settled G2 tube");
  }
  note_vertex_data_dropped(had_vertex_data, mesh, input_name, "blend");
  note_new_faces(mesh, input_faces, input_name, "blend");
  write_mesh_output(args.output, mesh);
  if (args.all) {
    nlohmann::json blends = nlohmann::json::array(), unjoined = nlohmann::json::array();
    for (const BlendReport& report : all.blends) blends.push_back(report_json(report));
    for (const UnjoinedLoops& pair : all.unjoined) unjoined.push_back(unjoined_json(pair));
    run.finish(nlohmann::json{
        {"blends", blends}, {"unjoined", unjoined}, {"loops_left", all.loops_left}, {"seconds", seconds}});
  } else {
    run.finish(report_json(all.blends.front()));
  }
  for (const BlendReport& report : all.blends) print_blend(report, args.no_relax);
  if (args.all) print_left_open(all);
  std::printf("%.2f s; wrote %s\n", seconds, args.output.c_str());
  std::fflush(stdout);
  const int unjoined = static_cast<int>(all.unjoined.size()), tried = unjoined + static_cast<int>(all.blends.size());
  if (unjoined > 0)
    throw CliError(kNumerical, "blend: " + std::to_string(unjoined) + " of " + std::to_string(tried) +
                                   " pairs of loops could not be joined and stay open; " + args.output +
                                   " still holds the " + std::to_string(all.blends.size()) +
                                   (all.blends.size() == 1 ? " pair that was joined" : " pairs that were joined") +
                                   repair_hint(all));
}

void setup_blend(CLI::App& app) {
  auto args = std::make_shared<BlendArgs>();
  CLI::App* cmd = app.add_subcommand(
      "blend", "Join two boundary loops (of one mesh or of two meshes) by a fair G2 tube");
  cmd->footer("Where the G2 tube crosses the mesh, does not settle, or settles but turns the normal across the loops "
              "more than the linear ∆³ tube or creases against it, the linear tube is written instead, labelled C2 "
              "(linear) with the reason; where that crosses too, the first lower linear tube (C1, C0) that does not; "
              "where every one crosses and the G0 membrane was dropped as pinched, all of this again from it. "
              "A tube from the membrane that folds back at a loop (turns the normal there by more than 90° and by "
              "more than twice the input's reading) or falls to a lower linear tube is built again from the Hermite "
              "tube, which is written where it turns the normal less or reaches a higher continuity; a tube that "
              "still folds back is written with a warning (docs/blend.md).");
  cmd->add_option("inputs", args->inputs, "One mesh, or two meshes to join (the second is appended)")
      ->required()
      ->expected(1, 2);
  cmd->add_option("-o,--output", args->output, "Output mesh")->required();
  CLI::Option* loops = cmd->add_option("--loops", args->loops,
                  "i,j: the boundary loops to join (default: the closest pair); loops are numbered by "
                  "their smallest vertex index, over the concatenated meshes")
      ->expected(2)
      ->delimiter(',');
  cmd->add_flag("--no-relax", args->no_relax,
                "Start the flow from the Hermite tube, without the G0 membrane (the membrane is dropped "
                "by itself when it pinches off: no minimal surface spans loops far apart for their size; "
                "it is then still the last start, where every tube without it crosses the mesh)");
  cmd->add_flag("--no-descent-fallback", args->no_descent_fallback,
                "Keep the time-stepped flow's last state when it does not settle, instead of continuing "
                "with the energy descent (BlendOptions::descent_fallback; docs/blend.md)");
  cmd->add_flag("--all", args->all,
                "Join the closest pair of loops, then the closest pair of those left, until fewer than two "
                "are left (pieces cut apart at several places); a pair that cannot be joined stays open, its loops "
                "paired with no other, and the others are joined and written (exit 4)")
      ->excludes(loops);
  add_region_fairing_options(cmd, args->fairing);
  add_keep_flow_flag(cmd, args->keep_flow);
  cmd->callback([args] { run_blend(*args); });
}

const CommandRegistration registration(60, setup_blend);

}  // namespace
}  // namespace fairsurf::cli
