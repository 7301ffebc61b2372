#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/patch.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

namespace fairsurf {
namespace {

// Refines `patch` on (V, F), then relaxes its interior: the steps shared by holes and tubes.
// `topo`: the connectivity of F, which the patched mesh's extends.
void refine_and_relax(const Vertices& V, const Faces& F, const Topology& topo, const Faces& patch,
                      const PatchOptions& options, InitialPatch& out) {
  out.refinement = refine_patch(V, F, patch, options.refinement);
  out.mesh.V = std::move(out.refinement.V);
  out.mesh.F = std::move(out.refinement.F);
  out.refinement.V.resize(0, 3);
  out.refinement.F.resize(0, 3);
  out.free_vertices = out.refinement.free_vertices;
  out.first_patch_face = out.refinement.first_patch_face;
  // The patched mesh's connectivity, once: the membrane reads it here, the caller's fairing later.
  // Refinement keeps the mesh's faces first, so it extends the mesh's own.
  out.topology = extend_topology(topo, out.mesh.F, out.mesh.num_vertices());
  if (options.relax && !out.free_vertices.empty()) {
    out.refined_free.resize(static_cast<Eigen::Index>(out.free_vertices.size()), 3);
    for (std::size_t k = 0; k < out.free_vertices.size(); ++k)
      out.refined_free.row(static_cast<Eigen::Index>(k)) = out.mesh.V.row(out.free_vertices[k]);
    out.membrane = relax_membrane(out.mesh.V, out.mesh.F, out.topology, out.free_vertices, options.membrane,
                                  options.solver);
  }
}

// The largest angle between the normals of a patch face and the mesh face across a border edge.
// `topo`: the connectivity of mesh.F; only the patch's edges are visited, so the cost goes with the
// patch, not the mesh.
double border_dihedral_angle(const Mesh& mesh, const Topology& topo, int first_patch_face) {
  const Vertices& V = mesh.V;
  const Faces& F = mesh.F;
  const auto normal = [&](int f) {
    const Eigen::Vector3d a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(), c = V.row(F(f, 2)).transpose();
    return Eigen::Vector3d((b - a).cross(c - a));
  };
  double angle = 0.0;
  for (int f = first_patch_face; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      for (int g : topo.edge_faces.row(topo.face_edges[3 * static_cast<std::size_t>(f) + k])) {
        if (g >= first_patch_face) continue;
        const Eigen::Vector3d n = normal(f), m = normal(g);
        angle = std::max(angle, std::atan2(n.cross(m).norm(), n.dot(m)));
      }
  return angle;
}

}  // namespace

InitialPatch hole_patch(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                        const PatchOptions& options) {
  if (loops.empty()) throw InvalidArgument("hole_patch: no hole given");
  return hole_patch(mesh, build_topology(mesh.F, mesh.num_vertices()), loops, options);
}

InitialPatch hole_patch(const Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                        const PatchOptions& options) {
  if (loops.empty()) throw InvalidArgument("hole_patch: no hole given");
  if (topo.num_vertices != mesh.num_vertices() || topo.num_faces != mesh.num_faces())
    throw InvalidArgument("hole_patch: the topology was built for another mesh");
  InitialPatch out;
  int rows = 0;
  for (const auto& loop : loops) {
    out.holes.push_back(triangulate_hole(mesh.V, mesh.F, topo, loop, options.triangulation));
    rows += static_cast<int>(out.holes.back().faces.rows());
  }
  Faces patch(rows, 3);
  rows = 0;
  for (const auto& hole : out.holes) {
    patch.middleRows(rows, hole.faces.rows()) = hole.faces;
    rows += static_cast<int>(hole.faces.rows());
  }
  refine_and_relax(mesh.V, mesh.F, topo, patch, options, out);
  out.border_dihedral_angle = border_dihedral_angle(out.mesh, out.topology, out.first_patch_face);
  return out;
}

InitialPatch without_membrane(InitialPatch patch) {
  if (patch.refined_free.rows() == 0) return patch;
  for (std::size_t k = 0; k < patch.free_vertices.size(); ++k)
    patch.mesh.V.row(patch.free_vertices[k]) = patch.refined_free.row(static_cast<Eigen::Index>(k));
  patch.refined_free.resize(0, 3);
  patch.membrane = {};
  patch.border_dihedral_angle = border_dihedral_angle(patch.mesh, patch.topology, patch.first_patch_face);
  return patch;
}

InitialPatch tube_patch(const Mesh& mesh, std::span<const int> loop_a, std::span<const int> loop_b,
                        const PatchOptions& options) {
  return tube_patch(mesh, build_topology(mesh.F, mesh.num_vertices()), loop_a, loop_b, options);
}

InitialPatch tube_patch(const Mesh& mesh, const Topology& topo, std::span<const int> loop_a,
                        std::span<const int> loop_b, const PatchOptions& options) {
  if (topo.num_vertices != mesh.num_vertices() || topo.num_faces != mesh.num_faces())
    throw InvalidArgument("tube_patch: the topology was built for another mesh");
  InitialPatch out;
  out.tube = build_tube(mesh.V, mesh.F, topo, loop_a, loop_b, options.tube);
  refine_and_relax(out.tube.V, mesh.F, topo, out.tube.faces, options, out);
  return out;
}

}  // namespace fairsurf
