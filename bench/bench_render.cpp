// Rendering a 1M-triangle torus coloured by its Gaussian curvature into a 1600x1200 image (target:
// under 1 s on 2 cores), and encoding that image as PNG. "CPU" is the whole process's CPU time (all
// threads): on a loaded machine, CPU / threads estimates the wall time on free cores.
#include <fairsurf/render.h>

#include <benchmark/benchmark.h>

#include "../tests/support/render_meshes.h"

namespace {

using namespace fairsurf;

constexpr int kAround = 1000, kTube = 500;  // 2 * 1000 * 500 = 1M triangles

const Mesh& fine_torus() {
  static const Mesh mesh = test::torus(1.0, 0.4, kAround, kTube);
  return mesh;
}

const Eigen::VectorXd& torus_curvature() {
  static const Eigen::VectorXd K = test::torus_gaussian_curvature(1.0, 0.4, kAround, kTube);
  return K;
}

RenderOptions figure_options(int supersampling) {
  RenderOptions o;
  o.width = 1600;
  o.height = 1200;
  o.title = "A torus of one million triangles";
  o.quantity = "Gaussian curvature K";  // (a one-letter literal trips GCC 12's bogus -Wrestrict)
  o.supersampling = supersampling;
  return o;
}

void BM_RenderTorus1M(benchmark::State& state) {
  const RenderOptions o = figure_options(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(render({{&fine_torus(), torus_curvature(), ""}}, o));
  state.counters["triangles"] = fine_torus().num_faces();
  state.counters["supersampling"] = o.supersampling;
}
BENCHMARK(BM_RenderTorus1M)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

void BM_WritePng1600x1200(benchmark::State& state) {
  const Image image = render({{&fine_torus(), torus_curvature(), ""}}, figure_options(1));
  const auto path = std::filesystem::temp_directory_path() / "fairsurf_bench_render.png";
  for (auto _ : state) write_png(path, image);
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}
BENCHMARK(BM_WritePng1600x1200)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
