// Region fairing (method.md §7, free-form design) against region size: the method.md §8.6 scene — a unit
// icosphere whose cap z > 0.5 is freed and flattened — at icosphere levels 4 to 8 (about 640, 2.6k,
// 10k, 41k and 164k free vertices). Three setups: the G2 sixth-order flow to its steady state started
// from the re-evaluated ∆³ solution (FairRegionOptions::harmonic_started(), what `fairsurf fair` and
// fill use), the same flow from the flattened cap (the plain defaults; only up to level 6, it needs
// ~300 steps), and the cotangent ∆³x = 0 baseline on the same patch. Prints steps, seconds per step,
// total seconds, peak memory and the deviation max|r − 1| each leaves.
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/scenes.h>

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

// The three runs compared at each size (the benchmark's second argument).
enum Setup { flat_start = 0, harmonic_baseline = 1, harmonic_start = 2 };

FairRegionOptions options_for(Setup setup) {
  if (setup == harmonic_start) return FairRegionOptions::harmonic_started();
  FairRegionOptions options;
  if (setup == harmonic_baseline) options.method = FairMethod::harmonic;
  return options;
}

const char* name_of(Setup setup) {
  constexpr const char* names[] = {"G2 flow from flat", "harmonic k=3", "G2 flow from ∆³"};
  return names[setup];
}

void BM_FairCap(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const auto setup = static_cast<Setup>(state.range(1));
  const bool harmonic = setup == harmonic_baseline;
  const FairRegionOptions options = options_for(setup);
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
              level, name_of(setup), report.free_vertices, steps, report.seconds,
              report.seconds / steps, deviation, static_cast<double>(bench::peak_bytes()) / 1e6);
}

}  // namespace

BENCHMARK(BM_FairCap)
    ->ArgsProduct({{4, 5, 6}, {harmonic_start, harmonic_baseline, flat_start}})
    ->Args({7, harmonic_start})  // ~41k and ~164k free vertices: the flat start (300 steps) is left out
    ->Args({7, harmonic_baseline})
    ->Args({8, harmonic_start})
    ->Args({8, harmonic_baseline})
    ->ArgNames({"level", "setup"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
