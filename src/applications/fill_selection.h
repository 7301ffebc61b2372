// Private to fill_holes: which boundary loops it fills. The mesh's requirements (a pinch of the
// border is allowed), the loops the options select or that cannot be filled usefully (a lone
// triangle, a flat piece), and the loops through a pinch that cannot be filled without another.
#pragma once

#include <fairsurf/applications/fill.h>
#include <fairsurf/mesh/topology.h>

#include <string_view>
#include <utility>
#include <vector>

namespace fairsurf::fill_detail {

/// The mesh requirements of filling: everything validate checks, except that a vertex may be
/// non-manifold where it pinches the border (more than two border edges): filling the holes through
/// it together makes it manifold (border_pinches.h), and a hole that cannot be is reported per hole.
/// Returns the mesh's connectivity, which validate built. Throws as require_valid.
Topology require_fillable(const Mesh& mesh);

/// What a reason of fillable_holes ends with where the loop sharing the pinch runs around a lone
/// triangle.
inline constexpr std::string_view kLoneTriangleRepairHint = "; repair splits the vertex and removes the lone triangle";
/// Why a loop around a lone triangle is not filled on its own.
inline constexpr std::string_view kLoneTriangleSkipped =
    "the loop runs around a lone triangle: filling it would add that face again, reversed";

/// The loops of `loops` (boundary_loops of the mesh (V, F), connectivity `topo`) to fill, ascending.
/// The others get their status in `reports` (one per loop) with the reason: skipped where the
/// options leave them out or their fill could only lay the mesh's own faces again, failed where a
/// pinch of their border is shared with a loop that is not filled (left out, skipped, or failed
/// so), unless their patch alone joins that vertex's two fans. A loop around a lone triangle that
/// hangs at a pinch of a hole to be filled is filled with that hole, one patch taking the triangle
/// in; elsewhere it is skipped.
std::vector<int> fillable_holes(const Vertices& V, const Faces& F, const Topology& topo,
                                const std::vector<std::vector<int>>& loops, const FillOptions& options,
                                std::vector<HoleReport>& reports);

/// A loop flagged in `candidates` (one flag per loop), other than `h`, that shares a vertex with
/// loop `h` (two loops meet only at a pinch of the border), as {loop, vertex}: at the first such
/// vertex along loop `h`, the loop of lowest index; {−1, −1} if none.
std::pair<int, int> flagged_loop_at_a_pinch(const std::vector<std::vector<int>>& loops, int h,
                                            const std::vector<char>& candidates);

/// After the fill: a loop around a lone triangle whose joint fill with its hole failed is reported
/// skipped, as one that is not taken in, and each hole that failed with it fails at that pinch, with
/// the repair hint and the joint fill's failure in its reason (and `pinched_by`).
void report_lone_triangles_not_taken_in(const std::vector<std::vector<int>>& loops, std::vector<HoleReport>& reports);

}  // namespace fairsurf::fill_detail
