// Fits and operators (METHOD §3) on spot.obj Loop-subdivided 1, 3 and 4 times (11.7k, 187k and
// 750k vertices): wall time per phase — building the fits (neighbourhood choice included),
// operator assembly (patterns and values), re-evaluation on moved positions (refit + update in
// place), the normal-weighted A_H and A_K — and memory per vertex of the fits and the operators.
// Targets: all fits and operators for ~1M vertices in under 1.5 s wall on 2 cores (compare per
// vertex), under 1.5 KB per vertex. Single-thread figures: OMP_NUM_THREADS=1.
#include <fairsurf/io.h>
#include <fairsurf/operators.h>
#include <fairsurf/quadratic_fit.h>
#include <fairsurf/topology.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <string>

#include "loop_subdivision.h"

using namespace fairsurf;

namespace {

struct Fixture {
  Mesh mesh;
  Vertices moved;
  Topology topo;
};

// spot.obj after `levels` rounds of Loop subdivision; the moved positions are scaled by 1.001.
const Fixture& fixture(int levels) {
  static std::map<int, Fixture> cache;
  auto [it, inserted] = cache.try_emplace(levels);
  if (inserted) {
    it->second.mesh = bench::loop_subdivide(read_mesh(std::string(FAIRSURF_DATA_DIR) + "/spot.obj"), levels);
    it->second.topo = build_topology(it->second.mesh.F, it->second.mesh.num_vertices());
    it->second.moved = it->second.mesh.V * 1.001;
  }
  return it->second;
}

double bytes(const Csr& c) { return 4.0 * (c.offsets.size() + c.indices.size()); }
double bytes(const SparseOperator& m) { return 12.0 * m.nonZeros() + 4.0 * (m.rows() + 1); }

double bytes(const QuadraticFits& f) {
  const double n = f.num_vertices();
  return bytes(f.neighbours) + bytes(f.vertex_faces) + bytes(f.outer_faces) +
         8.0 * f.coefficients.size() + n * (1 + 1 + 9 * 8 + 8) + 12.0 * f.faces.rows();
}

double bytes(const SurfaceOperators& o) {
  double total = bytes(o.laplace) + bytes(o.giaquinta);
  for (int c = 0; c < 3; ++c) total += bytes(o.gradient[c]) + bytes(o.second_gradient[c]);
  return total + 8.0 * o.geometry.H.size() * (3 + 5);
}

// Frees the previous iteration's result outside the timed region: a build happens once per
// connectivity, and returning hundreds of megabytes to the system is not part of it.
template <class T>
void release_untimed(benchmark::State& state, T& result) {
  state.PauseTiming();
  result = T{};
  state.ResumeTiming();
}

void per_vertex(benchmark::State& state, int vertices) {
  state.counters["vertices"] = vertices;
  state.counters["us_per_vertex"] =
      benchmark::Counter(static_cast<double>(vertices) * 1e-6,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_FitBuild(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  QuadraticFits fits;
  for (auto _ : state) {
    release_untimed(state, fits);
    fits = fit_quadratics(f.mesh.V, f.mesh.F, f.topo);
  }
  per_vertex(state, f.mesh.num_vertices());
  state.counters["fit_bytes_per_vertex"] = bytes(fits) / f.mesh.num_vertices();
  state.counters["two_ring_vertices"] = static_cast<double>(
      std::count_if(fits.neighbourhood.begin(), fits.neighbourhood.end(),
                    [](Neighbourhood r) { return r != Neighbourhood::kOneRing; }));
}

void BM_Refit(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  QuadraticFits fits = fit_quadratics(f.mesh.V, f.mesh.F, f.topo);
  for (auto _ : state) refit_quadratics(fits, f.moved);
  per_vertex(state, f.mesh.num_vertices());
}

void BM_OperatorsBuild(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  const QuadraticFits fits = fit_quadratics(f.mesh.V, f.mesh.F, f.topo);
  SurfaceOperators ops;
  for (auto _ : state) {
    release_untimed(state, ops);
    ops = compute_operators(fits, f.mesh.V);
  }
  per_vertex(state, f.mesh.num_vertices());
  state.counters["operator_bytes_per_vertex"] = bytes(ops) / f.mesh.num_vertices();
  state.counters["total_bytes_per_vertex"] = (bytes(ops) + bytes(fits)) / f.mesh.num_vertices();
}

void BM_OperatorsUpdate(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  QuadraticFits fits = fit_quadratics(f.mesh.V, f.mesh.F, f.topo);
  SurfaceOperators ops = compute_operators(fits, f.mesh.V);
  refit_quadratics(fits, f.moved);
  for (auto _ : state) update_operators(fits, f.moved, ops);
  per_vertex(state, f.mesh.num_vertices());
}

// Everything a flow step re-evaluates: refit, operators, A_H and A_K.
void BM_StepReevaluation(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  QuadraticFits fits = fit_quadratics(f.mesh.V, f.mesh.F, f.topo);
  SurfaceOperators ops = compute_operators(fits, f.mesh.V);
  SparseOperator A_H, A_K;
  for (auto _ : state) {
    refit_quadratics(fits, f.moved);
    update_operators(fits, f.moved, ops);
    normal_weighted(ops.laplace, ops.geometry.normal, A_H);
    normal_weighted(ops.giaquinta, ops.geometry.normal, A_K);
  }
  per_vertex(state, f.mesh.num_vertices());
}

// From nothing but the mesh and its topology to all fits and operators.
void BM_AllFitsAndOperators(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  QuadraticFits fits;
  SurfaceOperators ops;
  for (auto _ : state) {
    release_untimed(state, fits);
    release_untimed(state, ops);
    fits = fit_quadratics(f.mesh.V, f.mesh.F, f.topo);
    ops = compute_operators(fits, f.mesh.V);
  }
  per_vertex(state, f.mesh.num_vertices());
}

void sizes(benchmark::internal::Benchmark* b) {
  b->ArgName("loop_levels")->Arg(1)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace

BENCHMARK(BM_FitBuild)->Apply(sizes);
BENCHMARK(BM_Refit)->Apply(sizes);
BENCHMARK(BM_OperatorsBuild)->Apply(sizes);
BENCHMARK(BM_OperatorsUpdate)->Apply(sizes);
BENCHMARK(BM_StepReevaluation)->Apply(sizes);
BENCHMARK(BM_AllFitsAndOperators)->Apply(sizes);
BENCHMARK_MAIN();
