// What the CLI says about a repair: one summary line, a JSON object, and the --repair step that
// smooth, fill, fair, blend and curvature run on their input before anything else.
#pragma once

#include <fairsurf/applications/repair.h>
#include <fairsurf/mesh/mesh.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

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

/// The vertex indices of the file `path` (--region, --fixed-vertices), which name vertices of the
/// input as read, as vertices of `mesh`: after a --repair (`repaired`), each index's vertex and the
/// copies a split made of it (repaired_vertices), so that a file written for the input means the
/// same vertices. Throws ParseError for an index outside the input or a vertex the repair removed.
std::vector<int> input_vertex_indices(const std::string& path, const Mesh& mesh,
                                      const std::optional<RepairReport>& repaired);

/// The report as JSON for a --log, null when no repair ran.
nlohmann::json repair_json(const std::optional<RepairReport>& report);

}  // namespace fairsurf::cli
