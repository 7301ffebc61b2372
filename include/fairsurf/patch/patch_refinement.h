// fairsurf — refining a coarse patch until its edge lengths match the surrounding mesh (Liepa 2003).
//
// The patch is a set of triangles added to a mesh (a triangulated hole, a tube between loops). Its
// border — the edges used by one patch triangle — is glued to the mesh and never changes: border
// edges are never split or flipped and border vertices never move. Every vertex carries a scale σ,
// the edge length wanted around it: on border vertices, the mean length of their (two) border
// edges, which are edges of the surrounding mesh; on interior vertices of the input patch (tube
// rings), the mean length of their patch edges. σ thus interpolates the border's edge lengths, as
// method.md §7 asks ("edge lengths match the surrounding mesh"), and follows a grading along it.
// Refinement then repeats, until no triangle is split (Liepa's density control, factor α):
//   1. split: a triangle with centroid c and σ_c = mean σ of its corners is split 1→3 at c when
//      α·|c − v| > σ_c and α·|c − v| > σ_v for each corner v; c gets σ_c;
//   2. flip: interior edges are flipped to the Delaunay configuration (sum of the two opposite
//      angles > π), unless the flip would fold the two triangles over each other, duplicate an
//      edge of the patch or of the mesh around it, or turn a border triangle against the mesh face
//      across the border more than π/2 and more than before (2π/3 when the flip removes a sliver,
//      a triangle with an angle above 160°), until no edge flips.
// A disk of the patch that the rounds leave without an interior vertex gets one, at the midpoint of
// its longest inner edge, where its area A is at least (n − 1) times the mean area of the n mesh
// faces across its border (the count of triangles the mesh would put there is nearer n, one vertex,
// than n − 2, none: a one-ring hole); then the rounds run again (docs/patch.md §2).
// Finally interior vertices are relaxed tangentially: moved towards the centroid of their
// neighbours within the plane of their vertex normal, a few times, each followed by a flip pass.
// α = √2 gives edges whose mean is within a few percent of σ (measured in tests/patch/test_patch.cpp).
//
// Halfedge editing is done with OpenMesh on a local copy of the patch only: OpenMesh's split and
// flip are proven, and copying just the patch keeps the rest of the mesh (which may be non-manifold
// elsewhere) out of its way.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <cmath>
#include <vector>

namespace fairsurf {

struct PatchRefinementOptions {
  /// Liepa's α: larger splits more (smaller edges). √2 matches σ on average.
  double density_factor = std::sqrt(2.0);
  /// If positive, every σ is this length instead of the one measured from the mesh.
  double target_edge_length = 0.0;
  /// Split rounds at most (each round at least doubles the vertex count of a coarse patch).
  int max_rounds = 60;
  /// Tangential relaxation sweeps over the interior vertices at the end.
  int relaxation_sweeps = 5;
};

/// The mesh with its refined patch.
struct RefinedPatch {
  /// #V' by 3: the input vertices in their order, interior patch vertices moved, then new vertices.
  Vertices V;
  /// #F' by 3: the mesh faces in their order, then the refined patch faces.
  Faces F;
  int first_patch_face = 0;  ///< faces [first_patch_face, #F') are the patch
  /// Ascending indices of the interior patch vertices (the ones a flow may move): the input's
  /// interior patch vertices, then every vertex added by refinement (indices >= #V).
  std::vector<int> free_vertices;
  int splits = 0;  ///< triangles split (and inner edges split to put back a missing vertex)
  int flips = 0;   ///< edges flipped
  int rounds = 0;  ///< split rounds run
};

/// Refines the patch `patch` (#P by 3 triangles over the vertices of V, consistently oriented, a
/// manifold surface with border) added to the mesh (V, F). Throws InvalidArgument for a face index
/// out of range or invalid options, InvalidMeshError if the patch is not an orientable manifold.
RefinedPatch refine_patch(const Vertices& V, const Faces& F, const Faces& patch,
                          const PatchRefinementOptions& options = {});

}  // namespace fairsurf
