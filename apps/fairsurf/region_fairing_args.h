// The options `fair` and `blend` share: continuity, f, method, step limit, log, progress. Both run
// fair_region (fair_region.h); this file turns the flags into its options and its report into JSON
// (the run itself, progress and log: FlowCommandRun in flow_log.h).
#pragma once

#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/mesh/errors.h>

#include <CLI/CLI.hpp>

#include "command.h"
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace fairsurf::cli {

struct RegionFairingArgs {
  std::string continuity = "G2";
  std::vector<std::string> functions{"H"};
  std::string method = "flow";
  SolverArgs solver;
  std::optional<int> max_steps;  ///< unset: the options' own (500 for fair from its harmonic start, else 200)
  std::string log;
  bool force = false, quiet = false, repair = false;
};

/// Adds --continuity, --functions, --method, --solver, --mumps-controls, --max-steps, --log, --force,
/// --quiet, --repair to `cmd`.
void add_region_fairing_options(CLI::App* cmd, RegionFairingArgs& args);

/// Sets what the flags ask for on `options` (throws InvalidArgument for a bad name): a
/// FairRegionOptions, or the BlendOptions that derive from it. --solver and --mumps-controls set the
/// flow's and the harmonic solves' solver, keeping their ordering. `fair` starts from
/// FairRegionOptions::harmonic_started(), `blend` from the plain defaults (fair_region.h says why).
void apply_region_fairing_args(const RegionFairingArgs& args, FairRegionOptions& options);

/// Adds --keep-flow (fill, fair, blend): keep the flow wherever it settles (keep_settled_flow).
void add_keep_flow_flag(CLI::App* cmd, bool& keep_flow);

/// keep_settled_flow(options) where `keep_flow` (FillOptions and FairRegionOptions take the base's
/// overload, BlendOptions its own); throws InvalidArgument, naming `command`, where it comes with the
/// harmonic method, which runs no flow to keep.
template <class Options>
void apply_keep_flow(bool keep_flow, const std::string& command, Options& options) {
  if (!keep_flow) return;
  if (options.method == FairMethod::harmonic)
    throw InvalidArgument(command + ": --keep-flow keeps the flow's result; --method harmonic runs no flow");
  keep_settled_flow(options);
}

/// Sets FairRegionOptions::held_out_other_functions (fill, fair) from --other-functions; throws
/// InvalidArgument, naming `command`, where the options weigh nothing on held-out rings: the
/// harmonic method (no flow) or `fair --start flat` (no held-out rings).
void apply_other_functions(const std::vector<std::string>& functions, const std::string& command,
                           FairRegionOptions& options);

/// Where the checks that --keep-flow switches off chose the linear solution over the flow
/// (FairRegionReport::checks_chose_linear): "fairsurf: note: `what`; --keep-flow keeps ..." on
/// standard error, so that the flag is found where it would change the result.
void note_keep_flow(const std::string& what);

nlohmann::json to_json(const ContinuityMeasure& measure);
/// Method, continuity requested and supported, flow kind and run (or harmonic figures), measure.
nlohmann::json to_json(const FairRegionReport& report);

/// "G2 (sixth-order flow, 17 steps, steady, max|V| 3.1e-2)" or "G2 (harmonic k = 3)", with a
/// "NOT steady" warning when the flow stopped at its step limit, and "requested G2 but the fixed
/// rings support only G1" when the fixed rings forced a fallback.
std::string summary(const FairRegionReport& report);

}  // namespace fairsurf::cli
