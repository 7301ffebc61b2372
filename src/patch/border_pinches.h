// Internal to hole filling: loops that pass through a pinch of the border (a vertex with more than
// two border edges, where the mesh's faces form several fans, "wedges"), and the manifold check of a
// patch.
//
// At a pinch p with k wedges, each wedge has one outgoing border edge p→y (at its start, turning
// counter-clockwise about the normal) and one incoming x→p (at its end). A patch joins every incoming
// edge of a loop to the outgoing edge that follows it, with a fan of new faces at p. The vertex ends
// manifold only if these joins link the k wedges into one cycle: the incoming edge of wedge i must be
// followed by the outgoing edge of another wedge; following it by its own wedge's outgoing edge would
// close that wedge into a cone touching the others at p. boundary_loops follows whichever border
// edge it meets first, so at a pinch its loops may do either.
//
// A loop may also pass twice through one position without a pinch: through the copies of a vertex
// that `repair` split in two. Its triangulation then holds a triangle with two corners at that
// position, which patch_zero_area_face finds.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <string>
#include <vector>

namespace fairsurf::detail {

/// The loops to triangulate so that the patches of `loops` (boundary loops of the mesh (V, F), surface
/// on the left) leave every pinch among their vertices manifold: the same border edges, re-linked
/// at each pinch so that each incoming edge is followed by the outgoing edge of the next wedge
/// counter-clockwise about the vertex normal (for two wedges: the other one). A returned loop may
/// pass through a pinch more than once (a hole around an island joined to the rest at one vertex).
/// Throws InvalidMeshError if a wedge at a pinch has other than one outgoing and one incoming edge of
/// these loops (the loops leave some border edges of the pinch out).
std::vector<std::vector<int>> relink_pinched_loops(const Vertices& V, const Faces& F, const Topology& topo,
                                                   const std::vector<std::vector<int>>& loops);

/// The fan (wedge) of each face around vertex v, in topo.vertex_faces' order, and in `count` the
/// number of fans: two faces at v are in one fan when they share an edge v-x.
std::vector<int> fans_at(const Faces& F, const Topology& topo, int v, int& count);

/// Why the faces [first_face, #F) make the mesh (F, its topology `topo`) non-manifold at one of
/// their edges (more than two faces) or vertices (more than one fan of faces), or "" if they do not.
std::string patch_non_manifold(const Faces& F, const Topology& topo, int first_face);

/// Why one of the faces [first_face, #F) of (V, F) has zero area (validate's degenerate face: its
/// edge vectors' cross product is exactly zero), naming the two distinct corners at one position if
/// it has them, or "" if none has.
std::string patch_zero_area_face(const Vertices& V, const Faces& F, int first_face);

}  // namespace fairsurf::detail
