#include "bench_options.h"

namespace fairsurf::bench {

void take_last_values(CLI::App& app) { app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast); }

void add_case_options(CLI::App& app, std::string& section, std::string& mesh, std::vector<std::string>& mesh_files) {
  app.add_option("--section", section, "The section to run")
      ->check(CLI::IsMember({"fill", "fair", "blend", "all"}))
      ->capture_default_str();
  CLI::Option* bundled =
      app.add_option("--mesh", mesh, "Only the bundled meshes whose file name contains NAME")->type_name("NAME");
  app.add_option("--mesh-file", mesh_files, "A closed mesh to use instead of the bundled ones (repeatable)")
      ->type_name("PATH")
      ->allow_extra_args(false)
      ->excludes(bundled);
}

}  // namespace fairsurf::bench
