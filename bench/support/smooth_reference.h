// A smooth stand-in for a mesh's surface, for measuring how far a fill lies from it: the mesh
// refined by the modified butterfly scheme (subdivision.h's butterfly_refined). The scheme
// interpolates: every vertex of the mesh stays where it is, and the new faces bulge between them as
// a smooth surface does, where the mesh's own flat faces cut the chord (on data/torus.obj, 64 × 36 faces,
// they lie up to 0.04 mean edges inside the torus its vertices lie on).
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fairsurf::bench {

/// Exact distance from any point to the faces of a surface, through a uniform grid of cubes of side
/// `cell` that lists the faces whose bounding box meets each cube. A query visits the cubes in
/// growing shells around its own and stops once no unvisited cube can hold a nearer face, so a
/// point near the surface costs a few cubes whatever the surface's size. Built once for a finely
/// refined surface (millions of small faces) and queried for every measured point.
class GridSurfaceDistance {
 public:
  /// Throws InvalidArgument for a non-positive `cell`, or one so small that the grid would need
  /// more than 2^21 cubes along an axis.
  GridSurfaceDistance(Mesh surface, double cell);
  double operator()(const Eigen::Vector3d& p) const;

 private:
  std::int64_t key(const Eigen::Vector3i& cube) const;
  Eigen::Vector3i cube_of(const Eigen::Vector3d& p) const;
  double nearest_in(const Eigen::Vector3i& cube, const Eigen::Vector3d& p, double best) const;
  double nearest_in_shell(const Eigen::Vector3i& home, int shell, const Eigen::Vector3d& p, double best) const;

  Mesh surface_;
  double cell_;
  Eigen::Vector3i low_, high_;  ///< the cubes that hold faces lie in [low_, high_]
  std::unordered_map<std::int64_t, std::vector<int>> faces_;
};

}  // namespace fairsurf::bench
