// fairsurf smooth: denoise or fair a whole mesh with a geometric flow (smooth.h).
#include <fairsurf/applications/smooth.h>
#include <fairsurf/io/io.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>

#include "command.h"
#include "flow_log.h"
#include "repair_report.h"

namespace fairsurf::cli {
namespace {

struct SmoothArgs {
  std::string input, output, log, fixed_vertices_file;
  std::string flow = "sixth";
  std::vector<std::string> functions{"H"};
  SolverArgs solver;
  double tau = 0, time = 0, steady_tolerance = 1.0;
  int steps = 0, max_steps = 1000, fixed_rings = 3;
  bool steady = false, force = false, quiet = false, repair = false;
};

FlowKind flow_kind(const std::string& name) {
  static const std::map<std::string, FlowKind> short_names{
      {"sixth", FlowKind::sixth_order},
      {"diffusion", FlowKind::surface_diffusion},
      {"mean", FlowKind::mean_curvature}};
  const auto found = short_names.find(name);
  return found != short_names.end() ? found->second : parse_flow_kind(name);
}

SmoothOptions smooth_options(const SmoothArgs& args, const Mesh& mesh, const std::optional<RepairReport>& repaired) {
  SmoothOptions o = scan_smoothing_options(mesh, flow_kind(args.flow));
  o.flow.functions = args.functions;
  apply_solver_args(args.solver, o.flow.solver);
  o.flow.max_steps = args.max_steps;
  o.fixed_rings = args.fixed_rings;
  if (!args.fixed_vertices_file.empty())
    o.fixed_vertices = input_vertex_indices(args.fixed_vertices_file, mesh, repaired);
  set_smoothing_end(o, {args.steps, args.steady, args.steady_tolerance, args.time, args.tau});
  return o;
}

// The bounds that depend on two options, or on the flow's own limits: checked before any work.
void check_times(const SmoothArgs& args) {
  const double tau_max = FlowOptions{}.tau_max;
  char text[300];
  if (args.tau > tau_max) {
    std::snprintf(text, sizeof text, "smooth: --tau: must be <= %g, the largest step the step control takes "
                  "(unit-diagonal units; got %g)", tau_max, args.tau);
    throw CliError(kUsage, text);
  }
  if (args.time > args.max_steps * tau_max) {
    std::snprintf(text, sizeof text, "smooth: --time %g cannot be reached: --max-steps %d steps of at most "
                  "%g each end by t = %g (unit-diagonal units)", args.time, args.max_steps, tau_max,
                  args.max_steps * tau_max);
    throw CliError(kUsage, text);
  }
}

void run_smooth(const SmoothArgs& args) {
  check_times(args);
  check_outputs("smooth", {{"-o", args.output, OutputKind::mesh}, {"--log", args.log, OutputKind::json}},
                {args.input, args.fixed_vertices_file}, args.force);
  Mesh mesh = read_input(args.input);
  drop_shape_properties(mesh, args.input);
  const auto repaired = repair_input(mesh, args.repair, args.input);
  const SmoothOptions options = smooth_options(args, mesh, repaired);
  FlowCommandRun run("smooth", args.log, args.quiet,
                     {{"command", "smooth"},
                      {"input", args.input},
                      {"flow", to_string(options.flow.kind_to_run())},
                      {"functions", options.flow.functions},
                      {"repair", repair_json(repaired)}},
                     options.flow.step_kind);
  const FlowReport report = run.run([&] { return smooth(mesh, options, run.observer()); }, mesh, args.output);
  warn_if_not_parabolic(report);
  write_mesh_output(args.output, mesh);
  run.finish(to_json(report));
  std::printf("smoothed %s: %s flow, %d steps (%d rejected) to t = %.3g (%s); energy %.4g -> %.4g; "
              "max|V| %.3g -> %.3g; %d free vertices; wrote %s\n",
              args.input.c_str(), to_string(options.flow.kind_to_run()), report.accepted_steps,
              report.rejected_steps, report.time, to_string(report.stop_reason), report.initial_energy,
              report.final_energy, report.initial_max_velocity, report.final_max_velocity,
              report.free_vertices, args.output.c_str());
  if (args.steady && report.stop_reason != FlowStopReason::steady)
    std::printf("NOT steady: --steady stopped at --max-steps %d before reaching its tolerance; the output is "
                "the flow's state after its last step (raise --max-steps, or --steady-tolerance)\n",
                args.max_steps);
}

void setup_smooth(CLI::App& app) {
  auto args = std::make_shared<SmoothArgs>();
  CLI::App* cmd = app.add_subcommand(
      "smooth", "Smooth or denoise a mesh with the sixth-order flow (or a baseline flow)");
  cmd->add_option("input", args->input, "Input mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("-o,--output", args->output, "Output mesh")->required();
  cmd->add_option("--flow", args->flow,
                  "sixth (default), willmore, diffusion (surface diffusion) or mean (mean curvature)");
  add_functions_option(cmd, args->functions);
  cmd->add_option("--tau", args->tau,
                  "Initial time step, unit-diagonal units, in (0, 1] (default: the run's time / 64)")
      ->check(positive_number());
  auto* steps = cmd->add_option("--steps", args->steps, "Run this many accepted steps (>= 1)")
                    ->check(whole_number_at_least(1));
  auto* time = cmd->add_option("--time", args->time,
                               "Run to this time > 0, unit-diagonal units (default: (2h)^order / pi^(order-2), h "
                               "the mean edge length: every flow damps a feature 4h wide alike)")
                   ->check(positive_number());
  auto* steady = cmd->add_flag("--steady", args->steady, "Run to a steady state: max|V| under the tolerance or, for the sixth-order flow, until the energy descent stops lowering E (docs/flow.md)");
  steps->excludes(time)->excludes(steady);
  time->excludes(steady);
  cmd->add_option("--steady-tolerance", args->steady_tolerance,
                  "Steady-state tolerance on max|V| over free vertices, unit-diagonal units (default 1)")
      ->check(positive_number());
  cmd->add_option("--max-steps", args->max_steps, "Stop after this many accepted steps (default 1000)")
      ->check(whole_number_at_least(1));
  cmd->add_option("--fixed-vertices,--fixed", args->fixed_vertices_file,
                  "File of 0-based vertex indices to hold fixed");
  cmd->add_option("--fixed-rings", args->fixed_rings,
                  "Rings held fixed along the mesh border (default 3; 0 frees the border)")
      ->check(whole_number_at_least(0));
  add_solver_options(cmd, args->solver);
  cmd->add_option("--log", args->log, "Write a per-step JSON log here");
  add_repair_flag(cmd, args->repair);
  cmd->add_flag("--quiet", args->quiet, "No progress line");
  cmd->add_flag("--force", args->force, "Allow outputs to overwrite the input");
  cmd->callback([args] { run_smooth(*args); });
}

const CommandRegistration registration(30, setup_smooth);

}  // namespace
}  // namespace fairsurf::cli
