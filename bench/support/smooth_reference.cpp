#include "smooth_reference.h"

#include "real_holes.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace fairsurf::bench {
namespace {

Eigen::Vector3d corner(const Mesh& m, int f, int k) { return m.V.row(m.F(f, k)).transpose(); }

}  // namespace

GridSurfaceDistance::GridSurfaceDistance(Mesh surface, double cell) : surface_(std::move(surface)), cell_(cell) {
  if (!(cell > 0)) throw InvalidArgument("GridSurfaceDistance: cell must be positive, got " + std::to_string(cell));
  low_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::max());
  high_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::min());
  for (int v = 0; v < surface_.num_vertices(); ++v) {
    low_ = low_.cwiseMin(cube_of(surface_.V.row(v).transpose()));
    high_ = high_.cwiseMax(cube_of(surface_.V.row(v).transpose()));
  }
  if (surface_.num_vertices() > 0 && (high_ - low_).maxCoeff() >= (1 << 21))
    throw InvalidArgument("GridSurfaceDistance: cell " + std::to_string(cell) + " is too small for the surface");
  for (int f = 0; f < surface_.num_faces(); ++f) {
    const Eigen::Vector3d a = corner(surface_, f, 0), b = corner(surface_, f, 1), c = corner(surface_, f, 2);
    const Eigen::Vector3i first = cube_of(a.cwiseMin(b).cwiseMin(c)), last = cube_of(a.cwiseMax(b).cwiseMax(c));
    for (int i = first.x(); i <= last.x(); ++i)
      for (int j = first.y(); j <= last.y(); ++j)
        for (int k = first.z(); k <= last.z(); ++k) faces_[key({i, j, k})].push_back(f);
  }
}

Eigen::Vector3i GridSurfaceDistance::cube_of(const Eigen::Vector3d& p) const {
  return (p / cell_).array().floor().cast<int>();
}

// Only cubes in [low_, high_] are keyed: each coordinate then fits in 21 bits.
std::int64_t GridSurfaceDistance::key(const Eigen::Vector3i& cube) const {
  const Eigen::Vector3i c = cube - low_;
  return (static_cast<std::int64_t>(c.x()) << 42) | (static_cast<std::int64_t>(c.y()) << 21) | c.z();
}

double GridSurfaceDistance::nearest_in(const Eigen::Vector3i& cube, const Eigen::Vector3d& p, double best) const {
  if ((cube.array() < low_.array()).any() || (cube.array() > high_.array()).any()) return best;
  const auto it = faces_.find(key(cube));
  if (it == faces_.end()) return best;
  for (int f : it->second)
    best = std::min(best, point_triangle_distance(p, corner(surface_, f, 0), corner(surface_, f, 1), corner(surface_, f, 2)));
  return best;
}

// The cubes at Chebyshev distance `shell` from `home`: the whole faces i = ±shell and j = ±shell,
// and of the rest only the two caps k = ±shell.
double GridSurfaceDistance::nearest_in_shell(const Eigen::Vector3i& home, int shell, const Eigen::Vector3d& p,
                                             double best) const {
  for (int i = -shell; i <= shell; ++i)
    for (int j = -shell; j <= shell; ++j) {
      const bool side = std::abs(i) == shell || std::abs(j) == shell;
      for (int k = -shell; k <= shell; k += side || shell == 0 ? 1 : 2 * shell)
        best = nearest_in(home + Eigen::Vector3i(i, j, k), p, best);
    }
  return best;
}

double GridSurfaceDistance::operator()(const Eigen::Vector3d& p) const {
  const Eigen::Vector3i home = cube_of(p);
  // Beyond this shell no cube holds a face.
  const int last = std::max((home - low_).cwiseAbs().maxCoeff(), (high_ - home).cwiseAbs().maxCoeff());
  double best = std::numeric_limits<double>::infinity();
  for (int shell = 0; shell <= last; ++shell) {
    best = nearest_in_shell(home, shell, p, best);
    // p lies in its home cube, so every cube beyond this shell is at least shell · cell away.
    if (best <= shell * cell_) break;
  }
  return best;
}

}  // namespace fairsurf::bench
