#include "border_pinches.h"

#include <fairsurf/mesh/errors.h>

#include "loop_faces.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace fairsurf::detail {
namespace {

using Vec3 = Eigen::Vector3d;

struct HalfEdge {
  int from, to, face;  // face: the mesh face that contains from→to
};

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Links, at the pinch p, each incoming half-edge to the outgoing one of the next wedge
// counter-clockwise about p's normal (next[incoming] = outgoing).
void link_pinch(const Vertices& V, const Faces& F, const Topology& topo, int p, const std::vector<HalfEdge>& half,
                const std::vector<int>& at_p, std::vector<int>& next) {
  int count = 0;
  const std::vector<int> fan = fans_at(F, topo, p, count);
  const auto faces = topo.vertex_faces.row(p);
  const auto fan_of = [&](int f) { return fan[std::lower_bound(faces.begin(), faces.end(), f) - faces.begin()]; };
  std::vector<int> out(count, -1), in(count, -1);
  for (int h : at_p) (half[h].from == p ? out : in)[fan_of(half[h].face)] = h;
  Vec3 normal = Vec3::Zero();
  std::vector<Vec3> centre(count, Vec3::Zero());
  const Vec3 origin = V.row(p).transpose();
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Vec3 a = V.row(F(faces[i], 0)).transpose(), b = V.row(F(faces[i], 1)).transpose(),
               c = V.row(F(faces[i], 2)).transpose();
    normal += (b - a).cross(c - a);
    centre[fan[i]] += (a + b + c) / 3.0 - origin;
  }
  for (int w = 0; w < count; ++w)
    if (out[w] < 0 || in[w] < 0)
      throw InvalidMeshError("fill_holes: at the pinch vertex " + std::to_string(p) +
                             ", a fan of faces has no border edge of the loops being filled on one side");
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.normalized().cross(e1);
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> angle(count);
  for (int w = 0; w < count; ++w) angle[w] = std::atan2(centre[w].dot(e2), centre[w].dot(e1));
  std::sort(order.begin(), order.end(), [&](int a, int b) { return angle[a] < angle[b]; });
  for (int i = 0; i < count; ++i) next[in[order[i]]] = out[order[(i + 1) % count]];
}

}  // namespace

std::vector<int> fans_at(const Faces& F, const Topology& topo, int v, int& count) {
  const auto faces = topo.vertex_faces.row(v);
  const int n = static_cast<int>(faces.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::unordered_map<int, int> face_at_link;  // link vertex x -> first face (position) on edge v-x
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const int x = F(faces[i], k);
      if (x == v) continue;
      const auto [it, fresh] = face_at_link.emplace(x, i);
      if (!fresh) parent[find_root(parent, i)] = find_root(parent, it->second);
    }
  std::vector<int> id(n, -1), root_id(n, -1);
  count = 0;
  for (int i = 0; i < n; ++i) {
    const int r = find_root(parent, i);
    if (root_id[r] < 0) root_id[r] = count++;
    id[i] = root_id[r];
  }
  return id;
}

std::vector<std::vector<int>> relink_pinched_loops(const Vertices& V, const Faces& F, const Topology& topo,
                                                   const std::vector<std::vector<int>>& loops) {
  std::vector<HalfEdge> half;
  for (const auto& loop : loops) {
    const std::vector<int> faces = loop_edge_faces(F, topo, loop, "fill_holes");
    for (std::size_t t = 0; t < loop.size(); ++t) half.push_back({loop[t], loop[(t + 1) % loop.size()], faces[t]});
  }
  std::unordered_map<int, std::vector<int>> at;  // border half-edges of the loops at each vertex
  for (int h = 0; h < static_cast<int>(half.size()); ++h) at[half[h].from].push_back(h), at[half[h].to].push_back(h);
  std::vector<int> next(half.size(), -1);
  for (auto& [v, edges] : at) {
    std::sort(edges.begin(), edges.end());
    if (edges.size() > 2) {
      link_pinch(V, F, topo, v, half, edges, next);
      continue;
    }
    const int in = half[edges[0]].to == v ? edges[0] : edges[1];
    next[in] = in == edges[0] ? edges[1] : edges[0];
  }
  std::vector<std::vector<int>> relinked;
  std::vector<char> used(half.size(), 0);
  for (int start = 0; start < static_cast<int>(half.size()); ++start) {
    if (used[start]) continue;
    std::vector<int> loop;
    for (int h = start; !used[h]; h = next[h]) {
      if (next[h] < 0)
        throw InvalidMeshError("fill_holes: the border edge " + std::to_string(half[h].from) + "-" +
                               std::to_string(half[h].to) + " has no border edge of the loops after it");
      used[h] = 1;
      loop.push_back(half[h].from);
    }
    relinked.push_back(std::move(loop));
  }
  return relinked;
}

std::string patch_non_manifold(const Faces& F, const Topology& topo, int first_face) {
  std::vector<char> seen(topo.num_vertices, 0);
  for (int f = first_face; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int e = topo.face_edges[3 * f + k];
      if (topo.edge_faces.size(e) > 2)
        return "the patch makes edge " + std::to_string(topo.edges(e, 0)) + "-" + std::to_string(topo.edges(e, 1)) +
               " non-manifold (" + std::to_string(topo.edge_faces.size(e)) + " faces)";
      const int v = F(f, k);
      if (seen[v]) continue;
      seen[v] = 1;
      int fans = 0;
      fans_at(F, topo, v, fans);
      if (fans > 1)
        return "the patch makes vertex " + std::to_string(v) + " non-manifold (" + std::to_string(fans) +
               " fans of faces)";
    }
  return "";
}

std::string patch_zero_area_face(const Vertices& V, const Faces& F, int first_face) {
  for (int f = first_face; f < F.rows(); ++f) {
    const Vec3 a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(), c = V.row(F(f, 2)).transpose();
    if (!(b - a).cross(c - a).isZero(0.0)) continue;
    const std::string face = "the patch has a zero-area triangle, new face " + std::to_string(f);
    for (int k = 0; k < 3; ++k) {
      const int u = F(f, k), w = F(f, (k + 1) % 3);
      if (V.row(u) == V.row(w))
        return face + ", whose vertices " + std::to_string(std::min(u, w)) + " and " +
               std::to_string(std::max(u, w)) +
               " lie at one position: the hole's border passes twice through a vertex split in two (as "
               "repair splits a non-manifold vertex or edge), and no patch there has room for a triangle";
    }
    return face;
  }
  return "";
}

}  // namespace fairsurf::detail
