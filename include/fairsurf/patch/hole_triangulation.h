// fairsurf — minimum-weight triangulation of a hole's boundary polygon (Liepa 2003; method.md §7).
//
// A hole is a boundary loop as topology.h's boundary_loops returns it: an ordered vertex cycle with
// the surface on its left (walking it seen from the side the normals point to), so the mesh face
// across loop edge a→b contains the directed edge a→b. The new faces use only the loop's vertices
// and contain b→a across every loop edge: they are oriented consistently with the surrounding mesh.
//
// Weight of a triangulation (Liepa): the pair (largest dihedral angle, total area), compared
// lexicographically (angles within kAngleTie of each other count as equal, then the area decides).
// The dihedral angle of an edge is the angle between the unit normals of its two triangles, in
// [0, π]: 0 for a flat continuation. It is taken over every interior edge of the new triangulation
// and over every loop edge, against the existing mesh face across it. A degenerate triangle (area
// under 1e-12 times its longest edge squared) counts as angle π.
//
// Holes with at most `max_dynamic_programming_size` loop edges are solved by Liepa's O(n³) dynamic
// programme. (The programme is exact for the area; for the angle it evaluates the dihedral across a
// diagonal with the optimal sub-triangulation on its inner side, as Liepa does, so a triangulation
// with a smaller largest angle may exist, and which one the programme finds depends on the vertex
// the loop starts at: on a 73-edge hole in a concave corner of data/blub.obj, 69°
// from the first vertex, 44° from another. The programme is therefore solved from
// `start_vertices` starts evenly spaced round the loop, and another start's result replaces the
// first's only where it is lighter by more than `start_margin` in the largest angle: on the 204
// single-loop ball holes of bench_real_holes (fixed and random centres, clean and noisy) 8 starts
// lower the largest angle on 70 holes, mostly by a few degrees, by more than 10° on 12.)
// Larger holes are divided first: the polygon is cut along the admissible diagonal with the
// smallest ratio of its length to the shorter loop arc it cuts off (a diameter of a round hole, the
// waist of an elongated one), among those leaving at least a quarter of the vertices on each side,
// recursively, until every piece is small enough for the programme. The second piece of a cut sees
// the first piece's triangle across the cut as its "mesh" face, so the dihedral across the cut is
// still weighed. The cost is then O(n²) for the cuts plus O(n·t²) for the pieces, t the threshold.
// Pieces must stay large for the fill to stay good: with t = 64 on a 150-edge spherical cap the
// largest angle was 0.92 rad against 0.77 undivided, but with t = 8-16 thin pieces fold (2.9 rad).
//
// A triangulation must not run through the surrounding mesh. Where a loop runs round a sharp
// corner of a CAD part, the lightest triangles (for example every triangle on a loop edge next to a
// corner fan that curls over the hole) can pass through mesh faces. Each triangulation is checked
// (face_intersection.h, the same test as fill's); while it crosses, the programme is solved again
// with the crossing diagonals (an edge through a face) or triangles (a face's edge through them)
// forbidden, up to `max_crossing_rounds` times, and the triangulation with the fewest crossings is
// kept (docs/patch.md: the corner of cgal_mech_holes_shark's hole 3). CGAL avoids most of them by
// restricting the search to the faces of a 3D Delaunay tetrahedralization of the loop; that search is
// an option here (`delaunay_restricted`), which fill uses where a hole's fill folds back.
//
// A triangle is admissible only if its three vertices are distinct and none of its diagonals is
// already an edge of the mesh (that would make the edge non-manifold). A loop that passes twice
// through a vertex (a pinch of the border) is first cut by a diagonal from between the two passes
// to outside them, so each piece passes once. Where an end of the cut is itself passed twice, the
// cut leaves it into the hole at the pass it is drawn from (within the angle the loop turns through
// there), not across a face hanging at the vertex. No piece may repeat a cut or an earlier piece's
// diagonal (the two passes could otherwise both be joined to one vertex).
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <numbers>
#include <span>

