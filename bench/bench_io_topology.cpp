// Reading a large binary PLY and building its connectivity: time of each step and peak memory.
//
// data/spot.obj is Loop-subdivided 4 times (~750k vertices, 1.5M triangles) and written as a
// binary PLY to /tmp. The peak memory of read_mesh + build_topology is measured in a process whose
// heap has never held the subdivided mesh (a forked child makes the file), as the growth of VmHWM
// over VmRSS before reading, and reported per vertex beyond the raw V (24 B) and F (12 B) arrays.
// Targets: read + connectivity under 2 s, under 400 bytes per vertex.
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/topology.h>

#include <benchmark/benchmark.h>

#include "process_memory.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "subdivision.h"

namespace {

constexpr int kLevels = 4;

// Named after the parent's pid, fixed before the fork.
const std::string kPlyPath = "/tmp/fairsurf_bench_io_" + std::to_string(::getpid()) + ".ply";
const std::string& ply_path() { return kPlyPath; }

// Makes the benchmark file in a child process, so that this process's heap stays untouched.
bool write_subdivided_ply() {
  const pid_t child = ::fork();
  if (child == 0) {
    try {
      const fairsurf::Mesh spot = fairsurf::read_mesh(std::string(FAIRSURF_DATA_DIR) + "/spot.obj");
      fairsurf::write_mesh(ply_path(), fairsurf::bench::loop_subdivide(spot, kLevels));
      ::_exit(0);
    } catch (const std::exception& e) {
      std::cerr << "bench_io_topology: " << e.what() << "\n";
      ::_exit(1);
    }
  }
  int status = 0;
  return child > 0 && ::waitpid(child, &status, 0) == child && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void report_single_run() {
  using clock = std::chrono::steady_clock;
  const long long rss_before = fairsurf::bench::proc_status_bytes("VmRSS:");
  const auto t0 = clock::now();
  const fairsurf::Mesh mesh = fairsurf::read_mesh(ply_path());
  const auto t1 = clock::now();
  const fairsurf::Topology topology = fairsurf::build_topology(mesh.F, mesh.num_vertices());
  const auto t2 = clock::now();
  const long long peak = fairsurf::bench::proc_status_bytes("VmHWM:") - rss_before;
  benchmark::DoNotOptimize(topology.edges.data());

  const double nv = mesh.num_vertices();
  const double raw = 24.0 * nv + 12.0 * mesh.num_faces();
  const double read_s = std::chrono::duration<double>(t1 - t0).count();
  const double topo_s = std::chrono::duration<double>(t2 - t1).count();
  std::printf("mesh: %d vertices, %d triangles, %.1f MB binary PLY\n", mesh.num_vertices(), mesh.num_faces(),
              static_cast<double>(std::filesystem::file_size(ply_path())) / 1e6);
  std::printf("single run: read_mesh %.3f s, build_topology %.3f s, total %.3f s (target < 2 s)\n", read_s,
              topo_s, read_s + topo_s);
  std::printf("peak memory growth: %.1f MB = %.0f B/vertex; raw V+F %.0f B/vertex; beyond V+F %.0f B/vertex "
              "(target < 400)\n",
              static_cast<double>(peak) / 1e6, static_cast<double>(peak) / nv, raw / nv,
              (static_cast<double>(peak) - raw) / nv);
}

void BM_ReadMesh(benchmark::State& state) {
  for (auto _ : state) {
    const fairsurf::Mesh mesh = fairsurf::read_mesh(ply_path());
    benchmark::DoNotOptimize(mesh.V.data());
    state.counters["vertices"] = mesh.num_vertices();
  }
}

void BM_BuildTopology(benchmark::State& state) {
  const fairsurf::Mesh mesh = fairsurf::read_mesh(ply_path());
  for (auto _ : state) {
    const fairsurf::Topology topology = fairsurf::build_topology(mesh.F, mesh.num_vertices());
    benchmark::DoNotOptimize(topology.edges.data());
  }
}

BENCHMARK(BM_ReadMesh)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_BuildTopology)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

int main(int argc, char** argv) {
  if (!write_subdivided_ply()) return 1;
  report_single_run();  // first, while the heap is fresh
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove(ply_path());
  return 0;
}
