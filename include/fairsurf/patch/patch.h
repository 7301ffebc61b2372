// fairsurf — the initial patch of hole filling and blending (method.md §7): the surface a flow fairs.
//
// hole_patch:  every given hole is triangulated (hole_triangulation.h), all patches are refined
//              together to the surrounding edge length (patch_refinement.h) and relaxed to a G0
//              membrane with the original vertices fixed (membrane.h).
// tube_patch:  a tube joins two loops (tube.h), then the same refinement and relaxation.
// The result keeps the input's vertices and faces first, in their order and with their positions;
// patch vertices and faces follow. Per-vertex attributes of the input are not carried over (their
// length would no longer be #V). The free vertices are the patch's interior vertices, the set a
// later flow moves (region.h's make_region).
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/hole_triangulation.h>
#include <fairsurf/patch/membrane.h>
#include <fairsurf/patch/patch_refinement.h>
#include <fairsurf/patch/tube.h>

#include <span>
#include <vector>

namespace fairsurf {

struct PatchOptions {
  HoleTriangulationOptions triangulation{};
  TubeOptions tube{};
  PatchRefinementOptions refinement{};
  MembraneOptions membrane{};
  bool relax = true;  ///< run the G0 membrane relaxation (false: keep the refined, flat-ish patch)
  /// The solver of the membrane's Laplace systems, the patch stage's one linear solve.
  LinearSolverOptions solver = default_membrane_solver();
};

struct InitialPatch {
  Mesh mesh;                       ///< input vertices and faces first, unchanged; then the patch
  Topology topology;               ///< connectivity of mesh.F, built once for the caller to reuse
  std::vector<int> free_vertices;  ///< ascending indices of the patch's interior vertices
  int first_patch_face = 0;        ///< faces [first_patch_face, #F) are the patch
  std::vector<HoleTriangulation> holes;  ///< hole_patch: the triangulation of each hole, in order
  Tube tube;                       ///< tube_patch: the unrefined tube (faces and ring vertices)
  RefinedPatch refinement;         ///< split/flip figures (its V and F are moved into mesh)
  MembraneReport membrane;         ///< empty when not relaxed or when the patch has no interior vertex
  /// #free_vertices by 3: where refinement left the free vertices, before the membrane moved them
  /// (rows in free_vertices order); empty when not relaxed. Fill weighs one ∆^k solve from there.
  Vertices refined_free;
  /// hole_patch: the largest angle (radians) between the normals of a patch face and the mesh face
  /// across a border edge, on the final patch. Above π/2 the patch is folded against the mesh
  /// there: a refinement flip never folds a border triangle so (patch_refinement.h), but the
  /// membrane may (measured in docs/patch.md).
  double border_dihedral_angle = 0.0;
};

/// Fills the holes bounded by `loops` (each as boundary_loops orders it) of `mesh`.
/// Throws what triangulate_hole, refine_patch and relax_membrane throw; InvalidArgument if `loops`
/// is empty.
InitialPatch hole_patch(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                        const PatchOptions& options = {});
/// The same on `topo`, the connectivity of mesh.F (build_topology), instead of building it again.
InitialPatch hole_patch(const Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                        const PatchOptions& options = {});

/// `patch` as it was before its membrane: the free vertices back where refinement left them
/// (refined_free), no membrane report, the border dihedral angle of those positions. The same patch
/// hole_patch builds with relax = false, without triangulating and refining again. A patch that was
/// not relaxed is returned as it is.
InitialPatch without_membrane(InitialPatch patch);

/// Joins the loops `loop_a` and `loop_b` of `mesh` by a tube. Throws what build_tube,
/// refine_patch and relax_membrane throw.
InitialPatch tube_patch(const Mesh& mesh, std::span<const int> loop_a, std::span<const int> loop_b,
                        const PatchOptions& options = {});
/// The same on `topo`, the connectivity of mesh.F (build_topology), instead of building it again.
InitialPatch tube_patch(const Mesh& mesh, const Topology& topo, std::span<const int> loop_a,
                        std::span<const int> loop_b, const PatchOptions& options = {});

}  // namespace fairsurf
