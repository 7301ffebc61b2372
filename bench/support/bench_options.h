// Command-line conventions and options the benches share (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fairsurf::bench {

/// Every option of `app` keeps its last value when given twice, as the benches' hand-written
/// parsers did (CLI11 refuses a repeat), so that a run can append an override.
void take_last_values(CLI::App& app);

/// --section fill|fair|blend|all, --mesh NAME (the bundled meshes whose file name contains it) and
/// --mesh-file PATH (repeatable, one value each time; excludes --mesh): which cases run, on what.
void add_case_options(CLI::App& app, std::string& section, std::string& mesh, std::vector<std::string>& mesh_files);

}  // namespace fairsurf::bench
