// fairsurf fill: fill the holes of a mesh with G2 (or G1/G0) boundary data (fill.h).
#include <fairsurf/applications/fill.h>
#include <fairsurf/io/io.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <numbers>

#include "command.h"
#include "flow_log.h"
#include "region_fairing_args.h"
#include "repair_report.h"

namespace fairsurf::cli {
namespace {

struct FillArgs {
  std::string input, output, log;
  std::string continuity = "G2", method = "flow";
  SolverArgs solver;
  std::vector<std::string> functions{"H"};
  std::vector<std::string> other_functions;  // weighed on the held-out rings too (empty: off)
  std::vector<int> holes;
  int max_hole_edges = 0, max_steps = 0;
  bool skip_largest = false, force = false, quiet = false, repair = false, keep_flow = false;
};

FillOptions fill_options(const FillArgs& args) {
  FillOptions o;
  o.continuity = parse_continuity(args.continuity);
  o.method = parse_fair_method(args.method);
  o.flow.functions = args.functions;
  if (args.max_steps > 0) o.flow.max_steps = args.max_steps;
  // Every solve of the fill (membrane, harmonic start or floor, flow), each keeping its ordering.
  for (LinearSolverOptions* solver : {&o.flow.solver, &o.harmonic_solver, &o.patch.solver})
    apply_solver_args(args.solver, *solver);
  o.holes = args.holes;
  o.max_hole_edges = args.max_hole_edges;
  o.skip_largest = args.skip_largest;
  apply_keep_flow(args.keep_flow, "fill", o);
  apply_other_functions(args.other_functions, "fill", o);
  return o;
}

// "hole 5" or "holes 5, 7".
std::string holes_phrase(const std::vector<int>& values) {
  std::string s = values.size() == 1 ? "hole " : "holes ";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i > 0 ? ", " : "") + std::to_string(values[i]);
  return s;
}

// "hole 3 (24 border edges): filled, +41 vertices, +106 faces, G2, 17 steps, max|V| 3.2e-03, ..."
std::string hole_line(const HoleReport& r) {
  char buffer[512];
  std::string line = "hole " + std::to_string(r.index) + " (" + std::to_string(r.border_edges) +
                     " border edges): " + to_string(r.status);
  if (r.status != HoleStatus::filled) {
    line += ": " + r.reason;
    if (!r.filled_with.empty()) line += " (filled jointly with " + holes_phrase(r.filled_with) + ")";
    return line;
  }
  std::snprintf(buffer, sizeof buffer, ", +%d vertices, +%d faces, %s", r.vertices_added, r.faces_added,
                delivered_label(r.supported, r.linear).c_str());
  line += buffer;
  if (!r.note.empty()) line += " (" + std::string(to_string(r.requested)) + " requested; " + r.note + ")";
  if (!std::isnan(r.final_max_velocity)) {
    std::snprintf(buffer, sizeof buffer, ", %d steps, max|V| %.2e", r.steps, r.final_max_velocity);
    line += buffer;
  }
  if (r.continuity.border_vertices > 0) {
    std::snprintf(buffer, sizeof buffer, ", max normal angle %.3g deg, max H jump %.3g",
                  r.continuity.max_normal_angle * 180 / std::numbers::pi, r.continuity.max_mean_curvature_jump);
    line += buffer;
  }
  std::snprintf(buffer, sizeof buffer, ", %.2f s", r.seconds);
  line += buffer;
  if (!r.filled_with.empty()) line += " (jointly with " + holes_phrase(r.filled_with) + ")";
  return line;
}

// "3 G2, 1 C2 (linear)": the filled holes counted by what they got, in the order first seen.
std::string delivered_counts(const FillReport& report) {
  std::vector<std::pair<std::string, int>> counts;
  for (const HoleReport& r : report.holes) {
    if (r.status != HoleStatus::filled) continue;
    const std::string label = delivered_label(r.supported, r.linear);
    auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == label; });
    if (it == counts.end()) counts.emplace_back(label, 1);
    else ++it->second;
  }
  std::string text;
  for (const auto& [label, count] : counts) text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + label;
  return text.empty() ? "none filled" : text;
}

