// The real-holes protocol of bench_real_holes (docs/fill.md "Real holes benchmark"): holes cut out
// of a clean closed mesh by a ball, a slab cut for blending, deterministic normal noise, and the
// distance of points to the uncut surface.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace fairsurf::bench {

/// Mean length of the mesh's undirected edges (each counted once): the unit h of the benchmark.
double mean_edge_length(const Mesh& mesh);

/// V − E + F over the vertices that faces use.
int euler_characteristic(const Mesh& mesh);

/// A mesh with faces removed; the vertices left without a face are dropped, the others keep their
/// order.
struct CutMesh {
  Mesh mesh;
  std::vector<int> kept;     ///< for each vertex of `mesh`, its index in the uncut mesh
  std::vector<int> dropped;  ///< vertices of the uncut mesh that no kept face uses, ascending
};

/// Removes every face whose three vertices lie in the closed ball (centre, radius).
CutMesh cut_ball(const Mesh& mesh, const Eigen::Vector3d& centre, double radius);

/// Removes the faces whose three vertices satisfy |(x − V(vertex))·axis| < half_width (axis unit)
/// and that are connected, through shared edges of such faces, to a face at `vertex`: the band the
/// slab cuts across one neck or tube, not every place the plane meets the mesh.
CutMesh cut_slab(const Mesh& mesh, int vertex, const Eigen::Vector3d& axis, double half_width);

/// Irregular cuts: a blob of faces grown at random, or a slit (a random walk thickened). Unlike balls
/// they leave concave and elongated holes, islands, and lone triangles hanging at a vertex of a
/// hole's border, as the holes of raw scans have.
enum class CutShape { blob, slit };

/// Removes an irregular patch of faces from `start` (a face), drawn from `draw` (the seed fixes it on
/// every platform): a blob grown to `size` faces, each new face next to a random face of the blob,
/// or a slit, a random walk of `size` steps across edges thickened to every face at a vertex of the
/// walk. `tidy`: also remove every face the cut leaves with no neighbour across an edge (a lone
/// triangle hanging at a vertex), so that the holes are clean disks like a ball's.
CutMesh cut_irregular(const Mesh& mesh, int start, CutShape shape, int size, std::mt19937_64& draw, bool tidy);

/// The boundary loops of `mesh` (topology.h's order).
std::vector<std::vector<int>> loops_of(const Mesh& mesh);
/// The loops' sizes in border edges, "a+b+...".
std::string border_sizes(const Mesh& cut);
/// Removing k disks from a surface lowers its Euler characteristic by k; an annulus (a ball across a
/// tube thinner than it) lowers it by 0 and leaves two loops that no hole filling should close.
bool removed_disks(const Mesh& uncut, const Mesh& cut);
/// first, first + 1, ..., end − 1: the rows a fill appended.
std::vector<int> rows_from(int first, int end);

/// Moves every vertex used by a face along its area-weighted unit normal by a Gaussian of standard
/// deviation `sigma`, drawn by Box–Muller from std::mt19937_64(seed), so the same seed gives the
/// same mesh on every platform.
void add_normal_noise(Mesh& mesh, double sigma, std::uint64_t seed);

/// Distance from points to the triangles of a fixed mesh, searched outwards from a centre: faces
/// are sorted by a lower bound of their distance to `centre`, so points near it (the vertices of a
/// filled hole) visit only the nearby faces; far points are still exact, only slower.
class SurfaceDistance {
 public:
  SurfaceDistance(const Mesh& surface, const Eigen::Vector3d& centre);
  double operator()(const Eigen::Vector3d& p) const;

 private:
  const Mesh& surface_;
  Eigen::Vector3d centre_;
  std::vector<std::pair<double, int>> faces_;  ///< (|c_f − centre| − ρ_f, face), ascending
};

struct DistanceStats {
  int count = 0;
  double mean = 0, max = 0;  ///< in the units the caller divides by (h)
  /// Mean distance to a smooth stand-in of the surface (smooth_reference.h), when measured.
  double smooth_mean = std::numeric_limits<double>::quiet_NaN();
  /// Fill: mean distance of the uncut mesh's vertices that the cut removed to the filled surface,
  /// in the same unit; it measures a fill with no new vertex too (a flat patch over a one-ring hole).
  double removed_mean = std::numeric_limits<double>::quiet_NaN();
};

/// Distances of rows `rows` of V to the surface, divided by `unit`.
DistanceStats distance_stats(const SurfaceDistance& distance, const Vertices& V, const std::vector<int>& rows,
                             double unit);

/// Point-to-triangle distance (closest point by Voronoi regions of the triangle).
double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);

}  // namespace fairsurf::bench
