#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/mesh/submesh.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/membrane.h>
#include <fairsurf/solve/harmonic.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <string>

namespace fairsurf {
namespace {

using Vec3 = Eigen::Vector3d;

// The area of the faces F (#f by 3).
double area_of(const Vertices& V, const Faces& F) {
  double area = 0.0;
  for (int f = 0; f < F.rows(); ++f) {
    const Vec3 a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

}  // namespace

MembraneReport relax_membrane(Vertices& V, const Faces& F, std::span<const int> free_vertices,
                              const MembraneOptions& options, const LinearSolverOptions& solver) {
  return relax_membrane(V, F, build_topology(F, static_cast<int>(V.rows())), free_vertices, options, solver);
}

MembraneReport relax_membrane(Vertices& V, const Faces& F, const Topology& topo, std::span<const int> free_vertices,
                              const MembraneOptions& options, const LinearSolverOptions& solver) {
  if (topo.num_vertices != V.rows() || topo.num_faces != F.rows())
    throw InvalidArgument("relax_membrane: the topology was built for another mesh");
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
  // The free rows of ∆ involve only the faces touching a free vertex: solve on those alone, so that
  // relaxing a hole's patch costs in proportion to the patch, not to the mesh around it.
  Submesh sub = extract_neighbourhood(V, F, topo, free_list, 0);
  const Topology local = derive_topology(topo, sub.mesh.F, sub.to_global);  // once for all iterations
  const Region region = make_region(local, sub.free_local, Continuity::G0);
  HarmonicOptions membrane;
  membrane.order = 1;  // ∆x = 0 with the cotangent weights of the current positions
  membrane.solver = solver;

  MembraneReport report;
  report.area.push_back(area_of(sub.mesh.V, sub.mesh.F));
  for (int it = 0; it < options.iterations; ++it) {
    const Vertices before = sub.mesh.V;
    harmonic_fair(sub.mesh.V, sub.mesh.F, local, region, membrane);
    report.max_displacement = (sub.mesh.V - before).rowwise().norm().maxCoeff();
    report.area.push_back(area_of(sub.mesh.V, sub.mesh.F));
    ++report.iterations;
  }
  write_back_free(sub, V);
  return report;
}

}  // namespace fairsurf
