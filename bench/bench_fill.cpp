// Hole filling end to end (fill_holes) against patch size: a unit icosphere with the faces above
// z = c removed, filled with G2 data by the sixth-order flow (f = H, FillOptions defaults: start from
// the re-evaluated ∆³ solution, first step τ = 1e-2, steady stopping) and by the tri-harmonic
// baseline. Sizes: ~800 new vertices (5 subdivisions, c = 0.8), ~2.5k (6, 0.84), ~6.5k (6, 0.5),
// ~10k (7, 0.84) and, with "large", ~100k (8, 0.53). Each case runs in a forked child, so that VmHWM
// is the case's own peak memory. Printed per case: new vertices, ∆³ solves of the flow's start,
// accepted steps (trial steps), mean time of a trial step (fit + assembly + factorization + solve,
// from the step records), total wall time of fill_holes (triangulation, refinement, membrane, ∆³,
// flow, checks), max|r − 1| over the new vertices, peak memory, and the report's note when the
// continuity fell back. Arguments: "large" adds the ~100k case, "harmonic" runs the baseline only.
// "small-holes" instead cuts ten balls of four mean edge lengths out of icospheres of 10k to 655k
// vertices and fills them: the time a small hole costs as the mesh around it grows (it should not
// grow with it). "one-ring-holes" removes the faces of 100, 400 and 1600 vertices spread over an
// icosphere of 41k vertices, the holes a scan has most: the time a hole costs as they crowd (fill
// joins holes whose rings overlap into groups; a hole should not cost in proportion to its group).
#include <fairsurf/applications/fill.h>
#include <fairsurf/mesh/errors.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "process_memory.h"
#include "step_matrix_sphere.h"