namespace fairsurf {

/// Two dihedral angles closer than this (radians) compare as equal in the weight.
inline constexpr double kAngleTie = 1e-9;

struct HoleTriangulationOptions {
  /// Loops with at most this many edges are triangulated by the O(n³) dynamic programme; larger
  /// ones are cut into pieces of at most this size first, which bounds the cubic cost (timings in
  /// docs/patch.md).
  int max_dynamic_programming_size = 200;
  /// The programme is solved from this many start vertices, evenly spaced round the loop (or a
  /// piece of it): its largest angle depends on where the loop starts (see header). 1: the loop's
  /// first vertex only.
  int start_vertices = 8;
  /// Another start's triangulation replaces the first start's only where it is lighter with this
  /// added to its largest angle (radians): a few degrees less do not make a better patch once it is
  /// refined and faired, but the tens of degrees of a start that misses a fold do (docs/patch.md).
  double start_margin = 10.0 * std::numbers::pi / 180.0;
  /// A triangulation whose faces cross the mesh (face_intersection.h) is solved again with the
  /// crossing triangles forbidden, at most this many times; the one with the fewest crossings is
  /// kept. 0: no check. Rounds after the first are solved from the loop's first vertex only.
  int max_crossing_rounds = 100;
  /// The programme takes the triangles that are faces of the 3D Delaunay tetrahedralization of the
  /// loop's vertices (qhull), as CGAL's hole filling does by default, and as few others as it must:
  /// its weight is the count of those others, then Liepa's (docs/patch.md, "Delaunay restriction").
  /// The full search runs instead where the loop passes a vertex twice or exceeds
  /// `max_dynamic_programming_size`, or its vertices span no volume (HoleTriangulation::delaunay).
  bool delaunay_restricted = false;
  /// Where the loop passes a vertex twice, the number of admissible cuts between the passes (the
  /// shortest relative to the loop arc they cut off first, those that leave each twice-passed end
  /// into the hole ahead of the others) whose triangulations are weighed: the lightest is kept. 1:
  /// the first cut, unweighed. Weighed only at the loop's first such vertex; the pieces take their
  /// first cut. fill_holes weighs 8 where a patch through a pinch folds back (docs/fill.md).
  int bridge_cuts_weighed = 1;
};

/// The new faces of one hole and the weight they reach.
struct HoleTriangulation {
  Faces faces;                      ///< (#loop − 2) by 3 indices into the mesh's vertices
  double max_dihedral_angle = 0.0;  ///< radians, over interior and loop edges (see header)
  double area = 0.0;                ///< total area of the new faces
  bool divided = false;             ///< the loop was cut into pieces (above the threshold)
  int crossings = 0;                ///< crossings left with the mesh or each other (0 when not checked)
  bool delaunay = false;            ///< the faces come from the Delaunay-restricted search
  int outside_delaunay = 0;         ///< of them, faces that are not faces of the tetrahedralization
};

/// Triangulates the hole bounded by `loop` (vertex indices of `V`, surface on the left, as
/// boundary_loops orders them) of the mesh (V, F) whose connectivity is `topo`.
/// Throws InvalidArgument for a loop of fewer than 3 vertices, an index out of range, a loop edge
/// that is not a border edge of the mesh, or a non-positive threshold; InvalidMeshError if no
/// admissible triangulation exists (every candidate would duplicate a mesh edge).
HoleTriangulation triangulate_hole(const Vertices& V, const Faces& F, const Topology& topo,
                                   std::span<const int> loop,
                                   const HoleTriangulationOptions& options = {});

/// Whether `loop` passes a vertex more than once (a pinch of the border): the loops that are cut
/// between their passes (HoleTriangulationOptions::bridge_cuts_weighed) and that the Delaunay
/// restriction leaves to the full search.
bool passes_a_vertex_twice(std::span<const int> loop);

/// Whether HoleTriangulationOptions::delaunay_restricted can restrict the search for `loop`: not
/// where the loop passes a vertex twice or has more than `max_dynamic_programming_size` edges (the
/// full search runs then, as it does where the loop's vertices span no volume, which only the
/// tetrahedralization tells).
bool delaunay_restriction_applies(std::span<const int> loop, const HoleTriangulationOptions& options);

/// Liepa's weight of the triangles `faces` added to the mesh (V, F): the largest dihedral angle
/// over the edges that the new faces share with each other or with the mesh faces, and the total
/// area of `faces`. Faces of the mesh that share no edge with `faces` do not count.
struct TriangulationWeight {
  double max_dihedral_angle = 0.0;
  double area = 0.0;
};
TriangulationWeight triangulation_weight(const Vertices& V, const Faces& F, const Faces& faces);

}  // namespace fairsurf