nlohmann::json hole_json(const HoleReport& r) {
  nlohmann::json j{{"index", r.index},
                   {"border_edges", r.border_edges},
                   {"status", to_string(r.status)},
                   {"reason", r.reason},
                   {"filled_with", r.filled_with},
                   {"vertices_added", r.vertices_added},
                   {"faces_added", r.faces_added},
                   {"patch_shared_with", r.patch_shared_with},
                   {"pinched_by", r.pinched_by},
                   {"around_a_face", r.around_a_face},
                   {"hanging_piece_at", r.hanging_piece_at},
                   {"lone_triangle", r.lone_triangle},
                   {"requested_continuity", to_string(r.requested)},
                   {"supported_continuity", to_string(r.supported)},
                   {"delivered", delivered_label(r.supported, r.linear)},
                   {"linear", r.linear},
                   {"held_out_flow_error", r.held_out_flow_error},
                   {"held_out_linear_error", r.held_out_linear_error},
                   {"held_out_two_ring_flow_error", r.held_out_two_ring_flow_error},
                   {"held_out_other_flow_error", r.held_out_other_flow_error},
                   {"held_out_other_two_ring_flow_error", r.held_out_other_two_ring_flow_error},
                   {"other_functions_chosen", r.other_functions},
                   {"held_out_refined_linear_error", r.held_out_refined_linear_error},
                   {"held_out_roughness", r.held_out_roughness},
                   {"refined_start", r.refined_start},
                   {"unfaired", r.unfaired},
                   {"checks_chose_linear", r.checks_chose_linear},
                   {"flow_folded_back", r.flow_folded_back},
                   {"two_ring_boundary_fits", r.two_ring_boundary_fits},
                   {"note", r.note},
                   {"steps", r.steps},
                   {"harmonic_solves", r.harmonic_solves},
                   {"seconds", r.seconds},
                   {"final_max_velocity", r.final_max_velocity},
                   {"well_posedness",
                    {{"vertices", r.well_posedness.vertices},
                     {"violating_vertices", r.well_posedness.violating_vertices}}},
                   {"continuity", to_json(r.continuity)}};
  return j;
}

// Whether the hole failed because its border is pinched at a vertex it shares with a loop that is
// not filled.
bool failed_at_pinch(const HoleReport& hole) { return hole.status == HoleStatus::failed && hole.pinched_by >= 0; }

// What the user can do about the failed holes, or "". A lone triangle hanging at a pinch of a
// hole's border (fill never fills its loop) is what --repair removes. Otherwise, when the longest
// loop failed (not at a pinch) and is at least three times longer than any other, it is most likely
// the outer border of an open surface (a scan, a terrain), which is not a hole.
std::string failure_hint(const FillReport& report, const FillArgs& args) {
  const bool lone_triangle = std::any_of(report.holes.begin(), report.holes.end(),
                                         [&](const HoleReport& h) { return open_at_lone_triangle(report, h); });
  if (lone_triangle && !args.repair)
    return "; a lone triangle hangs at a pinch of a failed hole's border: --repair splits the vertex and removes it";
  if (args.skip_largest || report.holes.size() < 2) return "";
  std::vector<const HoleReport*> by_length;
  for (const auto& hole : report.holes) by_length.push_back(&hole);
  std::sort(by_length.begin(), by_length.end(),
            [](const HoleReport* a, const HoleReport* b) { return a->border_edges > b->border_edges; });
  if (by_length[0]->status != HoleStatus::failed || failed_at_pinch(*by_length[0]) ||
      by_length[0]->border_edges < 3 * by_length[1]->border_edges)
    return "";
  return "; the largest loop looks like the outer border of an open surface: use --skip-largest";
}

