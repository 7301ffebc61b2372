#include "region_fairing_args.h"

#include <fairsurf/energy/energy_function.h>

#include <cstdio>

#include "command.h"
#include "flow_log.h"
#include "repair_report.h"

namespace fairsurf::cli {

void add_region_fairing_options(CLI::App* cmd, RegionFairingArgs& args) {
  cmd->add_option("--continuity", args.continuity,
                  "G2 (default: sixth-order flow, three fixed rings), G1 (Willmore, two) or G0 (mean "
                  "curvature, one)");
  add_functions_option(cmd, args.functions);
  cmd->add_option("--method", args.method,
                  "flow (default: the geometric flow to a steady state) or harmonic (cotangent "
                  "Laplacian^(k+1) x = 0, the linear baseline)");
  add_solver_options(cmd, args.solver);
  cmd->add_option("--max-steps", args.max_steps,
                  "Stop the flow after this many accepted steps (default: 500 for fair's energy descent from the "
                  "Delta^k start, 200 for a time-stepped flow: fair --start flat, blend)")
      ->check(whole_number_at_least(1));
  cmd->add_option("--log", args.log, "Write a JSON report with every flow step here");
  cmd->add_flag("--quiet", args.quiet, "No progress line");
  add_repair_flag(cmd, args.repair);
  cmd->add_flag("--force", args.force, "Allow outputs to overwrite an input");
}

void apply_region_fairing_args(const RegionFairingArgs& args, FairRegionOptions& o) {
  o.continuity = parse_continuity(args.continuity);
  o.method = parse_fair_method(args.method);
  o.flow.functions = args.functions;
  if (args.max_steps) o.flow.max_steps = *args.max_steps;
  apply_solver_args(args.solver, o.flow.solver);
  apply_solver_args(args.solver, o.harmonic_solver);
}

void add_keep_flow_flag(CLI::App* cmd, bool& keep_flow) {
  cmd->add_flag("--keep-flow", keep_flow,
                "Keep the flow wherever it settles, even where its linear Delta^k floor re-predicts the held-out "
                "rings better or the flow turns the border more than the floor (blend: turns the normal across "
                "the loops more or creases against the linear tube): G2 over a C2 result that may lie closer to "
                "the surface; the floor still takes a flow that does not settle, crosses the mesh, or (fill, "
                "fair) folds back (turns the normal across the border by more than a right angle) where the "
                "floor does not");
}

void apply_other_functions(const std::vector<std::string>& functions, const std::string& command,
                           FairRegionOptions& options) {
  if (functions.empty()) return;
  if (options.method == FairMethod::harmonic)
    throw InvalidArgument(command + ": --other-functions weighs another flow; --method harmonic runs no flow");
  if (options.held_out_rings <= 0)
    throw InvalidArgument(command + ": --other-functions is weighed on the held-out rings, which only the "
                                    "harmonic start has (--start harmonic)");
  parse_energy_functions(functions);  // a bad name fails here, before any work
  options.held_out_other_functions = functions;
}

void note_keep_flow(const std::string& what) {
  std::fprintf(stderr,
               "fairsurf: note: %s; --keep-flow keeps the flow wherever it settles clear of the mesh, G2 over a linear "
               "result that may lie closer to the surface (docs/fill.md, \"Keeping the flow\")\n",
               what.c_str());
}

nlohmann::json to_json(const ContinuityMeasure& m) {
  return {{"border_vertices", m.border_vertices},
          {"max_normal_angle", m.max_normal_angle},
          {"mean_normal_angle", m.mean_normal_angle},
          {"max_mean_curvature_jump", m.max_mean_curvature_jump},
          {"mean_mean_curvature_jump", m.mean_mean_curvature_jump}};
}

nlohmann::json to_json(const FairRegionReport& r) {
  nlohmann::json j{{"free_vertices", r.free_vertices},
                   {"method", to_string(r.method)},
                   {"continuity_requested", to_string(r.requested)},
                   {"continuity_supported", to_string(r.supported)},
                   {"delivered", delivered_label(r.supported, r.linear)},
                   {"note", r.note},
                   {"continuity_measured", to_json(r.continuity)},
                   {"seconds", r.seconds}};
  if (r.method == FairMethod::flow) {
    j["flow"] = to_string(r.flow_kind);
    j["harmonic_start_solves"] = r.harmonic.iterations;  // 0: the flow started from the input
    j["held_out_flow_error"] = r.held_out_flow_error;      // NaN, ∞ (a failed fairing) -> null
    j["held_out_linear_error"] = r.held_out_linear_error;
    j["held_out_two_ring_flow_error"] = r.held_out_two_ring_flow_error;
    j["two_ring_boundary_fits"] = r.two_ring_boundary_fits;
    j["held_out_other_flow_error"] = r.held_out_other_flow_error;  // --other-functions; else null
    j["held_out_other_two_ring_flow_error"] = r.held_out_other_two_ring_flow_error;
    j["other_functions_chosen"] = r.other_functions;
    j["checks_chose_linear"] = r.checks_chose_linear;
    j["flow_folded_back"] = r.flow_folded_back;
  }
  for (const FairRegionReport& part : r.parts) j["parts"].push_back(to_json(part));
  if (r.has_flow_report()) {
    j.update(to_json(r.flow));
  } else {
    j["harmonic"] = {{"order", r.harmonic.order}, {"backward_error", r.harmonic.backward_error}};
    if (r.method == FairMethod::flow)  // of the flow that was weighed or tried
      j["well_posedness"] = {{"vertices", r.flow.well_posedness.vertices},
                             {"violating_vertices", r.flow.well_posedness.violating_vertices}};
  }
  return j;
}

std::string summary(const FairRegionReport& r) {
  if (!r.parts.empty()) {
    std::string out = std::to_string(r.parts.size()) + " parts whose fixed rings do not meet, each faired on its own:";
    for (std::size_t k = 0; k < r.parts.size(); ++k)
      out += (k == 0 ? " " : "; ") + std::string("part ") + std::to_string(k + 1) + " (" +
             std::to_string(r.parts[k].free_vertices) + " free vertices): " + summary(r.parts[k]);
    return out;
  }
  char text[256];
  if (r.linear) {
    std::snprintf(text, sizeof text, "%s (cotangent ∆^%d, %d solves)", delivered_label(r.supported, true).c_str(),
                  r.harmonic.order, r.harmonic.iterations);
  } else {
    std::string start;
    if (r.harmonic.iterations > 0)
      start.append("harmonic start (").append(std::to_string(r.harmonic.iterations)).append(" solves), ");
    std::snprintf(text, sizeof text, "%s (%s flow, %s%d steps, %s, max|V| %.3g)",
                  to_string(r.supported), to_string(r.flow_kind), start.c_str(),
                  r.flow.accepted_steps, to_string(r.flow.stop_reason), r.flow.final_max_velocity);
  }
  std::string out = text;
  if (!r.note.empty()) out += "; " + r.note;
  if (!r.linear && r.flow.stop_reason != FlowStopReason::steady)
    out += "; NOT steady: " + unsettled_reason(r.flow) + "; the result is the flow's state after its last step" +
           (r.flow.step_kind == FlowStepKind::energy_descent ? " (E was still falling: raise --max-steps)"
            : r.flow.final_max_velocity > r.flow.initial_max_velocity
                ? " (more steps drift further from a steady state: a lower --max-steps keeps an earlier "
                  "state; docs/blend.md, regions with no steady state)"
                : " (max|V| was still falling: raise --max-steps)");
  if (r.supported != r.requested && !r.crossing_fallback)
    out += "; requested " + std::string(to_string(r.requested)) + " but the fixed rings support only " +
           std::string(to_string(r.supported));
  return out;
}

}  // namespace fairsurf::cli
