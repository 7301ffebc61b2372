// fairsurf — mesh repair: turns the meshes users actually have (soups, scans with pinched vertices,
// CAD exports with fins, zero-area slivers) into meshes the flows accept.
//
// `repair` runs a fixed sequence of operations, each switchable in RepairOptions and each counted in
// the RepairReport. It never moves a vertex, except that merging coincident (or, with a tolerance,
// nearly coincident) vertices keeps the position of the lowest-indexed one. Vertex order is kept:
// removed vertices close up, copies made by splitting are appended. The findings it removes are
// those of validate.h, defined the same way (docs/validation.md); what each operation does is in
// docs/repair.md.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <span>
#include <vector>

namespace fairsurf {

struct RepairOptions {
  /// Faces with an index outside [0, #V), a repeated vertex or a NaN/Inf corner are always removed:
  /// no other operation can work with them.

  /// Merge vertices with exactly the same coordinates (an unwelded soup), unless the merged vertex
  /// would be non-manifold (it would then be split again, so it is left alone).
  bool merge_duplicate_vertices = true;
  /// With a positive value, also merge vertices closer than this times the mean edge length.
  double merge_tolerance = 0.0;
  /// Merge border vertices that coincide — exactly, or with a positive stitch_tolerance closer than
  /// it times the mean edge length — when the merged vertex stays manifold: coincident borders are
  /// zipped together. (A relative tolerance follows the mean edge, which one far-off vertex can
  /// inflate; exact coincidence is the safe default.)
  bool stitch_borders = true;
  double stitch_tolerance = 0.0;
  /// Remove every face with the same vertex set as a lower-index face (either orientation).
  bool remove_duplicate_faces = true;
  /// Remove zero-area and near-degenerate faces (validate's definition): a needle whose shortest
  /// edge is at most needle_tolerance times its longest is collapsed onto the lower-index endpoint;
  /// a cap (a corner near the longest edge) has that edge flipped, or is removed when that edge is
  /// on a border or its other face is degenerate too (the surface is the same without it).
  bool fix_degenerate_faces = true;
  double needle_tolerance = 1e-6;
  /// ValidationOptions::near_degenerate_tolerance: the faces repair treats as degenerate.
  double degenerate_tolerance = 1e-12;
  /// Give each extra fan of a non-manifold vertex its own copy of the vertex.
  bool split_non_manifold_vertices = true;
  /// With split_non_manifold_vertices: leave a pinch of the border joined, a vertex every fan of
  /// which meets the border there (two holes touching at a corner, a hole through one vertex
  /// twice), and split off only its lone triangles (fans of one face whose three edges are all on
  /// the border, which remove_small_components then removes). fill_holes fills the loops through
  /// such a pinch together, which makes it manifold; split, the pinch leaves two coincident
  /// vertices on one hole's border, which a patch can run into. `fairsurf fill --repair` sets it
  /// (docs/repair.md). The vertex stays non-manifold where no hole through it is filled.
  bool keep_border_pinches = false;
  /// At an edge with more than two faces keep two of them joined and detach the others (their
  /// fans get their own copies of the edge's vertices).
  bool resolve_non_manifold_edges = true;
  /// Flip faces so that each component is consistently oriented (the orientation most of its faces
  /// have wins; ties keep the lowest-index face's). A non-orientable component is oriented as far as it goes and reported.
  bool orient = true;
  /// Remove connected components (faces sharing vertices) with fewer faces than this: by default
  /// lone triangles, the debris a split or a removed cap can leave.
  bool remove_small_components = true;
  int min_component_faces = 2;
  /// Remove loose fins, what a split cut loose from a surface and left lying against it: components
  /// with no vertex inside (every vertex on the border) that share an input vertex with a component
  /// that has one, and pages, faces cut loose at a non-manifold edge that hang from their piece by
  /// one edge at a vertex that is theirs alone and a copy of a vertex inside a surface, along an edge
  /// that doubles one of that surface (a zippered scan's overlaps leave both; docs/repair.md).
  bool remove_loose_fins = true;
  /// Remove vertices no face uses (and those merged away).
  bool remove_unreferenced_vertices = true;
};

/// What repair changed; every count is zero on a clean mesh.
struct RepairReport {
  int input_vertices = 0, input_faces = 0;
  int output_vertices = 0, output_faces = 0;

  int invalid_faces_removed = 0;       ///< out-of-range index, repeated vertex or NaN/Inf corner
  int vertices_merged = 0;             ///< exact duplicates (and within merge_tolerance) merged away
  int merges_refused = 0;              ///< coincident groups left apart: merging would pinch (not a change)
  int border_vertices_stitched = 0;    ///< border vertices merged away by stitch_borders
  int faces_collapsed = 0;             ///< faces that lost a corner to a merge or collapse
  int duplicate_faces_removed = 0;
  int needles_collapsed = 0;           ///< short edges of needles collapsed
  int caps_flipped = 0;                ///< longest edges of caps flipped
  int caps_removed = 0;                ///< caps on a border or against a degenerate face removed
  int degenerate_faces_left = 0;       ///< degenerate faces no operation could remove
  int non_manifold_edges = 0;          ///< edges with more than two faces, resolved
  int vertices_split = 0;              ///< non-manifold vertices and ends of detached fans, split
  int vertices_added = 0;              ///< copies made by both splits
  int faces_flipped = 0;
  int non_orientable_components = 0;   ///< reported, not fixed (a Möbius band stays one)
  int small_components_removed = 0;
  int small_component_faces_removed = 0;
  int fins_removed = 0;                ///< loose fins: such components and pages, one count each
  int fin_faces_removed = 0;
  int unreferenced_vertices_removed = 0;  ///< including the vertices merged away

  /// #V out: for each output vertex, the input vertex whose position and attributes it carries (the
  /// lowest-indexed vertex of a merged group, the original of a split copy). Lets a caller carry
  /// its own per-vertex data across the repair; the identity where no vertex was merged, split or
  /// removed.
  std::vector<int> vertex_origin;
  /// #V in: for each input vertex, the output vertex it became (a merged vertex: its group's), or −1
  /// where repair removed it. A split vertex became several: this one and the output vertices whose
  /// vertex_origin is the same (repaired_vertices gathers them).
  std::vector<int> vertex_destination;

  /// Whether any operation changed the mesh (non_orientable_components is a finding, not a change).
  bool changed() const;
};

/// One count of a RepairReport under its field's name.
struct NamedCount {
  const char* key;  ///< "vertices_merged", ...
  int value;
};
/// Every count of `report` (not the vertex maps), in declaration order: the keys of `fairsurf repair
/// --json` and of the Python report.
std::vector<NamedCount> named_counts(const RepairReport& report);

/// The vertices of the repaired mesh that stand for `input_vertices` (indices into the mesh repair
/// was given, as a user's file of region or fixed vertices holds them): each one's output vertex
/// and every copy a split made of it, ascending. Throws InvalidArgument for an index outside the
/// input, or a vertex repair removed (naming it).
std::vector<int> repaired_vertices(const RepairReport& report, std::span<const int> input_vertices);

/// Repairs `mesh` in place; vertex_scalars and vertex_colors follow their vertices (copies get
/// their original's values). Never throws on bad content: a mesh with no valid face comes out empty.
RepairReport repair(Mesh& mesh, const RepairOptions& options = {});

}  // namespace fairsurf
