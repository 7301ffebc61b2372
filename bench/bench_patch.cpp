// The patch stage (method.md §7): hole triangulation time against hole size, and refinement and
// membrane relaxation time against the number of new vertices.
//
// The hole is the inner loop of an annulus: n vertices on a unit circle lifted by a wave
// z = 0.2 sin 3θ (non-planar, so the dihedral weights matter), the mesh around it a ring of
// triangles out to radius 2. Triangulation: n = 50, 200 (Liepa's programme) and 800 (divided
// into pieces of at most 200), plus the programme forced on 400 and 800 to show its O(n³) cost.
// Refinement: a 200-edge hole refined to a target edge length that yields about 1k, 10k and 100k
// new vertices (an equilateral mesh of edge L covers area π with about 2π/(√3 L²) vertices), then
// the membrane relaxation of those vertices (one cotangent solve, MUMPS).
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/hole_triangulation.h>
#include <fairsurf/patch/membrane.h>
#include <fairsurf/patch/patch_refinement.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace fairsurf;

namespace {

struct Hole {
  Mesh mesh;
  Topology topo;
  std::vector<int> loop;
};

Hole wavy_hole(int n) {
  Hole h;
  h.mesh.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    h.mesh.V.row(i) << std::cos(t), std::sin(t), 0.2 * std::sin(3 * t);
    h.mesh.V.row(n + i) << 2 * std::cos(t), 2 * std::sin(t), 0.2 * std::sin(3 * t);
  }
  h.mesh.F.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const int a = i, b = (i + 1) % n;
    h.mesh.F.row(2 * i) << a, n + i, n + b;
    h.mesh.F.row(2 * i + 1) << a, n + b, b;
  }
  h.topo = build_topology(h.mesh.F, 2 * n);
  for (const auto& loop : boundary_loops(h.mesh.F, h.topo))
    if (loop.front() == 0) h.loop = loop;
  return h;
}

// `starts`: HoleTriangulationOptions::start_vertices.
void triangulate(benchmark::State& state, int threshold, int starts = HoleTriangulationOptions{}.start_vertices) {
  const Hole h = wavy_hole(static_cast<int>(state.range(0)));
  HoleTriangulation t;
  for (auto _ : state) {
    t = triangulate_hole(h.mesh.V, h.mesh.F, h.topo, h.loop,
                         {.max_dynamic_programming_size = threshold, .start_vertices = starts});
    benchmark::DoNotOptimize(t.faces.data());
  }
  state.counters["loop_edges"] = static_cast<double>(h.loop.size());
  state.counters["divided"] = t.divided;
  state.counters["max_dihedral_rad"] = t.max_dihedral_angle;
}

void BM_TriangulateHole(benchmark::State& state) { triangulate(state, 200); }
void BM_TriangulateHoleFirstStartOnly(benchmark::State& state) { triangulate(state, 200, 1); }
void BM_TriangulateHoleWholeProgramme(benchmark::State& state) { triangulate(state, 100000); }

double target_for(double new_vertices) { return std::sqrt(2 * std::numbers::pi / (std::sqrt(3.0) * new_vertices)); }

void BM_RefinePatch(benchmark::State& state) {
  const Hole h = wavy_hole(200);
  const Faces coarse = triangulate_hole(h.mesh.V, h.mesh.F, h.topo, h.loop).faces;
  const double target = target_for(static_cast<double>(state.range(0)));
  RefinedPatch r;
  for (auto _ : state) {
    r = refine_patch(h.mesh.V, h.mesh.F, coarse, {.target_edge_length = target});
    benchmark::DoNotOptimize(r.V.data());
  }
  double sum = 0.0;
  int count = 0;
  for (int f = r.first_patch_face; f < r.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (r.V.row(r.F(f, k)) - r.V.row(r.F(f, (k + 1) % 3))).norm(), ++count;
  state.counters["new_vertices"] = static_cast<double>(r.free_vertices.size());
  state.counters["mean_edge_over_target"] = sum / count / target;
  state.counters["rounds"] = r.rounds;
  state.counters["flips"] = r.flips;
}

void BM_RelaxMembrane(benchmark::State& state) {
  const Hole h = wavy_hole(200);
  const Faces coarse = triangulate_hole(h.mesh.V, h.mesh.F, h.topo, h.loop).faces;
  const RefinedPatch r = refine_patch(h.mesh.V, h.mesh.F, coarse,
                                      {.target_edge_length = target_for(static_cast<double>(state.range(0)))});
  MembraneReport report;
  for (auto _ : state) {
    Vertices V = r.V;
    report = relax_membrane(V, r.F, r.free_vertices, {.iterations = 1});
    benchmark::DoNotOptimize(V.data());
  }
  state.counters["free_vertices"] = static_cast<double>(r.free_vertices.size());
  state.counters["area_before"] = report.area.front();
  state.counters["area_after"] = report.area.back();
}

}  // namespace

BENCHMARK(BM_TriangulateHole)->Arg(50)->Arg(200)->Arg(800)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateHoleFirstStartOnly)->Arg(50)->Arg(200)->Arg(800)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateHoleWholeProgramme)->Arg(400)->Arg(800)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RefinePatch)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RelaxMembrane)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
