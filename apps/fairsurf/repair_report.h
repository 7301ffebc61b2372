// What the CLI says about a repair: one summary line, a JSON object, and the --repair step that
// smooth, fill, fair, blend and curvature run on their input before anything else.
#pragma once

#include <fairsurf/applications/repair.h>
#include <fairsurf/mesh/mesh.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace fairsurf::cli {

/// "merged 16 duplicate vertices, split 1 non-manifold vertex (+1 vertex)", or "nothing to repair".
std::string describe(const RepairReport& report);
/// Every count of the report, keyed by its field name.
nlohmann::json to_json(const RepairReport& report);

/// Adds the --repair flag to a command; `how` says which options repair_input gets.
void add_repair_flag(CLI::App* command, bool& repair_flag, const std::string& how = "fairsurf repair's defaults");

/// With `enabled`, repairs `mesh` with `options` (fill's keep the border's pinches) and, unless
/// `quiet` (a command printing JSON), prints "repaired PATH: ..." to standard output; returns the
/// report (nothing when not enabled).
std::optional<RepairReport> repair_input(Mesh& mesh, bool enabled, const std::string& path,
                                         bool quiet = false, const RepairOptions& options = {});

/// The report as JSON for a --log, null when no repair ran.
nlohmann::json repair_json(const std::optional<RepairReport>& report);

}  // namespace fairsurf::cli
