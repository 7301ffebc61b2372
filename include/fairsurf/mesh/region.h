// fairsurf — free and fixed vertices, and the fixed rings that carry boundary data (method.md §6).
//
// A flow moves the free vertices only. A flow of order 2(c+1) reaches continuity Gc across the border
// of the free region when c+1 rings of fixed vertices surround it: the second-order flow needs one
// ring (positions: G0), the fourth-order flow two (tangent planes: G1), the sixth-order flow three
// (curvatures: G2). Ring k is the set of fixed vertices at graph distance k from the free region.
// Where the mesh runs out before the third ring (the free region comes close to a mesh border), the
// region records how many rings the data supports and the continuity that follows.
#pragma once

#include <fairsurf/mesh/continuity.h>
#include <fairsurf/mesh/topology.h>

#include <span>
#include <string>
#include <vector>

namespace fairsurf {

/// A partition of the vertices into free and fixed, with the fixed rings around the free ones.
struct Region {
  std::vector<int> free_vertices;  ///< ascending vertex indices that move
  std::vector<int> free_index;     ///< #V: position of the vertex in free_vertices, -1 if fixed
  std::vector<int> ring;           ///< #V: 0 free, k = 1..3 fixed ring number, -1 farther away
  /// Complete fixed rings (0-3): the rings before the first one that contains a mesh-border
  /// vertex, or 3. A border vertex in ring k still holds position data but the band around the
  /// region is cut there, so rings k and beyond are not a complete boundary condition. Where ring 1
  /// has vertices and ring k (2 or 3) has none, at most k − 1 (a region that takes nearly all of a
  /// closed mesh); with no fixed vertex at all (a closed mesh smoothed whole), 3.
  int complete_rings = 0;
  Continuity requested = Continuity::G2;
  Continuity supported = Continuity::G2;  ///< min(requested, complete_rings - 1); G0 at least

  int num_free() const { return static_cast<int>(free_vertices.size()); }
  bool is_free(int v) const { return free_index[v] >= 0; }
};

/// Builds the region whose free set is `free_vertices` (any order, duplicates allowed).
/// Throws InvalidArgument for an out-of-range index or an empty free set.
Region make_region(const Topology& topo, std::span<const int> free_vertices,
                   Continuity requested = Continuity::G2);

/// The faces of F (over `num_vertices` vertices) with a vertex in `vertices`, ascending: the faces a
/// free region moves. Indices outside [0, num_vertices) are ignored.
std::vector<int> region_faces(const Faces& F, int num_vertices, std::span<const int> vertices);

/// Every vertex except those within `fixed_rings` rings of the mesh border (border vertices are
/// ring 1): the default free set for smoothing an open mesh with its border fixed. On a closed mesh
/// every vertex is returned.
std::vector<int> interior_vertices(const Topology& topo, int fixed_rings);

}  // namespace fairsurf
