// Rendering a ~1M-triangle mesh (blub.obj after three rounds of Loop subdivision: 909,312 triangles)
// coloured by its mean curvature into a 1600x1200 image (target: under 1 s on 2 cores), and encoding
// that image as PNG. "CPU" is the whole process's CPU time (all threads): on a loaded machine,
// CPU / threads estimates the wall time on free cores.
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/render/render.h>

#include <benchmark/benchmark.h>

#include <filesystem>

#include "subdivision.h"

namespace {

using namespace fairsurf;

struct Scene {
  Mesh mesh;
  Eigen::VectorXd H;
};

const Scene& fine_blub() {
  static const Scene scene = [] {
    Scene s;
    s.mesh = bench::loop_subdivide(read_mesh(std::string(FAIRSURF_DATA_DIR) + "/blub.obj"), 3);
    const Topology topo = build_topology(s.mesh.F, s.mesh.num_vertices());
    s.H = compute_geometry(fit_quadratics(s.mesh.V, s.mesh.F, topo), s.mesh.V).H;
    return s;
  }();
  return scene;
}

RenderOptions figure_options(int supersampling) {
  RenderOptions o;
  o.width = 1600;
  o.height = 1200;
  o.title = "blub, three rounds of Loop subdivision";
  o.quantity = "mean curvature H";  // (a one-letter literal trips GCC 12's bogus -Wrestrict)
  o.supersampling = supersampling;
  return o;
}

void BM_Render1MTriangles(benchmark::State& state) {
  const Scene& scene = fine_blub();
  const RenderOptions o = figure_options(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(render({{&scene.mesh, scene.H, ""}}, o));
  state.counters["triangles"] = scene.mesh.num_faces();
  state.counters["supersampling"] = o.supersampling;
}
BENCHMARK(BM_Render1MTriangles)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

void BM_WritePng1600x1200(benchmark::State& state) {
  const Scene& scene = fine_blub();
  const Image image = render({{&scene.mesh, scene.H, ""}}, figure_options(3));
  const auto path = std::filesystem::temp_directory_path() / "fairsurf_bench_render.png";
  for (auto _ : state) write_png(path, image);
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}
BENCHMARK(BM_WritePng1600x1200)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
