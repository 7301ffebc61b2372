#include "hole_meshes.h"

#include "analytic_meshes.h"
#include "test_support.h"

#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/mesh_operations.h>
#include <fairsurf/mesh/topology.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <numbers>
#include <random>
#include <vector>

namespace fairsurf::test {

using Vec3 = Eigen::Vector3d;

namespace {

// `mesh` with only the faces `keep` accepts and the vertices they use, in their order.
Mesh keep_faces(const Mesh& mesh, const std::function<bool(int)>& keep) {
  std::vector<int> kept_faces;
  std::vector<int> new_index(mesh.num_vertices(), -1);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (!keep(f)) continue;
    kept_faces.push_back(f);
    for (int k = 0; k < 3; ++k) new_index[mesh.F(f, k)] = 0;
  }
  Mesh out;
  int count = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (new_index[v] == 0) new_index[v] = count++;
  out.V.resize(count, 3);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (new_index[v] >= 0) out.V.row(new_index[v]) = mesh.V.row(v);
  out.F.resize(static_cast<int>(kept_faces.size()), 3);
  for (int i = 0; i < static_cast<int>(kept_faces.size()); ++i)
    for (int k = 0; k < 3; ++k) out.F(i, k) = new_index[mesh.F(kept_faces[i], k)];
  return out;
}

}  // namespace

Mesh cut_hole(const Mesh& mesh, const std::function<bool(const Vec3&)>& inside) {
  return keep_faces(mesh, [&](int f) {
    for (int k = 0; k < 3; ++k)
      if (inside(mesh.V.row(mesh.F(f, k)).transpose())) return false;
    return true;
  });
}

Mesh cut_ball(const Mesh& mesh, const Vec3& centre, double radius) {
  return keep_faces(mesh, [&](int f) {
    for (int k = 0; k < 3; ++k)
      if ((mesh.V.row(mesh.F(f, k)).transpose() - centre).norm() > radius) return true;
    return false;
  });
}

Mesh cut_faces(const Mesh& mesh, std::span<const int> faces) {
  std::vector<char> removed(static_cast<std::size_t>(mesh.num_faces()), 0);
  for (int f : faces) removed.at(static_cast<std::size_t>(f)) = 1;
  return keep_faces(mesh, [&](int f) { return !removed[static_cast<std::size_t>(f)]; });
}

bool new_faces_cross(const Mesh& holed, const Mesh& filled) {
  std::vector<int> new_faces(filled.num_faces() - holed.num_faces());
  std::iota(new_faces.begin(), new_faces.end(), holed.num_faces());
  return !find_face_intersections(filled.V, filled.F, new_faces, 1).empty();
}

Mesh grid_with_chained_pinches() {
  const Mesh grid = test::regular_grid(16, 16, 1.0);
  const auto centroid = [&](int f) {
    return Vec3((grid.V.row(grid.F(f, 0)) + grid.V.row(grid.F(f, 1)) + grid.V.row(grid.F(f, 2))) / 3.0);
  };
  const auto in_a = [](const Vec3& c) { return c.x() > 4 && c.x() < 6 && c.y() > 4 && c.y() < 6; };
  const auto in_b = [](const Vec3& c) { return c.x() > 6 && c.x() < 10 && c.y() > 6 && c.y() < 10; };
  // The lone triangle: a face of B's square with one corner on B's border and two inside it.
  const auto inside_b = [](const Vec3& p) { return p.x() > 6.5 && p.x() < 9.5 && p.y() > 6.5 && p.y() < 9.5; };
  int lone = -1;
  for (int f = 0; f < grid.num_faces() && lone < 0; ++f) {
    if (!in_b(centroid(f))) continue;
    int inner = 0;
    for (int k = 0; k < 3; ++k) inner += inside_b(grid.V.row(grid.F(f, k)).transpose());
    if (inner == 2) lone = f;
  }
  Mesh holed;
  holed.V = grid.V;
  std::vector<int> kept;
  for (int f = 0; f < grid.num_faces(); ++f)
    if (f == lone || (!in_a(centroid(f)) && !in_b(centroid(f)))) kept.push_back(f);
  holed.F.resize(static_cast<int>(kept.size()), 3);
  for (int i = 0; i < static_cast<int>(kept.size()); ++i) holed.F.row(i) = grid.F.row(kept[i]);
  return holed;
}

Mesh sphere_hole_with_lone_triangle(int* pinch) {
  Mesh m = cut_ball(icosphere(3), Vec3(0, 0, 1), 0.45);
  const auto loops = boundary_loops(m.F, build_topology(m.F, m.num_vertices()));
  const int p = loops.at(0).front();
  const int n = m.num_vertices();
  m.V.conservativeResize(n + 2, 3);
  m.V.row(n) = 0.9 * m.V.row(p) + Eigen::RowVector3d(0.0, 0.05, 0.1);
  m.V.row(n + 1) = 0.9 * m.V.row(p) + Eigen::RowVector3d(0.0, -0.05, 0.1);
  m.F.conservativeResize(m.num_faces() + 1, 3);
  m.F.row(m.num_faces() - 1) << p, n, n + 1;
  if (pinch) *pinch = p;
  return m;
}

