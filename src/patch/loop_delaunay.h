// Internal to the patch stage: the triangles of the 3D Delaunay tetrahedralization of a hole's
// loop vertices, the search space to which CGAL restricts Liepa's programme (hole_triangulation.h,
// HoleTriangulationOptions::delaunay_restricted). Computed by Debian's qhull (libqhull_r).
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <array>
#include <set>
#include <span>

namespace fairsurf::detail {

/// The vertex set of a triangle, sorted: independent of its orientation and corner order.
using TriangleKey = std::array<int, 3>;

/// Every face of every tetrahedron of the Delaunay tetrahedralization of the points V.row(v), v in
/// `vertices` (distinct indices), as the sorted triple of those indices. Empty where the points
/// span no volume (a flat or collinear loop) or qhull fails otherwise: there is no restriction then.
std::set<TriangleKey> delaunay_triangles(const Vertices& V, std::span<const int> vertices);

}  // namespace fairsurf::detail
