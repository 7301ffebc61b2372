#include <fairsurf/errors.h>
#include <fairsurf/harmonic.h>
#include <fairsurf/membrane.h>
#include <fairsurf/region.h>
#include <fairsurf/topology.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <string>

namespace fairsurf {
namespace {

using Vec3 = Eigen::Vector3d;

// Faces with at least one free vertex: the only ones whose weights enter the free rows.
std::vector<int> faces_touching(const Faces& F, const std::vector<int>& free_index) {
  std::vector<int> faces;
  for (int f = 0; f < F.rows(); ++f)
    if (free_index[F(f, 0)] >= 0 || free_index[F(f, 1)] >= 0 || free_index[F(f, 2)] >= 0)
      faces.push_back(f);
  return faces;
}

double area_of(const Vertices& V, const Faces& F, const std::vector<int>& faces) {
  double area = 0.0;
  for (int f : faces) {
    const Vec3 a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

}  // namespace

MembraneReport relax_membrane(Vertices& V, const Faces& F, std::span<const int> free_vertices,
                              const MembraneOptions& options) {
  if (options.iterations < 1)
    throw InvalidArgument("relax_membrane: iterations must be at least 1, got " +
                          std::to_string(options.iterations));
  if (free_vertices.empty()) throw InvalidArgument("relax_membrane: the free set is empty");
  std::vector<int> free_index(V.rows(), -1), free_list;
  for (int v : free_vertices) {
    if (v < 0 || v >= V.rows())
      throw InvalidArgument("relax_membrane: free vertex " + std::to_string(v) + " is out of range");
    if (free_index[v] < 0) free_index[v] = static_cast<int>(free_list.size()), free_list.push_back(v);
  }
  const Topology topo = build_topology(F, static_cast<int>(V.rows()));  // checks the faces
  const Region region = make_region(topo, free_list, Continuity::G0);
  const std::vector<int> faces = faces_touching(F, free_index);
  HarmonicOptions membrane;
  membrane.order = 1;  // ∆x = 0 with the cotangent weights of the current positions
  membrane.solver = options.solver;

  MembraneReport report;
  report.area.push_back(area_of(V, F, faces));
  for (int it = 0; it < options.iterations; ++it) {
    Eigen::MatrixX3d before(free_list.size(), 3);
    for (std::size_t r = 0; r < free_list.size(); ++r) before.row(r) = V.row(free_list[r]);
    harmonic_fair(V, F, region, membrane);
    report.max_displacement = 0.0;
    for (std::size_t r = 0; r < free_list.size(); ++r)
      report.max_displacement = std::max(report.max_displacement, (V.row(free_list[r]) - before.row(r)).norm());
    report.area.push_back(area_of(V, F, faces));
    ++report.iterations;
  }
  return report;
}

}  // namespace fairsurf