// A patch that folds back at its hole's border (fill.h's folds_back) is written; the user is told,
// once for a patch two loops share (HoleReport::patch_shared_with).
void warn_if_folded_back(const HoleReport& hole) {
  if (!folds_back(hole) || hole.patch_shared_with >= 0) return;
  std::fprintf(stderr,
               "fairsurf: warning: hole %d's patch folds back: it turns the normal across the hole's border by "
               "%.3g°, more than a right angle; the loop may not be a hole (the edge of a fin) or the hole may cut "
               "across a thin part (docs/fill.md)\n",
               hole.index, hole.continuity.max_normal_angle * 180 / std::numbers::pi);
}

void run_fill(const FillArgs& args) {
  check_outputs("fill", {{"-o", args.output, OutputKind::mesh}, {"--log", args.log, OutputKind::json}},
                {args.input}, args.force);
  const FillOptions options = fill_options(args);
  Mesh mesh = read_input(args.input);
  drop_shape_properties(mesh, args.input);
  RepairOptions repair_options;  // fill relinks a pinch of the border; split, it would not be one
  repair_options.keep_border_pinches = true;
  const auto repaired = repair_input(mesh, args.repair, args.input, false, repair_options);
  const bool progress = progress_wanted(args.quiet);
  std::map<int, nlohmann::json> steps;  // by the first hole of each jointly faired group
  const FillObserver observer = [&](std::span<const int> holes, const StepRecord& r) {
    steps[holes.front()].push_back(to_json(r));
    if (progress) print_progress(r, "hole " + std::to_string(holes.front()) + "  ");
  };
  const bool had_vertex_data = has_vertex_data(mesh);
  FillReport report = fill_holes(mesh, options, observer);
  if (progress) std::fputc('\n', stderr);
  note_vertex_data_dropped(had_vertex_data, mesh, args.input, "fill");
  note_new_faces(mesh, report.input_faces, args.input, "fill");

  write_mesh_output(args.output, mesh);
  if (!args.log.empty()) {
    nlohmann::json log{{"command", "fill"},
                       {"input", args.input},
                       {"output", args.output},
                       {"continuity", args.continuity},
                       {"method", args.method},
                       {"keep_flow", args.keep_flow},
                       {"functions", args.functions},
                       {"other_functions", args.other_functions},
                       {"filled", report.filled},
                       {"skipped", report.skipped},
                       {"failed", report.failed},
                       {"seconds", report.seconds},
                       {"repair", repair_json(repaired)},
                       {"holes", nlohmann::json::array()}};
    for (const auto& r : report.holes) {
      nlohmann::json j = hole_json(r);
      const int group = r.filled_with.empty() ? r.index : std::min(r.index, r.filled_with.front());
      if (steps.count(group)) j["steps_log"] = steps[group];
      log["holes"].push_back(j);
    }
    write_output([&] { write_file_atomically(args.log, log.dump(2) + "\n", "fill"); });
  }

  for (const auto& r : report.holes) warn_if_not_parabolic(r.well_posedness, "hole " + std::to_string(r.index) + ": ");
  for (const auto& r : report.holes) warn_if_folded_back(r);
  const auto checked = std::count_if(report.holes.begin(), report.holes.end(),
                                     [](const HoleReport& r) { return r.checks_chose_linear; });
  if (checked > 0)
    note_keep_flow(std::to_string(checked) + (checked == 1 ? " hole got" : " holes got") +
                   " the linear solution, which the held-out rings or the fold check preferred to the G2 flow");
  if (!args.quiet)
    for (const auto& r : report.holes) std::printf("%s\n", hole_line(r).c_str());
  const int selected = report.filled + report.failed;
  std::printf("filled %d of %d selected holes of %s (%s; %d failed, %d skipped): %d -> %d vertices, %d -> %d "
              "faces, %.2f s; wrote %s\n",
              report.filled, selected, args.input.c_str(), delivered_counts(report).c_str(), report.failed,
              report.skipped, report.input_vertices, mesh.num_vertices(), report.input_faces, mesh.num_faces(),
              report.seconds, args.output.c_str());
  std::fflush(stdout);
  if (report.failed > 0)
    throw CliError(kNumerical, "fill: " + std::to_string(report.failed) + " of " + std::to_string(selected) +
                                   " selected holes failed; " + args.output + " still holds the " +
                                   std::to_string(report.filled) +
                                   (report.filled == 1 ? " hole that was filled" : " holes that were filled") +
                                   failure_hint(report, args));
}

