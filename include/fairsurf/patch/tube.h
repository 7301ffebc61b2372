// fairsurf — the initial tube that joins two boundary loops before a blend is faired (method.md §7).
//
// Both loops are in topology.h's boundary_loops order (surface on the left). For the tube to be
// oriented consistently with both surfaces, its faces contain b→a across every loop edge a→b; that
// holds when the tube runs from loop A to loop B *reversed*, so B is always reversed first. (Two
// surfaces whose normals disagree, one outward and one inward, admit no consistent tube.)
//
// Construction:
//   1. Alignment. Each loop is parametrized by normalized arc length s ∈ [0, 1), A from its first
//      vertex. Every vertex of reversed B is tried as B's start; the one that minimizes the sum of
//      squared distances |A(s) − B(s)|² over max(#A, #B) equally spaced s is kept.
//   2. Rings. With h the mean length of the two loops' edges and D the mean matched distance
//      |A(s) − B(s)|, R = max(0, round(D / h) − 1) intermediate rings (or options.rings). Ring r
//      (t = r/(R+1)) has round(#A + (#B − #A)·t) points at equally spaced s; a point is the cubic
//      Hermite blend of A(s) and B(s) with end tangents ℓ·d_A(s) and −ℓ·d_B(s), where d is the
//      loop's outward direction: the unit direction in the surface's tangent plane, perpendicular to
//      the loop, pointing away from the surface (for a loop edge a→b of a face with normal n, along
//      (b − a) × n; averaged over a vertex's two edges). ℓ = tangent_scale · c · 2tan(φ/4)/sin(φ/2),
//      c = |B(s) − A(s)|, is the tangent of the cubic that approximates the circular arc of angle φ
//      from A(s) to B(s), φ = the sum of the angles that d_A(s) and −d_B(s) make with the chord
//      (capped at 3π/2): ℓ = c between facing loops (φ = 0), 6.83c for two ends that face away
//      from each other at right angles (adjacent ends of a cross, φ = 3π/2). With ℓ = c there, the
//      outer side's curves ran inside the inner side's and the tube folded flat. Tube sides thus
//      leave each surface tangentially, a much better start for a G2 flow than straight lines
//      (options.hermite = false gives the linear blend).
//   3. Strips. Consecutive rings (different counts allowed) are joined by the shortest-diagonal
//      zipper: walking both rings from their starts, each step adds the triangle whose new diagonal
//      is shorter.
// Refinement and relaxation are patch.h's business (tube_patch runs the whole pipeline).
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <span>
#include <vector>

namespace fairsurf {

struct TubeOptions {
  int rings = -1;              ///< intermediate rings; negative: automatic (header, step 2)
  bool hermite = true;         ///< Hermite along the outward directions; false: straight lines
  double tangent_scale = 1.0;  ///< factor on the circular-arc Hermite tangent length (header, step 2)
};

struct Tube {
  Vertices V;                      ///< the input vertices, then the ring vertices (ring by ring)
  Faces faces;                     ///< tube triangles over V, oriented consistently with both loops
  std::vector<int> ring_vertices;  ///< ascending indices of the new vertices (>= input #V)
  int rings = 0;                   ///< intermediate rings built
  int start_b = 0;                 ///< position in loop B of the vertex matched to A's first vertex
  double mean_squared_distance = 0.0;  ///< alignment cost per sample at the chosen start
};

/// Builds the tube from `loop_a` to `loop_b`, two disjoint boundary loops of the mesh (V, F) with
/// connectivity `topo` (the loops may lie on different components, e.g. of two concatenated meshes).
/// Throws InvalidArgument for loops of fewer than 3 vertices, out-of-range or shared vertices, or a
/// loop edge that is not a border edge.
Tube build_tube(const Vertices& V, const Faces& F, const Topology& topo, std::span<const int> loop_a,
                std::span<const int> loop_b, const TubeOptions& options = {});

/// The pair of loops closest to each other, by the symmetric mean nearest-vertex distance:
/// ½ (mean over a ∈ A of min_b |a − b| + mean over b ∈ B of min_a |a − b|). Unlike the distance of
/// the centroids it tells coaxial loops of different radii apart and is not fooled by loops whose
/// centroids coincide. O(Σ #A·#B) over all pairs.
struct LoopPair {
  int first = -1, second = -1;  ///< indices into the loop list, first < second
  double distance = 0.0;
};
/// Throws InvalidArgument if fewer than two loops are given or a vertex index is out of range.
LoopPair closest_loop_pair(const Vertices& V, const std::vector<std::vector<int>>& loops);

}  // namespace fairsurf
