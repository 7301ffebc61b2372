// Region fairing (METHOD §7, free-form design) against region size: the METHOD §8.6 scene — a unit
// icosphere whose cap z > 0.5 is freed and flattened — at icosphere levels 4 to 8 (about 640,
// 2.6k, 10k, 41k and 164k free vertices; the flat start only up to level 6), G2 sixth-order flow to its steady state, started from the
// re-evaluated ∆³ solution (FairRegionOptions::harmonic_started(), what `fairsurf fair` and fill
// use; method 2) and from the flattened cap (the plain defaults; method 0), beside the cotangent
// ∆³x = 0 baseline on the same patch (method 1). Prints steps, seconds per step, total seconds, peak memory
// and the deviation max|r − 1| each method leaves. Larger regions cost a proportionally larger
// factorization per step (bench_flow measures the step alone up to 164k vertices).
#include <fairsurf/fair_region.h>
#include <fairsurf/scenes.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>

#include "process_memory.h"

using namespace fairsurf;

namespace {

double max_radius_error(const Mesh& mesh, const std::vector<int>& free) {
  double worst = 0;
  for (int v : free) worst = std::max(worst, std::abs(mesh.V.row(v).norm() - 1.0));
  return worst;
}

void BM_FairCap(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const bool harmonic = state.range(1) == 1;
  FairRegionOptions options;
  if (harmonic) options.method = FairMethod::harmonic;
  if (state.range(1) == 2) options = FairRegionOptions::harmonic_started();
  FairRegionReport report;
  double deviation = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Scene scene = sphere_cap_scene(level);
    state.ResumeTiming();
    report = fair_region(scene.mesh, scene.free_vertices, options);
    deviation = max_radius_error(scene.mesh, scene.free_vertices);
  }
  const int steps = harmonic ? 1 : report.flow.accepted_steps + report.flow.rejected_steps;
  state.counters["free"] = report.free_vertices;
  state.counters["steps"] = steps;
  state.counters["s_per_step"] = report.seconds / steps;
  state.counters["max_r_err"] = deviation;
  state.counters["peak_MB"] = static_cast<double>(bench::peak_bytes()) / 1e6;
  std::printf("[fair] level %d %s: %d free vertices, %d trial steps, %.3f s (%.3f s/step), "
              "max|r-1| %.3g, peak %.0f MB\n",
              level, harmonic ? "harmonic k=3" : state.range(1) == 2 ? "G2 flow from ∆³" : "G2 flow from flat", report.free_vertices, steps, report.seconds,
              report.seconds / steps, deviation, static_cast<double>(bench::peak_bytes()) / 1e6);
}

}  // namespace

BENCHMARK(BM_FairCap)
    ->ArgsProduct({{4, 5, 6}, {2, 1, 0}})
    ->Args({7, 2})  // ~41k and ~164k free vertices: the flat start (300 steps) is left out there
    ->Args({7, 1})
    ->Args({8, 2})
    ->Args({8, 1})
    ->ArgNames({"level", "harmonic"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
