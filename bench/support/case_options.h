// Command-line options that bench_real_holes and bench_stress share (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fairsurf::bench {

/// --section fill|fair|blend|all, --mesh NAME (the bundled meshes whose file name contains it) and
/// --mesh-file PATH (repeatable, one value each time; excludes --mesh): which cases run, on what.
void add_case_options(CLI::App& app, std::string& section, std::string& mesh, std::vector<std::string>& mesh_files);

}  // namespace fairsurf::bench
