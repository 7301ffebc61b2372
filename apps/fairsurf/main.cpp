// fairsurf — command-line entry point. Parses, runs one subcommand, maps failures to exit codes.
#include "command.h"

#include <fairsurf/errors.h>

#include <algorithm>
#include <iostream>
#include <string>

namespace {

int report(fairsurf::cli::ExitCode code, const char* what) {
  std::cerr << "fairsurf: error: " << what << "\n";
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fairsurf::cli;
  CLI::App app{"fairsurf: fair surfaces on triangle meshes with sixth-order geometric flows"};
  app.set_version_flag("--version", FAIRSURF_VERSION);
  app.require_subcommand(1);
  auto& registry = command_registry();
  std::sort(registry.begin(), registry.end());
  for (const auto& entry : registry) entry.second(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the parse error itself
    return code == 0 ? kOk : kUsage;
  } catch (const CliError& e) {
    return report(e.code, e.what());
  } catch (const fairsurf::InvalidArgument& e) {
    return report(kUsage, e.what());
  } catch (const fairsurf::IoError& e) {
    return report(kInputError, e.what());
  } catch (const fairsurf::RepairableMeshError& e) {
    const std::string message = std::string(e.what()) + " (run with --repair, or `fairsurf repair`)";
    return report(kInvalidMesh, message.c_str());
  } catch (const fairsurf::InvalidMeshError& e) {
    return report(kInvalidMesh, e.what());
  } catch (const fairsurf::NumericalError& e) {
    return report(kNumerical, e.what());
  } catch (const std::bad_alloc&) {
    return report(kNumerical, "out of memory");
  } catch (const std::exception& e) {
    return report(kNumerical, e.what());
  }
  return kOk;
}