void setup_fill(CLI::App& app) {
  auto args = std::make_shared<FillArgs>();
  CLI::App* cmd = app.add_subcommand("fill", "Fill the holes of a mesh with G2 (or G1, G0) boundary data");
  cmd->footer("Where a hole's fill fails (its patch crosses the mesh or its fairing throws), the flow is tried once "
              "more with its trial states relaxed tangentially where it crossed, and once more rejecting each trial "
              "that crosses the mesh, then the linear ∆³, ∆², ∆ solutions, then all that again from the refined "
              "triangulation instead of its membrane, then that triangulation unfaired, C0 (linear); each hole's "
              "line says which and why. Where even that crosses the mesh, the loop is triangulated again within the "
              "faces of its Delaunay tetrahedralization and filled from there; a hole is left open only where that "
              "fails too, or where its patch has a zero-area triangle (a loop through both copies of a vertex that "
              "repair split). A fill "
              "that folds back (turns the normal across its border by more than 90°) is made again from the refined "
              "triangulation, then from the lightest of the triangulation's starts, then within the faces of the "
              "loop's Delaunay tetrahedralization, and written with a warning if it still folds back (docs/fill.md).");
  cmd->add_option("input", args->input, "Input mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("-o,--output", args->output, "Output mesh")->required();
  cmd->add_option("--continuity", args->continuity,
                  "G2 (default: sixth-order flow, three fixed rings), G1 (Willmore) or G0 (mean curvature)");
  add_functions_option(cmd, args->functions);
  add_other_functions_option(cmd, args->other_functions);
  cmd->add_option("--holes", args->holes,
                  "Fill only these boundary loops (0-based, comma separated, or one per --holes)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(whole_number_at_least(0));
  cmd->add_option("--max-hole-edges", args->max_hole_edges, "Skip loops with more border edges than this (>= 1)")
      ->check(whole_number_at_least(1));
  cmd->add_flag("--skip-largest", args->skip_largest,
                "Leave the longest loop open (the outer border of an open surface)");
  cmd->add_option("--method", args->method, "flow (default: the flow, or its linear ∆^k floor where that re-predicts the held-out rings better by more than 5%) or harmonic (the cotangent ∆^k alone, labelled C2 (linear): re-evaluated from the membrane, or one solve from the patch before it where that re-predicts the held-out rings more than twice as well, or where the surface around the hole is rough)");
  add_keep_flow_flag(cmd, args->keep_flow);
  add_solver_options(cmd, args->solver);
  cmd->add_option("--max-steps", args->max_steps, "Stop each hole's flow after this many accepted steps (>= 1)")
      ->check(whole_number_at_least(1));
  cmd->add_option("--log", args->log, "Write a per-hole JSON report with every flow step here");
  add_repair_flag(cmd, args->repair,
                  "fairsurf repair's defaults, but a pinch of the border stays joined for fill to close, only its "
                  "lone triangles split off");
  cmd->add_flag("--quiet", args->quiet, "Only the summary line; no progress");
  cmd->add_flag("--force", args->force, "Allow outputs to overwrite the input");
  cmd->callback([args] { run_fill(*args); });
}

const CommandRegistration registration(40, setup_fill);

}  // namespace
}  // namespace fairsurf::cli