namespace {

using namespace fairsurf;

// `mesh` without the faces for which `removed(f)` holds (the vertices stay, unused).
Mesh without_faces(const Mesh& mesh, const std::function<bool(int)>& removed) {
  Mesh out;
  out.V = mesh.V;
  std::vector<int> kept;
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (!removed(f)) kept.push_back(f);
  out.F = mesh.F(kept, Eigen::all);
  return out;
}

// The icosphere of `subdivisions` without the faces for which `removed(corners)` holds.
Mesh icosphere_without(int subdivisions, const std::function<bool(const std::array<Eigen::Vector3d, 3>&)>& removed) {
  const Mesh sphere = bench::icosphere(subdivisions);
  return without_faces(sphere, [&](int f) {
    return removed({sphere.V.row(sphere.F(f, 0)).transpose(), sphere.V.row(sphere.F(f, 1)).transpose(),
                    sphere.V.row(sphere.F(f, 2)).transpose()});
  });
}

// `count` points spread evenly over the unit sphere (a Fibonacci lattice).
std::vector<Eigen::Vector3d> fibonacci_points(int count) {
  std::vector<Eigen::Vector3d> points;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count, r = std::sqrt(1.0 - z * z);
    points.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return points;
}

// fill_holes with the defaults on `mesh`, or nullopt after saying why it threw (`what`: the case).
std::optional<FillReport> fill_or_say(Mesh& mesh, const std::string& what) {
  try {
    return fill_holes(mesh, FillOptions{});
  } catch (const Error& e) {
    std::printf("%s: failed: %s\n", what.c_str(), e.what());
    return std::nullopt;
  }
}

// The icosphere without the faces that have a vertex above z = cap.
Mesh holed_sphere(int subdivisions, double cap) {
  return icosphere_without(subdivisions, [cap](const std::array<Eigen::Vector3d, 3>& corners) {
    return std::any_of(corners.begin(), corners.end(), [cap](const Eigen::Vector3d& p) { return p.z() > cap; });
  });
}

int run_case(int subdivisions, double cap, FairMethod method) {
  Mesh mesh = holed_sphere(subdivisions, cap);
  const int input_vertices = mesh.num_vertices();
  FillOptions o;
  o.method = method;
  int attempts = 0;
  double step_seconds = 0;
  const FillObserver observer = [&](std::span<const int>, const StepRecord& s) {
    ++attempts;
    step_seconds += s.fit_seconds + s.assembly_seconds + s.factorize_seconds + s.solve_seconds;
  };
  FillReport report;
  try {
    report = fill_holes(mesh, o, observer);
  } catch (const Error& e) {
    std::printf("%d subdivisions, cap z > %.1f, %s: failed: %s\n", subdivisions, cap, to_string(method), e.what());
    return 1;
  }
  const HoleReport& h = report.holes.front();
  if (h.status != HoleStatus::filled) {
    std::printf("%d subdivisions, cap z > %.1f, %s: hole %s: %s\n", subdivisions, cap, to_string(method),
                to_string(h.status), h.reason.c_str());
    return 1;
  }
  double deviation = 0;
  for (int v = input_vertices; v < mesh.num_vertices(); ++v)
    deviation = std::max(deviation, std::abs(mesh.V.row(v).norm() - 1.0));
  std::printf("%7d new vertices (%d subdivisions, cap z > %4.2f), %-8s: %d ∆³ solves, %3d steps (%d trials), "
              "%.3f s a trial step, fill_holes %.2f s; max|r-1| %.2e, max|V| %.2e; peak %.0f MB%s%s\n",
              h.vertices_added, subdivisions, cap, to_string(method), h.harmonic_solves, h.steps, attempts,
              attempts > 0 ? step_seconds / attempts : 0.0, report.seconds, deviation, h.final_max_velocity,
              static_cast<double>(bench::peak_bytes()) / 1e6, h.note.empty() ? "" : "; ", h.note.c_str());
  return 0;
}

// The icosphere without the faces whose three vertices lie within `radius` of one of ten points
// spread over it (a Fibonacci lattice).
Mesh sphere_with_small_holes(int subdivisions, double radius) {
  const std::vector<Eigen::Vector3d> centres = fibonacci_points(10);
  return icosphere_without(subdivisions, [&](const std::array<Eigen::Vector3d, 3>& corners) {
    return std::any_of(centres.begin(), centres.end(), [&](const Eigen::Vector3d& c) {
      return std::all_of(corners.begin(), corners.end(),
                         [&](const Eigen::Vector3d& p) { return (p - c).norm() < radius; });
    });
  });
}

// Ten holes of 4 mean edge lengths on an icosphere of `subdivisions`: seconds per hole (the hole
// reports' own, patch to checks) against the mesh's size.
int run_small_holes(int subdivisions) {
  const double edge = 1.1 * std::pow(0.5, subdivisions);  // the icosphere's mean edge, to a few percent
  Mesh mesh = sphere_with_small_holes(subdivisions, 4 * edge);
  const int input_vertices = mesh.num_vertices();
  const std::optional<FillReport> filled = fill_or_say(mesh, std::to_string(subdivisions) + " subdivisions, small holes");
  if (!filled) return 1;
  const FillReport& report = *filled;
  double total = 0, slowest = 0;
  int g2 = 0;
  for (const HoleReport& h : report.holes) {
    total += h.seconds;
    slowest = std::max(slowest, h.seconds);
    g2 += h.status == HoleStatus::filled && !h.linear;
  }
  const int holes = static_cast<int>(report.holes.size());
  std::printf("%7d vertices (%d subdivisions): %d holes (%d filled, %d G2), %.3f s a hole (slowest %.3f s), "
              "fill_holes %.2f s; peak %.0f MB\n",
              input_vertices, subdivisions, holes, report.filled, g2, holes > 0 ? total / holes : 0.0, slowest,
              report.seconds, static_cast<double>(bench::peak_bytes()) / 1e6);
  return report.filled == holes ? 0 : 1;
}

// The icosphere of `subdivisions` without the faces of the `count` vertices nearest to points spread
// over it (a Fibonacci lattice): one-ring holes.
Mesh sphere_with_one_ring_holes(int subdivisions, int count) {
  const Mesh sphere = bench::icosphere(subdivisions);
  std::vector<char> removed(sphere.num_vertices(), 0);
  for (const Eigen::Vector3d& p : fibonacci_points(count)) {
    Eigen::Index nearest = 0;
    (sphere.V.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&nearest);
    removed[nearest] = 1;
  }
  return without_faces(sphere, [&](int f) {
    return removed[sphere.F(f, 0)] || removed[sphere.F(f, 1)] || removed[sphere.F(f, 2)];
  });
}

// `count` one-ring holes on an icosphere of 6 subdivisions: seconds a hole as they crowd.
int run_one_ring_holes(int count) {
  Mesh mesh = sphere_with_one_ring_holes(6, count);
  const std::optional<FillReport> filled = fill_or_say(mesh, std::to_string(count) + " one-ring holes");
  if (!filled) return 1;
  const FillReport& report = *filled;
  std::size_t largest_group = 1;
  for (const HoleReport& h : report.holes) largest_group = std::max(largest_group, h.filled_with.size() + 1);
  const int holes = static_cast<int>(report.holes.size());
  std::printf("%5d one-ring holes (%d filled, the largest group filled jointly %zu): fill_holes %.2f s, %.4f s a "
              "hole; peak %.0f MB\n",
              holes, report.filled, largest_group, report.seconds, holes > 0 ? report.seconds / holes : 0.0,
              static_cast<double>(bench::peak_bytes()) / 1e6);
  return report.filled == holes ? 0 : 1;
}

template <class Case>
void in_child(Case run) {
  std::fflush(stdout);
  const pid_t child = ::fork();
  if (child == 0) {
    const int code = run();
    std::fflush(stdout);
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
}

}  // namespace

int main(int argc, char** argv) {
  bool large = false, harmonic_only = false, small_holes = false, one_ring_holes = false;
  for (int i = 1; i < argc; ++i) {
    large = large || std::strcmp(argv[i], "large") == 0;
    harmonic_only = harmonic_only || std::strcmp(argv[i], "harmonic") == 0;
    small_holes = small_holes || std::strcmp(argv[i], "small-holes") == 0;
    one_ring_holes = one_ring_holes || std::strcmp(argv[i], "one-ring-holes") == 0;
  }
  if (small_holes) {
    for (int subdivisions : {5, 6, 7, 8}) in_child([=] { return run_small_holes(subdivisions); });
    return 0;
  }
  if (one_ring_holes) {
    for (int count : {100, 400, 1600}) in_child([=] { return run_one_ring_holes(count); });
    return 0;
  }
  struct Case {
    int subdivisions;
    double cap;
  };
  std::vector<Case> cases{{5, 0.8}, {6, 0.84}, {6, 0.5}, {7, 0.84}};
  if (large) cases.push_back({8, 0.53});
  for (const Case& c : cases)
    for (const FairMethod method : {FairMethod::flow, FairMethod::harmonic})
      if (!harmonic_only || method == FairMethod::harmonic)
        in_child([=] { return run_case(c.subdivisions, c.cap, method); });
  return 0;
}
