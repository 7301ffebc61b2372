// fairsurf — the neighbourhood of a free region as a mesh of its own.
//
// A flow that moves a small region of a large mesh (a hole fill, a marked region) only needs the
// region and enough rings around it for every fit and stencil its equations reach. Extracting them
// makes each step cost in proportion to the region instead of the whole mesh. Operator stencils
// reach one ring (interior vertices of valence ≥ 5) or two (method.md §3.1), and the sixth-order EL
// nests three of them, so the default keeps six rings: the equations at the free vertices then see
// exactly what they would see in the whole mesh.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <span>
#include <vector>

namespace fairsurf {

struct Submesh {
  Mesh mesh;                    ///< local V (#v by 3) and F (#f by 3) in local indices
  std::vector<int> to_global;   ///< #v: global index of each local vertex, ascending
  std::vector<int> free_local;  ///< local indices of the free vertices, ascending
};

/// The faces touching any vertex within `rings` rings of `free_vertices`, with their vertices, and
/// every face around a vertex where those faces would meet in two or more fans (so the
/// neighbourhood is non-manifold only where the mesh is: its outer rings can touch themselves).
/// Local vertex order follows the global order. Throws InvalidArgument for an out-of-range index.
Submesh extract_neighbourhood(const Vertices& V, const Faces& F, const Topology& topo,
                              std::span<const int> free_vertices, int rings = 6);

/// Copies the positions of the submesh's free vertices back into the global #V by 3 array `V`.
void write_back_free(const Submesh& sub, Vertices& V);

}  // namespace fairsurf
