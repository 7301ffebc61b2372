#include "command.h"

#include <fairsurf/io.h>

#include <iostream>

#include <system_error>

namespace fairsurf::cli {

std::vector<std::pair<int, CommandSetup>>& command_registry() {
  static std::vector<std::pair<int, CommandSetup>> registry;
  return registry;
}

CommandRegistration::CommandRegistration(int order, CommandSetup setup) {
  command_registry().emplace_back(order, setup);
}

void check_output_path(const std::filesystem::path& output,
                       const std::vector<std::filesystem::path>& inputs, bool force) {
  if (force) return;
  for (const auto& input : inputs) {
    std::error_code ec;
    const bool same = std::filesystem::equivalent(output, input, ec);
    if (same && !ec)
      throw CliError(kOutputError, "refusing to overwrite input '" + input.string() +
                                       "' (pass --force to allow it)");
  }
}

Mesh read_input(const std::string& path) {
  ReadReport report;
  Mesh mesh = read_mesh(path, &report);
  for (const auto& note : report.notes) std::cerr << "fairsurf: note: " << path << ": " << note << "\n";
  return mesh;
}

}  // namespace fairsurf::cli
