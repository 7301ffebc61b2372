// The C++ side of bench/bench_python.py (the Python bindings' overhead): the median and the least
// process CPU time of the library calls that the script times through `fairsurf` on the same
// inputs. CPU time, not wall time: on a shared machine other load blurs wall times by ±50%, while
// the CPU time of a single-threaded call (the script sets OMP_NUM_THREADS=1) is its own work.
// Prints JSON.
//   bench_python_reference FILL_MESH CURVATURE_EDGE_LENGTH REPEATS
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/scenes.h>
#include <fairsurf/geometry/curvatures.h>
#include <fairsurf/io/io.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class Call>
double seconds_of(Call&& call) {
  const double start = cpu_seconds();
  call();
  return cpu_seconds() - start;
}

// Median and minimum of `repeats` runs; `run` returns the seconds of one timed run.
template <class Run>
std::pair<double, double> timings(int repeats, Run&& run) {
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) seconds.push_back(run());
  std::sort(seconds.begin(), seconds.end());
  return {seconds[repeats / 2], seconds.front()};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s FILL_MESH CURVATURE_EDGE_LENGTH REPEATS\n", argv[0]);
    return 2;
  }
  const fairsurf::Mesh holed = fairsurf::read_mesh(argv[1]);
  const fairsurf::Mesh cylinder = fairsurf::make_scene("fig7", {std::stod(argv[2])}).mesh;
  const int repeats = std::stoi(argv[3]);
  // The binding copies its input into a Mesh it then fills, so the copy is not part of this time.
  const auto [fill_median, fill_min] = timings(repeats, [&] {
    fairsurf::Mesh mesh = holed;
    return seconds_of([&] { fairsurf::fill_holes(mesh); });
  });
  const auto [curvature_median, curvature_min] =
      timings(repeats, [&] { return seconds_of([&] { fairsurf::curvatures(cylinder); }); });
  std::printf("{\"fill\": [%.6f, %.6f], \"curvature\": [%.6f, %.6f]}\n", fill_median, fill_min,
              curvature_median, curvature_min);
  return 0;
}
