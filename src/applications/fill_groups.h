// Private to fill_holes: holes filled together (whose fixed rings overlap) and, in a patch of
// several, which hole each new vertex and face belongs to.
#pragma once

#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/patch.h>

#include <span>
#include <vector>

namespace fairsurf::fill_detail {

/// Groups of holes whose fixed rings (the loop and `rings` − 1 rings around it) share a vertex,
/// each group ascending, the groups ordered by their first hole.
std::vector<std::vector<int>> overlapping_groups(const Topology& topo, const std::vector<std::vector<int>>& loops,
                                                 const std::vector<int>& holes, int rings);

/// The hole each new vertex and face of `patch` belongs to. Patches of different loops share no
/// edge (at a pinch they share the vertex only), so the new faces fall into one edge-connected piece
/// per patch, found from the face across each loop edge. Where relinking at a pinch made one loop of
/// two holes (two loops that meet at a vertex, as a figure eight), their one piece goes to the later
/// hole, and `patch_hole` says so for the earlier; but a loop that is only the border of a piece the
/// patch takes in (`taken_in`, per hole of `holes`: a lone triangle, a piece hanging at a vertex)
/// gets it only where no other loop shares it, so that the hole, not the debris, reports the patch.
struct PatchOwnership {
  std::vector<int> vertex_hole;  ///< per new vertex (index − first new vertex)
  std::vector<int> face_hole;    ///< per new face
  std::vector<int> patch_hole;   ///< per hole of the group: the hole its loop's patch is counted for
};

PatchOwnership patch_ownership(const InitialPatch& patch, int input_vertices,
                               const std::vector<std::vector<int>>& loops, std::span<const int> holes,
                               std::span<const char> taken_in);

}  // namespace fairsurf::fill_detail
