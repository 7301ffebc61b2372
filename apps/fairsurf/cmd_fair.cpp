// fairsurf fair: free-form design / region fairing. A user-marked region is freed and faired with
// the rings around it as boundary data (fair_region.h).
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region_selection.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "command.h"
#include "flow_log.h"
#include "region_fairing_args.h"
#include "repair_report.h"

namespace fairsurf::cli {
namespace {

struct FairArgs {
  std::string input, output, region_file, region_property;
  std::vector<double> region_sphere;
  std::string start = "harmonic";
  std::vector<std::string> other_functions;  // weighed on the held-out rings too (empty: off)
  bool keep_flow = false;
  RegionFairingArgs fairing;
};

std::vector<int> selected_region(const FairArgs& args, const Mesh& mesh, const std::optional<RepairReport>& repaired) {
  std::vector<int> region;
  if (!args.region_file.empty()) {
    region = input_vertex_indices(args.region_file, mesh, repaired);
  } else if (!args.region_sphere.empty()) {
    const auto& s = args.region_sphere;
    region = vertices_in_ball(mesh.V, Eigen::Vector3d(s[0], s[1], s[2]), s[3]);
  } else {
    region = vertices_with_property(mesh, args.region_property);
  }
  if (region.empty()) throw InvalidArgument("fair: the region selects no vertex of " + args.input);
  if (static_cast<int>(region.size()) == mesh.num_vertices())
    throw InvalidArgument("fair: the region holds all " + std::to_string(mesh.num_vertices()) +
                          " vertices of " + args.input + "; the rings around it must stay fixed");
  return region;
}

std::string degrees(double radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g°", radians * 180.0 / M_PI);
  return text;
}

void run_fair(const FairArgs& args) {
  const RegionFairingArgs& f = args.fairing;
  check_outputs("fair", {{"-o", args.output, OutputKind::mesh}, {"--log", f.log, OutputKind::json}},
                {args.input, args.region_file}, f.force);
  FairRegionOptions options =
      args.start == "harmonic" ? FairRegionOptions::harmonic_started() : FairRegionOptions{};
  apply_region_fairing_args(f, options);
  apply_keep_flow(args.keep_flow, "fair", options);
  apply_other_functions(args.other_functions, "fair", options);
  Mesh mesh = read_input(args.input);
  drop_shape_properties(mesh, args.input);
  const auto repaired = repair_input(mesh, f.repair, args.input);
  const std::vector<int> region = selected_region(args, mesh, repaired);

  FlowCommandRun run("fair", f.log, f.quiet,
                     {{"command", "fair"},
                      {"input", args.input},
                      {"functions", f.functions},
                      {"other_functions", args.other_functions},
                      {"keep_flow", args.keep_flow},
                      {"repair", repair_json(repaired)}},
                     options.flow.step_kind);
  const FairRegionReport report =
      run.run([&] { return fair_region(mesh, region, options, run.observer()); }, mesh, args.output);
  if (report.method == FairMethod::flow) warn_if_not_parabolic(report.flow);
  if (report.checks_chose_linear)
    note_keep_flow(std::string(report.parts.empty() ? "the region" : "a part of the region") +
                   " got the linear solution, which the held-out rings or the fold check preferred to the flow");
  write_mesh_output(args.output, mesh);
  run.finish(to_json(report));
  std::printf("faired %s: %d free vertices, %s; border (%d vertices): max normal angle %s, max H jump "
              "%.3g; %.2f s; wrote %s\n",
              args.input.c_str(), report.free_vertices, summary(report).c_str(),
              report.continuity.border_vertices, degrees(report.continuity.max_normal_angle).c_str(),
              report.continuity.max_mean_curvature_jump, report.seconds, args.output.c_str());
}

void setup_fair(CLI::App& app) {
  auto args = std::make_shared<FairArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fair", "Fair a marked region (free-form design): the region moves, the rings around it hold "
              "the boundary data");
  cmd->add_option("input", args->input, "Input mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("-o,--output", args->output, "Output mesh")->required();
  auto* group = cmd->add_option_group("region", "The free region (exactly one)");
  group->add_option("--region", args->region_file, "File of 0-based vertex indices of the free region");
  group->add_option("--region-sphere", args->region_sphere,
                    "x,y,z,r: the vertices strictly inside this ball are free")
      ->expected(4)
      ->delimiter(',');
  group->add_option("--region-property", args->region_property,
                    "Per-vertex property (PLY) whose non-zero vertices are free");
  group->require_option(1);
  cmd->add_option("--start", args->start,
                  "Flow start: harmonic (default: one cotangent Delta^k solve with the region's own operator, then the "
                  "energy descent, that solution kept as the floor) or flat (the region as given, the "
                  "time-stepped flow with tau doubling from 1e-9)")
      ->check(CLI::IsMember({"harmonic", "flat"}));
  add_region_fairing_options(cmd, args->fairing);
  add_other_functions_option(cmd, args->other_functions);
  add_keep_flow_flag(cmd, args->keep_flow);
  cmd->callback([args] { run_fair(*args); });
}

const CommandRegistration registration(50, setup_fair);

}  // namespace
}  // namespace fairsurf::cli
