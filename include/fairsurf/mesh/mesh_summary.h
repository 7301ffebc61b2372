// fairsurf — a mesh's size, topology and extent in figures: what `fairsurf info` prints.
//
// Connectivity figures are computed on the well-formed faces only (validate.h), so a summary exists
// for any mesh that `validate` accepts, that is, any mesh.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/validate.h>

#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace fairsurf {

struct MeshSummary {
  int vertices = 0;             ///< #V, every vertex record
  int referenced_vertices = 0;  ///< vertices used by a well-formed face
  int faces = 0;                ///< #F, every face record
  int edges = 0;                ///< undirected edges of the well-formed faces
  int boundary_edges = 0;       ///< edges with exactly one face
  /// Length in edges of each boundary loop (topology.h boundary_loops order). On a non-manifold
  /// border (a vertex with more than two border edges) boundary_loops splits the border into
  /// chains that need not close; the figure is then the chain's vertex count and only indicative.
  std::vector<int> boundary_loop_lengths;
  /// Triangles whose three edges are all on the border: a triangle on its own, hanging at a vertex
  /// (debris a scan or a cut leaves by a hole), or a face of an unwelded soup. Each has its own
  /// 3-edge loop, which is no hole (fill skips it); repair welds a soup and removes the others.
  int lone_triangles = 0;
  int components = 0;  ///< groups of faces connected through shared vertices
  /// V - E + F over referenced vertices and well-formed faces, summed over all components.
  int euler_characteristic = 0;
  /// Sum over components of g = (2 - b - chi) / 2, with chi and b the component's Euler
  /// characteristic and boundary-loop count: the number of handles of the whole surface.
  /// Defined only for a manifold, orientable mesh (no value otherwise), where each component is a
  /// compact orientable surface and the classification theorem makes g a non-negative integer.
  std::optional<int> genus;
  Eigen::AlignedBox3d bounding_box;  ///< over the finite vertex positions; empty if there are none
  double mean_edge_length = 0;       ///< over edges with finite endpoints; 0 if there are none
};

/// Summarizes `mesh`; `report` must be validate(mesh) (it decides whether the genus is defined).
MeshSummary summarize(const Mesh& mesh, const ValidationReport& report);

}  // namespace fairsurf