Mesh wavy_annulus(int n, unsigned seed, double amplitude, int waves, double height_jitter) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> radius(0.6, 1.2), jitter(-0.3, 0.3);
  Mesh m;
  m.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (i + jitter(rng)) / n;
    const double r = radius(rng);
    m.V.row(i) << r * std::cos(t), r * std::sin(t), amplitude * std::sin(waves * t) + height_jitter * amplitude * jitter(rng);
    const double u = 2 * std::numbers::pi * i / n;
    m.V.row(n + i) << 3 * std::cos(u), 3 * std::sin(u), 0.0;
  }
  m.F.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const int a = i, b = (i + 1) % n;
    m.F.row(2 * i) << a, n + i, n + b;  // counter-clockwise seen from +z
    m.F.row(2 * i + 1) << a, n + b, b;
  }
  return m;
}

Mesh s_sheet_with_hole() {
  Mesh sheet = saddle_patch(12, 1.0);
  for (int v = 0; v < sheet.num_vertices(); ++v) sheet.V(v, 2) = 0.5 * std::sin(std::numbers::pi * sheet.V(v, 0));
  const Vec3 centre(0.5, 0.35, 0.5 * std::sin(0.5 * std::numbers::pi));
  return cut_hole(sheet, [&](const Vec3& p) { return (p - centre).norm() < 0.22; });
}

Mesh cut_slab(const Mesh& mesh, const Vec3& point, const Vec3& axis, double half_width) {
  const auto in_slab = [&](int f) {
    for (int k = 0; k < 3; ++k)
      if (std::abs((mesh.V.row(mesh.F(f, k)).transpose() - point).dot(axis)) >= half_width) return false;
    return true;
  };
  // The band's faces connected across edges to those at the vertex nearest `point`.
  int nearest = 0;
  for (int v = 1; v < mesh.num_vertices(); ++v)
    if ((mesh.V.row(v).transpose() - point).norm() < (mesh.V.row(nearest).transpose() - point).norm()) nearest = v;
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      edge_faces[std::minmax(mesh.F(f, k), mesh.F(f, (k + 1) % 3))].push_back(f);
  std::vector<char> removed(mesh.num_faces(), 0);
  std::vector<int> stack;
  for (int f = 0; f < mesh.num_faces(); ++f)
    if ((mesh.F.row(f).array() == nearest).any() && in_slab(f)) removed[f] = 1, stack.push_back(f);
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k)
      for (int g : edge_faces[std::minmax(mesh.F(f, k), mesh.F(f, (k + 1) % 3))])
        if (!removed[g] && in_slab(g)) removed[g] = 1, stack.push_back(g);
  }
  return keep_faces(mesh, [&](int f) { return !removed[f]; });
}

Mesh capsules_one_gap_blocked() {
  const Mesh capsule = ellipsoid(4, 0.5, 0.5, 1.2);
  Mesh blocked = cut_slab(capsule, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.2);
  blocked = concatenate_meshes(blocked, ellipsoid(3, 0.8, 0.8, 0.03));
  blocked.V.col(0).array() += 4.0;
  return concatenate_meshes(blocked, cut_slab(capsule, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.3));
}

Mesh sphere_with_two_holes_touching() {
  const Mesh sphere = icosphere(3);
  std::vector<int> fan;
  for (int f = 0; f < sphere.num_faces(); ++f)
    if ((sphere.F.row(f).array() == 0).any()) fan.push_back(f);
  const auto shared = [&](int f, int g) {
    int count = 0;
    for (int i = 0; i < 3; ++i) count += (sphere.F.row(g).array() == sphere.F(f, i)).any() ? 1 : 0;
    return count;
  };
  for (int g : fan)
    if (shared(fan.front(), g) == 1) {
      const int cut[] = {fan.front(), g};
      return cut_faces(sphere, cut);
    }
  return sphere;  // not reached: a fan of five or more faces has two that share only its centre
}

void add_normal_noise(Mesh& mesh, double sigma, unsigned seed) {
  Vertices normal = Vertices::Zero(mesh.num_vertices(), 3);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Vec3 a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Vec3 area_normal = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) normal.row(mesh.F(f, k)) += area_normal.transpose();
  }
  std::mt19937 random(seed);
  std::normal_distribution<double> deviate(0.0, sigma);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const double length = normal.row(v).norm();
    if (length > 0) mesh.V.row(v) += deviate(random) * normal.row(v) / length;
  }
}

// Ericson, Real-Time Collision Detection, 5.1.5: the closest point by Voronoi regions.
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denominator = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).norm();
}

double distance_to_mesh(const Vec3& p, const Mesh& mesh) {
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Vec3 a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const double box_distance = (lo - p).cwiseMax(p - hi).cwiseMax(0.0).norm();
    if (box_distance >= best) continue;
    best = std::min(best, point_triangle_distance(p, a, b, c));
  }
  return best;
}

}  // namespace fairsurf::test
