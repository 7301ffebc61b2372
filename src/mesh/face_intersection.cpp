#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace fairsurf {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kRelativeTolerance = 1e-12;

Vec3 corner(const Vertices& V, const Faces& F, int f, int k) { return V.row(F(f, k)).transpose(); }

bool faces_share_vertex(const Faces& F, int f, int g) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (F(f, i) == F(g, j)) return true;
  return false;
}

struct Box {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -Vec3::Constant(std::numeric_limits<double>::infinity());
  void add(const Vec3& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
  bool meets(const Box& o) const { return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all(); }
};

Box face_box(const Vertices& V, const Faces& F, int f) {
  Box b;
  for (int k = 0; k < 3; ++k) b.add(corner(V, F, f, k));
  return b;
}

// A uniform grid of face bounding boxes over `region`.
class FaceGrid {
 public:
  FaceGrid(const Box& region, double cell) : origin_(region.lo) {
    const Vec3 extent = region.hi - region.lo;
    // Cap the cell count at about 2^21 so that a tiny cell on a large region stays affordable.
    const double volume_cells = (extent / cell).array().max(1.0).prod();
    if (volume_cells > 2e6) cell *= std::cbrt(volume_cells / 2e6);
    cell_ = cell;
    for (int d = 0; d < 3; ++d) dims_[d] = std::max(1, static_cast<int>(std::ceil(extent[d] / cell)) + 1);
    cells_.resize(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2]);
  }

  template <class Visit>
  void for_cells(const Box& b, Visit&& visit) const {
    std::array<int, 3> lo{}, hi{};
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::clamp(static_cast<int>(std::floor((b.lo[d] - origin_[d]) / cell_)), 0, dims_[d] - 1);
      hi[d] = std::clamp(static_cast<int>(std::floor((b.hi[d] - origin_[d]) / cell_)), 0, dims_[d] - 1);
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x)
          visit((static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x);
  }

  void insert(int face, const Box& b) {
    for_cells(b, [&](std::size_t c) { cells_[c].push_back(face); });
  }
  const std::vector<int>& cell(std::size_t c) const { return cells_[c]; }

 private:
  Vec3 origin_;
  double cell_ = 1;
  std::array<int, 3> dims_{};
  std::vector<std::vector<int>> cells_;
};

// Coplanar triangles: on the plane's two dominant axes, whether their interiors share an area.
// They do where an edge of one properly crosses an edge of the other, or a corner or the centroid of
// one lies strictly inside the other (one inside the other, or two copies of one triangle).
using Vec2 = Eigen::Vector2d;

double orientation(const Vec2& p, const Vec2& q, const Vec2& r) {
  return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
}

bool strictly_inside(const Vec2& x, const std::array<Vec2, 3>& t, double tolerance) {
  const double sign = orientation(t[0], t[1], t[2]) > 0 ? 1.0 : -1.0;
  for (int k = 0; k < 3; ++k)
    if (sign * orientation(t[k], t[(k + 1) % 3], x) <= tolerance) return false;
  return true;
}

bool opposite_sides(double a, double b, double tolerance) {
  return (a > tolerance && b < -tolerance) || (a < -tolerance && b > tolerance);
}

bool coplanar_triangles_overlap(const std::array<Vec2, 3>& a, const std::array<Vec2, 3>& b, double tolerance) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec2 &p = a[i], &q = a[(i + 1) % 3], &r = b[j], &s = b[(j + 1) % 3];
      if (opposite_sides(orientation(p, q, r), orientation(p, q, s), tolerance) &&
          opposite_sides(orientation(r, s, p), orientation(r, s, q), tolerance))
        return true;
    }
  const Vec2 centroid_a = (a[0] + a[1] + a[2]) / 3, centroid_b = (b[0] + b[1] + b[2]) / 3;
  if (strictly_inside(centroid_a, b, tolerance) || strictly_inside(centroid_b, a, tolerance)) return true;
  for (int k = 0; k < 3; ++k)
    if (strictly_inside(a[k], b, tolerance) || strictly_inside(b[k], a, tolerance)) return true;
  return false;
}

// Whether (b0, b1, b2) lies in the plane of (a0, a1, a2), within the tolerance of
// segment_crosses_triangle, and overlaps it there.
bool coplanar_overlap(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                      const Vec3& b2) {
  const Vec3 n = (a1 - a0).cross(a2 - a0);
  const double length = n.norm();
  if (!(length > 0)) return false;
  const double scale = std::max({(a1 - a0).norm(), (a2 - a0).norm(), (a2 - a1).norm(), (b1 - b0).norm(),
                                 (b2 - b0).norm(), (b2 - b1).norm()});
  const double off_plane = kRelativeTolerance * scale * length;
  for (const Vec3* p : {&b0, &b1, &b2})
    if (std::abs(n.dot(*p - a0)) > off_plane) return false;
  int drop = 0;
  n.cwiseAbs().maxCoeff(&drop);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const auto flat = [u, v](const Vec3& p) { return Vec2(p[u], p[v]); };
  return coplanar_triangles_overlap({flat(a0), flat(a1), flat(a2)}, {flat(b0), flat(b1), flat(b2)},
                                    kRelativeTolerance * scale * scale);
}

}  // namespace

bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0)) return false;
  const double scale = std::max({(b - a).norm(), (c - a).norm(), (q - p).norm()});
  const double tolerance = kRelativeTolerance * scale * std::sqrt(n2);
  const double dp = n.dot(p - a), dq = n.dot(q - a);
  if (!((dp > tolerance && dq < -tolerance) || (dp < -tolerance && dq > tolerance))) return false;
  const Vec3 x = p + (dp / (dp - dq)) * (q - p);
  // Barycentric coordinates of x: each must be strictly positive.
  const double la = n.dot((c - b).cross(x - b)) / n2;
  const double lb = n.dot((a - c).cross(x - c)) / n2;
  const double lc = 1.0 - la - lb;
  return la > kRelativeTolerance && lb > kRelativeTolerance && lc > kRelativeTolerance;
}

bool triangles_cross(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                     const Vec3& b2) {
  return segment_crosses_triangle(a0, a1, b0, b1, b2) || segment_crosses_triangle(a1, a2, b0, b1, b2) ||
         segment_crosses_triangle(a2, a0, b0, b1, b2) || segment_crosses_triangle(b0, b1, a0, a1, a2) ||
         segment_crosses_triangle(b1, b2, a0, a1, a2) || segment_crosses_triangle(b2, b0, a0, a1, a2) ||
         coplanar_overlap(a0, a1, a2, b0, b1, b2);
}

std::vector<FaceIntersection> find_face_intersections(const Vertices& V, const Faces& F,
                                                      std::span<const int> query_faces, int max_results) {
  std::vector<FaceIntersection> found;
  if (query_faces.empty()) return found;
  std::vector<char> is_query(F.rows(), 0);
  Box region;
  double edge_total = 0;
  for (int f : query_faces) {
    if (f < 0 || f >= F.rows())
      throw InvalidArgument("find_face_intersections: face " + std::to_string(f) + " is outside [0, " +
                            std::to_string(F.rows()) + ")");
    is_query[f] = 1;
    const Box b = face_box(V, F, f);
    region.add(b.lo), region.add(b.hi);
    for (int k = 0; k < 3; ++k) edge_total += (corner(V, F, f, k) - corner(V, F, f, (k + 1) % 3)).norm();
  }
  const double cell = std::max(edge_total / (3.0 * query_faces.size()), 1e-12 * (region.hi - region.lo).norm());
  FaceGrid grid(region, cell > 0 ? cell : 1.0);
  // Only the faces whose boxes meet the query faces' region can cross one: they are kept (ascending,
  // with their boxes) and the grid holds their positions among them, so that a small patch on a
  // large mesh stores nothing per face of the mesh but the query flags.
  std::vector<int> near;
  std::vector<Box> boxes;
  for (int f = 0; f < F.rows(); ++f) {
    const Box b = face_box(V, F, f);
    if (!b.meets(region)) continue;
    grid.insert(static_cast<int>(near.size()), b);
    near.push_back(f);
    boxes.push_back(b);
  }
  const auto position = [&](int f) {
    return static_cast<int>(std::lower_bound(near.begin(), near.end(), f) - near.begin());
  };

  std::vector<int> seen(near.size(), -1);
  for (int f : query_faces) {
    const int i = position(f);
    // A query face outside the region its own box spans has a non-finite corner: it crosses nothing.
    if (i == static_cast<int>(near.size()) || near[i] != f) continue;
    std::vector<int> crossed;
    grid.for_cells(boxes[i], [&](std::size_t c) {
      for (int j : grid.cell(c)) {
        const int g = near[j];
        if (g == f || seen[j] == f) continue;
        seen[j] = f;
        if (is_query[g] && g < f) continue;  // that pair was tested from g's side
        if (!boxes[i].meets(boxes[j]) || faces_share_vertex(F, f, g)) continue;
        if (triangles_cross(corner(V, F, f, 0), corner(V, F, f, 1), corner(V, F, f, 2),
                            corner(V, F, g, 0), corner(V, F, g, 1), corner(V, F, g, 2)))
          crossed.push_back(g);
      }
    });
    std::sort(crossed.begin(), crossed.end());
    for (int g : crossed) {
      found.push_back({f, g});
      if (max_results > 0 && static_cast<int>(found.size()) >= max_results) return found;
    }
  }
  return found;
}

}  // namespace fairsurf
