// fairsurf — connectivity of a triangle mesh, built once and read by every later stage.
//
// Everything here is derived from the face array alone (plus positions for areas and normals) and is
// tolerant of defective input: non-manifold edges, duplicate faces and unreferenced vertices are
// represented, not rejected, so that `validate` can report them. Algorithms that need a manifold
// mesh check it through `validate`, not here.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace fairsurf {

/// Compressed sparse rows: row i is indices[offsets[i] .. offsets[i+1]).
struct Csr {
  std::vector<int> offsets{0};  ///< #rows+1 prefix offsets
  std::vector<int> indices;     ///< concatenated rows

  int rows() const { return static_cast<int>(offsets.size()) - 1; }
  int size(int i) const { return offsets[i + 1] - offsets[i]; }
  std::span<const int> row(int i) const {
    return {indices.data() + offsets[i], static_cast<std::size_t>(size(i))};
  }
};

/// #E by 2 undirected edges, each stored once with the smaller vertex index first.
using Edges = Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// Connectivity of a triangle mesh.
struct Topology {
  int num_vertices = 0;
  int num_faces = 0;
  Csr vertex_vertices;  ///< neighbours of each vertex (sharing an edge), ascending indices
  Csr vertex_faces;     ///< faces incident to each vertex, ascending indices
  Edges edges;          ///< #E by 2, sorted lexicographically
  Csr edge_faces;       ///< faces containing each edge: 1 on a border, 2 inside, >2 non-manifold
  std::vector<int> face_edges;  ///< #F*3: edge index of face f's edge (F(f,k), F(f,(k+1)%3))

  bool is_boundary_edge(int e) const { return edge_faces.size(e) == 1; }
};

/// Builds the connectivity of `F` over `num_vertices` vertices.
/// Throws InvalidArgument if a face index is outside [0, num_vertices) or a face repeats a vertex.
Topology build_topology(const Faces& F, int num_vertices);

/// The connectivity of a part of a mesh (a submesh, one side of a region), derived from the whole
/// mesh's connectivity `parent` instead of built from faces again. `F` holds some of the parent's
/// faces, each vertex renumbered to its position in `to_parent`: the ascending parent indices of the
/// part's vertices (submesh.h's to_global). The result equals build_topology(F, to_parent.size()),
/// field by field: each neighbour row is the parent's, already sorted, filtered to what F keeps (each
/// kept neighbour found by bisection in that row), so no row is sorted again and the time goes with
/// the part and its vertices' parent rows, not with the parent. Not counted by topology_builds(). Throws InvalidArgument as build_topology does, for a `to_parent` that is not
/// ascending or out of the parent's range, or for a face with an edge the parent does not have.
Topology derive_topology(const Topology& parent, const Faces& F, std::span<const int> to_parent);

/// The connectivity of a mesh grown from the one `base` was built for: the first base.num_faces
/// rows of `F` are that mesh's faces, unchanged, and the rows after them are added faces, over
/// `num_vertices` (at least base.num_vertices) vertices, the added ones last. The result equals
/// build_topology(F, num_vertices), field by field, but only the added faces are searched: the base's
/// rows are copied, and its edges keep their order with the added ones merged in. So a hole's patch
/// added to a large mesh costs a copy of the mesh's connectivity, not a rebuild with its sorts. The
/// base faces are trusted to be the ones `base` was built from (not checked). Not counted by
/// topology_builds(). Throws InvalidArgument as build_topology does for an added face, and for an
/// `F` or `num_vertices` smaller than the base's.
Topology extend_topology(const Topology& base, const Faces& F, int num_vertices);

/// Diagnostic counter: how many times build_topology has run in this process (all threads). Tests
/// read its difference across a call to check that an operation builds each mesh's connectivity
/// once and passes it down (deriving its parts' with derive_topology) instead of rebuilding it.
std::uint64_t topology_builds();

/// Per-vertex flag: the vertex lies on a border edge (an edge with exactly one face).
std::vector<char> boundary_vertex_flags(const Topology& topo);

/// Boundary loops as ordered vertex cycles (the first vertex is not repeated at the end).
/// Each loop follows the orientation of its faces, so the surface lies to the left when walking it
/// seen from the side the normals point to. Loops are sorted by their smallest vertex index. On a
/// non-manifold border (a vertex with more than two border edges) the cycles through that vertex are
/// split where the orientation allows; the count is then only indicative.
std::vector<std::vector<int>> boundary_loops(const Faces& F, const Topology& topo);

/// Connected components of faces, faces being connected when they share a vertex.
struct Components {
  int count = 0;
  std::vector<int> face_component;    ///< #F component ids in [0, count)
  std::vector<int> vertex_component;  ///< #V component ids; -1 for unreferenced vertices
};
Components connected_components(const Faces& F, const Topology& topo);

/// Graph distance (in edges) from the vertex set `seeds`, computed up to `max_rings`:
/// 0 on the seeds, 1..max_rings on the rings around them, -1 farther away.
std::vector<int> ring_distances(const Topology& topo, std::span<const int> seeds, int max_rings);

/// The vertices within `k` rings of `seeds` (seeds included), in ascending order.
std::vector<int> k_ring(const Topology& topo, std::span<const int> seeds, int k);

/// #F unit face normals (zero for degenerate faces) and #F face areas.
void face_normals_and_areas(const Vertices& V, const Faces& F, Eigen::MatrixX3d& normals,
                            Eigen::VectorXd& areas);

/// Mean length of the edges of `topo` whose two ends are finite in V (#V by 3); 0 if there are
/// none. The mesh's scale h, in which fills, smoothing times and benchmarks are measured.
double mean_edge_length(const Vertices& V, const Topology& topo);

/// #V vertex areas: one third of the areas of the incident triangles (method.md §4).
Eigen::VectorXd vertex_areas(const Vertices& V, const Faces& F);

}  // namespace fairsurf
