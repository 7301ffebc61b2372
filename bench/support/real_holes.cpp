#include "real_holes.h"

#include <fairsurf/mesh/topology.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace fairsurf::bench {

double mean_edge_length(const Mesh& mesh) {
  return fairsurf::mean_edge_length(mesh.V, build_topology(mesh.F, mesh.num_vertices()));
}

int euler_characteristic(const Mesh& mesh) {
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  int used = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) used += topo.vertex_faces.size(v) > 0;
  return used - static_cast<int>(topo.edges.rows()) + mesh.num_faces();
}

namespace {

// Keeps the faces for which `remove` is false and drops the vertices they no longer use.
template <class Remove>
CutMesh cut_faces(const Mesh& mesh, Remove remove) {
  std::vector<int> faces;
  std::vector<char> used(mesh.num_vertices(), 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (remove(f)) continue;
    faces.push_back(f);
    for (int k = 0; k < 3; ++k) used[mesh.F(f, k)] = 1;
  }
  CutMesh cut;
  std::vector<int> new_index(mesh.num_vertices(), -1);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (!used[v]) {
      cut.dropped.push_back(v);
      continue;
    }
    new_index[v] = static_cast<int>(cut.kept.size());
    cut.kept.push_back(v);
  }
  cut.mesh.V.resize(static_cast<int>(cut.kept.size()), 3);
  for (int i = 0; i < static_cast<int>(cut.kept.size()); ++i) cut.mesh.V.row(i) = mesh.V.row(cut.kept[i]);
  cut.mesh.F.resize(static_cast<int>(faces.size()), 3);
  for (int i = 0; i < static_cast<int>(faces.size()); ++i)
    for (int k = 0; k < 3; ++k) cut.mesh.F(i, k) = new_index[mesh.F(faces[i], k)];
  return cut;
}

}  // namespace

CutMesh cut_ball(const Mesh& mesh, const Eigen::Vector3d& centre, double radius) {
  std::vector<char> inside(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    inside[v] = (mesh.V.row(v).transpose() - centre).norm() <= radius;
  return cut_faces(mesh, [&](int f) { return inside[mesh.F(f, 0)] && inside[mesh.F(f, 1)] && inside[mesh.F(f, 2)]; });
}

CutMesh cut_irregular(const Mesh& mesh, int start, CutShape shape, int size, std::mt19937_64& draw, bool tidy) {
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const auto neighbours = [&](int f) {
    std::vector<int> across;
    for (int k = 0; k < 3; ++k)
      for (int g : topo.edge_faces.row(topo.face_edges[3 * f + k]))
        if (g != f) across.push_back(g);
    return across;
  };
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(draw() % static_cast<std::uint64_t>(n)); };
  std::vector<char> removed(mesh.num_faces(), 0);
  if (shape == CutShape::blob) {
    std::vector<int> blob{start};
    removed[start] = 1;
    for (int grown = 1, tries = 0; grown < size && tries < 100 * size; ++tries) {
      std::vector<int> free;
      for (int g : neighbours(blob[pick(blob.size())]))
        if (!removed[g]) free.push_back(g);
      if (free.empty()) continue;
      const int g = free[pick(free.size())];
      removed[g] = 1;
      blob.push_back(g);
      ++grown;
    }
  } else {
    std::vector<int> walk{start};
    for (int s = 0; s < size; ++s) {
      const std::vector<int> next = neighbours(walk.back());
      if (next.empty()) break;
      walk.push_back(next[pick(next.size())]);
    }
    for (int f : walk)
      for (int k = 0; k < 3; ++k)
        for (int g : topo.vertex_faces.row(mesh.F(f, k))) removed[g] = 1;
  }
  for (bool again = tidy; again;) {
    again = false;
    for (int f = 0; f < mesh.num_faces(); ++f) {
      if (removed[f]) continue;
      const std::vector<int> across = neighbours(f);
      if (std::none_of(across.begin(), across.end(), [&](int g) { return !removed[g]; })) removed[f] = 1, again = true;
    }
  }
  return cut_faces(mesh, [&](int f) { return removed[f] != 0; });
}

