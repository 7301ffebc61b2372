#include <fairsurf/errors.h>
#include <fairsurf/patch.h>
#include <fairsurf/topology.h>

#include <utility>

namespace fairsurf {
namespace {

// Refines `patch` on (V, F), then relaxes its interior: the steps shared by holes and tubes.
void refine_and_relax(const Vertices& V, const Faces& F, const Faces& patch, const PatchOptions& options,
                      InitialPatch& out) {
  out.refinement = refine_patch(V, F, patch, options.refinement);
  out.mesh.V = std::move(out.refinement.V);
  out.mesh.F = std::move(out.refinement.F);
  out.refinement.V.resize(0, 3);
  out.refinement.F.resize(0, 3);
  out.free_vertices = out.refinement.free_vertices;
  out.first_patch_face = out.refinement.first_patch_face;
  if (options.relax && !out.free_vertices.empty())
    out.membrane = relax_membrane(out.mesh.V, out.mesh.F, out.free_vertices, options.membrane);
}

}  // namespace

InitialPatch hole_patch(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                        const PatchOptions& options) {
  if (loops.empty()) throw InvalidArgument("hole_patch: no hole given");
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
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
  refine_and_relax(mesh.V, mesh.F, patch, options, out);
  return out;
}

InitialPatch tube_patch(const Mesh& mesh, std::span<const int> loop_a, std::span<const int> loop_b,
                        const PatchOptions& options) {
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  InitialPatch out;
  out.tube = build_tube(mesh.V, mesh.F, topo, loop_a, loop_b, options.tube);
  refine_and_relax(out.tube.V, mesh.F, out.tube.faces, options, out);
  return out;
}

}  // namespace fairsurf
