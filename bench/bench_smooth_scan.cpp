// `fairsurf smooth` on the real raw scans of data/ (hammer_rawscan.obj: 30k vertices, closed;
// demosthenes_scan_lowres.obj: 8.4k vertices, open base) with the options the CLI uses, to its
// default time (2h̄)⁶/π⁴. Prints, per scan: wall time, accepted/rejected steps, the time reached against
// the default time, the faces inverted against the input, the noise index before and after, the
// energy before and after. Arguments: the scans to run (paths; default both), optionally --relax W
// to override the tangential relaxation weight (0 turns it off, for comparisons) and --out PATH to
// write the result; BENCH_VERBOSE=1 prints every trial step.
#include <fairsurf/applications/smooth.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_quality.h>
#include <fairsurf/mesh/topology.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_options.h"

using namespace fairsurf;

namespace {

void run_scan(const std::string& path, double relax, const std::string& out) {
  Mesh mesh = read_mesh(path);
  const Vertices input = mesh.V;
  const double end_time = default_smoothing_time(mesh, FlowKind::sixth_order);
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  SmoothOptions options = scan_smoothing_options(mesh);
  if (relax >= 0) options.flow.tangential_relaxation = relax;
  const auto start = std::chrono::steady_clock::now();
  FlowReport report;
  std::string failure;
  int accepted = 0, rejected = 0;
  double time = 0;
  try {
    report = smooth(mesh, options, [&](const StepRecord& r) {
      (r.accepted ? accepted : rejected) += 1;
      if (r.accepted) time = r.time;
      if (std::getenv("BENCH_VERBOSE"))
        std::printf("  step %d try %d tau %.3g E %.4g held %d %s %s\n", r.step, r.attempt, r.tau, r.energy, r.held_back_vertices,
                    r.accepted ? "ok" : to_string(r.rejection), r.detail.c_str());
    });
  } catch (const NumericalError& e) {
    failure = e.what();
  }
  if (!out.empty()) write_mesh(out, mesh);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[smooth scan] %s: %d vertices, relaxation %.2f: %s after %.1f s, %d accepted / %d "
              "rejected steps, t = %.3g of %.3g (%s); energy %.4g -> %.4g; noise index %.3f -> %.3f; "
              "%d of %d faces inverted against the input; finite: %s\n",
              path.c_str(), mesh.num_vertices(), options.flow.tangential_relaxation,
              failure.empty() ? "finished" : failure.c_str(), seconds, accepted, rejected, time, end_time,
              failure.empty() ? to_string(report.stop_reason) : "failed", report.initial_energy,
              report.final_energy, noise_index(input, mesh.F, topo), noise_index(mesh.V, mesh.F, topo),
              count_inverted_faces(input, mesh.V, mesh.F), mesh.num_faces(),
              mesh.V.allFinite() ? "yes" : "no");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"`fairsurf smooth` on the raw scans of data/ with the CLI's options", "bench_smooth_scan"};
  bench::take_last_values(app);
  std::vector<std::string> scans;
  double relax = -1;
  std::string out;
  app.add_option("scans", scans, "The scans to run (default: demosthenes_scan_lowres.obj and hammer_rawscan.obj)")
      ->type_name("PATH");
  app.add_option("--relax", relax, "Tangential relaxation weight W (0 turns it off; < 0: the CLI's)")->type_name("W");
  app.add_option("--out", out, "Write the result to PATH")->type_name("PATH");
  CLI11_PARSE(app, argc, argv);
  if (scans.empty())
    scans = {std::string(FAIRSURF_DATA_DIR) + "/demosthenes_scan_lowres.obj",
             std::string(FAIRSURF_DATA_DIR) + "/hammer_rawscan.obj"};
  if (std::FILE* load = std::fopen("/proc/loadavg", "r")) {
    char line[128] = {};
    if (std::fgets(line, sizeof line, load)) std::printf("[smooth scan] load average: %s", line);
    std::fclose(load);
  }
  for (const std::string& scan : scans) run_scan(scan, relax, out);
}