CutMesh cut_slab(const Mesh& mesh, int vertex, const Eigen::Vector3d& axis, double half_width) {
  const Eigen::Vector3d point = mesh.V.row(vertex).transpose();
  std::vector<char> inside(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    inside[v] = std::abs((mesh.V.row(v).transpose() - point).dot(axis)) < half_width;
  const auto in_slab = [&](int f) { return inside[mesh.F(f, 0)] && inside[mesh.F(f, 1)] && inside[mesh.F(f, 2)]; };
  // Flood the slab's faces from those at `vertex` across their edges.
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  std::vector<char> removed(mesh.num_faces(), 0);
  std::vector<int> stack;
  for (int f : topo.vertex_faces.row(vertex))
    if (in_slab(f)) {
      removed[f] = 1;
      stack.push_back(f);
    }
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k)
      for (int g : topo.edge_faces.row(topo.face_edges[3 * f + k]))
        if (!removed[g] && in_slab(g)) {
          removed[g] = 1;
          stack.push_back(g);
        }
  }
  return cut_faces(mesh, [&](int f) { return removed[f] != 0; });
}

void add_normal_noise(Mesh& mesh, double sigma, std::uint64_t seed) {
  // Area-weighted normals: the sum of the incident faces' cross products (twice their areas).
  Vertices normals = Vertices::Zero(mesh.num_vertices(), 3);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::RowVector3d n = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k) normals.row(mesh.F(f, k)) += n;
  }
  std::mt19937_64 engine(seed);
  // Uniform in (0, 1] from the top 53 bits: std::uniform_real_distribution is not portable.
  const auto uniform = [&] { return (static_cast<double>(engine() >> 11) + 1.0) * 0x1.0p-53; };
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const double u1 = uniform(), u2 = uniform();
    const double gaussian = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    const double length = normals.row(v).norm();
    if (length > 0) mesh.V.row(v) += sigma * gaussian * normals.row(v) / length;
  }
}

double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const double denominator = va + vb + vc;
  if (denominator <= 0) return std::min({ap.norm(), bp.norm(), cp.norm()});  // degenerate triangle
  return (p - (a + ab * (vb / denominator) + ac * (vc / denominator))).norm();
}

SurfaceDistance::SurfaceDistance(const Mesh& surface, const Eigen::Vector3d& centre)
    : surface_(surface), centre_(centre) {
  faces_.reserve(surface.num_faces());
  for (int f = 0; f < surface.num_faces(); ++f) {
    const Eigen::Vector3d a = surface.V.row(surface.F(f, 0)), b = surface.V.row(surface.F(f, 1)),
                          c = surface.V.row(surface.F(f, 2));
    const Eigen::Vector3d mid = (a + b + c) / 3.0;
    const double rho = std::max({(a - mid).norm(), (b - mid).norm(), (c - mid).norm()});
    faces_.emplace_back((mid - centre).norm() - rho, f);
  }
  std::sort(faces_.begin(), faces_.end());
}

double SurfaceDistance::operator()(const Eigen::Vector3d& p) const {
  // A face's distance to p is at least its bound to the centre minus |p − centre|.
  const double offset = (p - centre_).norm();
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [bound, f] : faces_) {
    if (bound - offset >= best) break;
    best = std::min(best, point_triangle_distance(p, surface_.V.row(surface_.F(f, 0)), surface_.V.row(surface_.F(f, 1)),
                                                  surface_.V.row(surface_.F(f, 2))));
  }
  return best;
}

DistanceStats distance_stats(const SurfaceDistance& distance, const Vertices& V, const std::vector<int>& rows,
                             double unit) {
  DistanceStats s;
  for (int v : rows) {
    const double d = distance(V.row(v).transpose()) / unit;
    s.mean += d;
    s.max = std::max(s.max, d);
    ++s.count;
  }
  if (s.count > 0) s.mean /= s.count;
  return s;
}

std::vector<std::vector<int>> loops_of(const Mesh& mesh) {
  return boundary_loops(mesh.F, build_topology(mesh.F, mesh.num_vertices()));
}

std::string border_sizes(const Mesh& cut) {
  std::string text;
  for (const auto& loop : loops_of(cut)) {
    if (!text.empty()) text += '+';
    text += std::to_string(loop.size());
  }
  return text;
}

bool removed_disks(const Mesh& uncut, const Mesh& cut) {
  const int loops = static_cast<int>(loops_of(cut).size());
  return euler_characteristic(uncut) - euler_characteristic(cut) == loops;
}

std::vector<int> rows_from(int first, int end) {
  std::vector<int> rows;
  for (int v = first; v < end; ++v) rows.push_back(v);
  return rows;
}

}  // namespace fairsurf::bench
