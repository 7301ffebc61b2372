// repair on a ~1M-face mesh: data/hammer_rawscan.obj (a closed raw scan, 60k faces) Loop-subdivided
// twice (962k faces, 481k vertices).
//   clean:  the mesh as it is: every operation runs and finds nothing (the cost of `--repair` on a
//           good input).
//   broken: the same mesh as an unwelded soup (2.9M vertex records), with every 50th face
//           repeated and every 7th face flipped: merge, duplicate faces and orientation have work.
// Target: under 1 s for the clean mesh. Each iteration repairs a fresh copy (copying not timed).
#include <fairsurf/applications/repair.h>
#include <fairsurf/io/io.h>

#include <benchmark/benchmark.h>

#include <iostream>
#include <string>

#include "subdivision.h"

namespace {

const fairsurf::Mesh& clean_mesh() {
  static const fairsurf::Mesh mesh = fairsurf::bench::loop_subdivide(
      fairsurf::read_mesh(std::string(FAIRSURF_DATA_DIR) + "/hammer_rawscan.obj"), 2);
  return mesh;
}

fairsurf::Mesh broken_mesh() {
  const fairsurf::Mesh& clean = clean_mesh();
  fairsurf::Mesh soup;
  const int faces = clean.num_faces();
  soup.V.resize(3 * faces, 3);
  soup.F.resize(faces + faces / 50, 3);
  for (int f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      soup.V.row(3 * f + k) = clean.V.row(clean.F(f, k));
      soup.F(f, k) = 3 * f + (f % 7 == 0 ? 2 - k : k);
    }
  for (int i = 0; i < faces / 50; ++i) soup.F.row(faces + i) = soup.F.row(50 * i);
  return soup;
}

void run(benchmark::State& state, const fairsurf::Mesh& input) {
  fairsurf::RepairReport report;
  for (auto _ : state) {
    state.PauseTiming();
    fairsurf::Mesh mesh = input;
    state.ResumeTiming();
    report = fairsurf::repair(mesh);
    benchmark::DoNotOptimize(mesh.F.data());
  }
  state.counters["faces"] = input.num_faces();
  state.counters["merged"] = report.vertices_merged;
  state.counters["flipped"] = report.faces_flipped;
  state.counters["duplicates"] = report.duplicate_faces_removed;
}

void BM_RepairClean(benchmark::State& state) { run(state, clean_mesh()); }
void BM_RepairBroken(benchmark::State& state) {
  static const fairsurf::Mesh broken = broken_mesh();
  run(state, broken);
}

BENCHMARK(BM_RepairClean)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_RepairBroken)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
