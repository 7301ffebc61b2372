// How close `fairsurf smooth` brings a noisy copy of a real shape back to it (docs/flow.md, "The
// default time"): the clean closed meshes of bench_real_holes (spot, blub, the closed bunny, ...)
// get normal noise of σ = 0.2 h̄ (fixed seed), and each flow smooths them with the CLI's options
// (scan_smoothing_options) to its default time, times --time-scale. Prints, per mesh and flow, the
// mean and max distance of the vertices to the clean surface in h̄ (searched over the clean faces
// within 3 rings of the same vertex: smoothing keeps the connectivity and moves a vertex by less
// than an edge or two), beside the noisy copy's.
//
// Usage: bench_denoise [--mesh NAME] [--sigma S (0.2)] [--time-scale S (1)] [--tau-max F]
//   --time-scale 97.41 (π⁴) runs the sixth-order flow to the earlier default time (2h̄)⁶;
//   --tau-max F bounds the step τ by F times the end time (the CLI's bound: FlowOptions::tau_max).
#include <fairsurf/applications/smooth.h>
#include <fairsurf/mesh/topology.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "bench_options.h"
#include "real_holes.h"
#include "real_holes_cases.h"

namespace {

using namespace fairsurf;

struct Args {
  std::string mesh;
  double sigma = 0.2;
  double time_scale = 1.0;
  double tau_max_fraction = 0;  ///< > 0: the largest step, as a fraction of the end time
};

// --sigma and --time-scale: a number > 0, NaN refused. Not CLI::PositiveNumber: it lets NaN through,
// and its refusal prints DBL_MAX's 309 digits.
CLI::Validator positive() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && value > 0) return "";
        return "must be a number > 0, got " + text;
      },
      "POSITIVE");
}

void add_options(CLI::App& app, Args& args) {
  app.add_option("--mesh", args.mesh, "Only the bundled meshes whose file name contains NAME")->type_name("NAME");
  app.add_option("--sigma", args.sigma, "Noise σ in mean edge lengths h̄")
      ->type_name("S")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--time-scale", args.time_scale, "Multiplies each flow's default end time")
      ->type_name("S")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--tau-max", args.tau_max_fraction, "Bound the step τ by F times the end time (<= 0: no bound)")
      ->type_name("F");
}

// For each vertex, the clean faces within 3 rings of it (the search set of `distances`). The rings
// are gathered here with one marker array for all vertices: topology.h's k_ring allocates and scans
// #V per call.
std::vector<std::vector<int>> nearby_faces(const Mesh& clean, const Topology& topo) {
  std::vector<std::vector<int>> nearby(clean.num_vertices());
  std::vector<int> mark(clean.num_vertices(), -1);
  for (int v = 0; v < clean.num_vertices(); ++v) {
    std::vector<int> ring{v};
    mark[v] = v;
    for (int r = 0, begin = 0; r < 3; ++r) {
      const int end = static_cast<int>(ring.size());
      for (int i = begin; i < end; ++i)
        for (int u : topo.vertex_vertices.row(ring[i]))
          if (mark[u] != v) {
            mark[u] = v;
            ring.push_back(u);
          }
      begin = end;
    }
    for (int u : ring) {
      const auto faces = topo.vertex_faces.row(u);
      nearby[v].insert(nearby[v].end(), faces.begin(), faces.end());
    }
    std::sort(nearby[v].begin(), nearby[v].end());
    nearby[v].erase(std::unique(nearby[v].begin(), nearby[v].end()), nearby[v].end());
  }
  return nearby;
}

struct Distances {
  double mean = 0, max = 0;
};

Distances distances(const Mesh& clean, const std::vector<std::vector<int>>& nearby, const Vertices& V, double h) {
  Distances d;
  for (int v = 0; v < V.rows(); ++v) {
    double best = std::numeric_limits<double>::infinity();
    for (int f : nearby[v])
      best = std::min(best, bench::point_triangle_distance(V.row(v).transpose(), clean.V.row(clean.F(f, 0)).transpose(),
                                                           clean.V.row(clean.F(f, 1)).transpose(),
                                                           clean.V.row(clean.F(f, 2)).transpose()));
    d.mean += best;
    d.max = std::max(d.max, best);
  }
  d.mean /= static_cast<double>(V.rows()) * h;
  d.max /= h;
  return d;
}

void run_mesh(const bench::ClosedMesh& m, const Args& args) {
  const Topology topo = build_topology(m.mesh.F, m.mesh.num_vertices());
  const std::vector<std::vector<int>> nearby = nearby_faces(m.mesh, topo);
  Mesh noisy = m.mesh;
  bench::add_normal_noise(noisy, args.sigma * m.h, 12345);
  const Distances input = distances(m.mesh, nearby, noisy.V, m.h);
  std::printf("%-10s %6d vertices, noise %.2f h: mean %.4f h, max %.3f h\n", m.name.c_str(), m.mesh.num_vertices(),
              args.sigma, input.mean, input.max);
  for (FlowKind kind : {FlowKind::sixth_order, FlowKind::willmore, FlowKind::mean_curvature}) {
    Mesh smoothed = noisy;
    SmoothOptions options = scan_smoothing_options(smoothed, kind);
    set_smoothing_end(options, {.time = options.flow.end_time * args.time_scale});
    if (args.tau_max_fraction > 0) {
      options.flow.tau_max = args.tau_max_fraction * options.flow.end_time;
      options.flow.tau = std::min(options.flow.tau, options.flow.tau_max);
    }
    try {
      const FlowReport report = smooth(smoothed, options);
      const Distances d = distances(m.mesh, nearby, smoothed.V, m.h);
      std::printf("  %-15s t %.3g: %3d steps (%d rejected), %-9s mean %.4f h (%.2f of the noise's), max %.3f h\n",
                  to_string(kind), report.time, report.accepted_steps, report.rejected_steps,
                  to_string(report.stop_reason), d.mean, d.mean / input.mean, d.max);
    } catch (const std::exception& e) {
      std::printf("  %-15s failed: %s\n", to_string(kind), e.what());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"How close `fairsurf smooth` brings a noisy copy of a real shape back to it", "bench_denoise"};
  bench::take_last_values(app);
  Args args;
  add_options(app, args);
  CLI11_PARSE(app, argc, argv);
  try {
    for (const bench::ClosedMesh& m : bench::read_bundled_meshes(args.mesh)) run_mesh(m, args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_denoise: %s\n", e.what());
    return 1;
  }
  return 0;
}
