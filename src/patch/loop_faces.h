// Internal to the patch stage: the mesh faces along a boundary loop, shared by hole triangulation
// and tube construction.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <span>
#include <vector>

namespace fairsurf::detail {

/// True if a and b are joined by an edge of the mesh.
bool is_mesh_edge(const Topology& topo, int a, int b);

/// For each loop edge loop[t] → loop[t+1 mod n], the mesh face that contains that directed edge.
/// Throws InvalidArgument, its message starting with `function`, for a loop of fewer than 3
/// vertices, a vertex out of range, or a loop edge that is not a border edge with the surface on
/// its left.
std::vector<int> loop_edge_faces(const Faces& F, const Topology& topo, std::span<const int> loop,
                                 const char* function);

}  // namespace fairsurf::detail
