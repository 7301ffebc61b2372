#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include "parallel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <string>
#include <utility>

namespace fairsurf {
namespace {

std::atomic<std::uint64_t> builds{0};  // topology_builds(); relaxed: a count, not a synchronization

// Counting-sort construction of vertex -> incident faces; rows come out in ascending face order.
Csr build_vertex_faces(const Faces& F, int num_vertices) {
  Csr vf;
  vf.offsets.assign(num_vertices + 1, 0);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++vf.offsets[F(f, k) + 1];
  std::partial_sum(vf.offsets.begin(), vf.offsets.end(), vf.offsets.begin());
  vf.indices.resize(vf.offsets.back());
  std::vector<int> fill(vf.offsets.begin(), vf.offsets.end() - 1);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) vf.indices[fill[F(f, k)]++] = f;
  return vf;
}

// Neighbours of each vertex from its incident faces, sorted and deduplicated in place.
Csr build_vertex_vertices(const Faces& F, const Csr& vf) {
  const int n = vf.rows();
  Csr vv;
  vv.offsets.assign(n + 1, 0);
  std::vector<int> scratch;
  // First pass collects each row into a scratch buffer to count distinct neighbours; the second
  // writes them. Valence is small, so the per-row sort is cheap and the total cost is linear.
  std::vector<int> all;
  all.reserve(static_cast<std::size_t>(vf.indices.size()) * 2);
  for (int v = 0; v < n; ++v) {
    scratch.clear();
    for (int f : vf.row(v))
      for (int k = 0; k < 3; ++k)
        if (F(f, k) != v) scratch.push_back(F(f, k));
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    all.insert(all.end(), scratch.begin(), scratch.end());
    vv.offsets[v + 1] = static_cast<int>(all.size());
  }
  all.shrink_to_fit();
  vv.indices = std::move(all);
  return vv;
}

// Throws InvalidArgument, naming `who`, for a face from `first` on with an index outside
// [0, num_vertices) or that repeats a vertex.
void check_faces(const Faces& F, int num_vertices, const std::string& who, int first = 0) {
  if (num_vertices < 0) throw InvalidArgument(who + ": negative vertex count");
  for (int f = first; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = F(f, k);
      if (v < 0 || v >= num_vertices)
        throw InvalidArgument(who + ": face " + std::to_string(f) + " has vertex index " + std::to_string(v) +
                              " outside [0, " + std::to_string(num_vertices) + ")");
    }
    if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 2) == F(f, 0))
      throw InvalidArgument(who + ": face " + std::to_string(f) + " repeats a vertex");
  }
}

// The edges, face_edges and edge_faces of `t`, from F and t.vertex_vertices (ascending rows).
void add_edges(const Faces& F, Topology& t) {
  const int num_vertices = t.num_vertices;
  // Edge (v, w) with v < w is owned by v; rows are sorted, so owned neighbours form a suffix of the
  // row and edges come out in lexicographic order without a global sort.
  std::vector<int> first_owned(num_vertices), edge_offset(num_vertices + 1, 0);
  for (int v = 0; v < num_vertices; ++v) {
    auto row = t.vertex_vertices.row(v);
    first_owned[v] = static_cast<int>(std::upper_bound(row.begin(), row.end(), v) - row.begin());
    edge_offset[v + 1] = edge_offset[v] + static_cast<int>(row.size()) - first_owned[v];
  }
  t.edges.resize(edge_offset.back(), 2);
  for (int v = 0; v < num_vertices; ++v) {
    auto row = t.vertex_vertices.row(v);
    for (int j = first_owned[v], e = edge_offset[v]; j < static_cast<int>(row.size()); ++j, ++e) {
      t.edges(e, 0) = v;
      t.edges(e, 1) = row[j];
    }
  }
  auto edge_index = [&](int a, int b) {
    const int v = std::min(a, b), w = std::max(a, b);
    auto row = t.vertex_vertices.row(v);
    const int pos = static_cast<int>(std::lower_bound(row.begin(), row.end(), w) - row.begin());
    return edge_offset[v] + pos - first_owned[v];
  };

  t.face_edges.resize(static_cast<std::size_t>(F.rows()) * 3);
  t.edge_faces.offsets.assign(t.edges.rows() + 1, 0);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int e = edge_index(F(f, k), F(f, (k + 1) % 3));
      t.face_edges[3 * f + k] = e;
      ++t.edge_faces.offsets[e + 1];
    }
  std::partial_sum(t.edge_faces.offsets.begin(), t.edge_faces.offsets.end(), t.edge_faces.offsets.begin());
  t.edge_faces.indices.resize(t.edge_faces.offsets.back());
  std::vector<int> fill(t.edge_faces.offsets.begin(), t.edge_faces.offsets.end() - 1);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) t.edge_faces.indices[fill[t.face_edges[3 * f + k]]++] = f;
}

// The neighbours of each vertex of a part of the parent mesh: the parent's row, already sorted,
// filtered to the neighbours the part's faces keep. The renumbering is ascending, so what is kept
// stays in order and no row is sorted again. Each kept neighbour is found in the parent's row by
// bisection; `slot` marks its position there.
Csr derived_vertex_vertices(const Faces& F, const Csr& vf, const Topology& parent, std::span<const int> to_parent) {
  const int n = vf.rows();
  Csr vv;
  vv.offsets.assign(n + 1, 0);
  vv.indices.reserve(static_cast<std::size_t>(vf.indices.size()) * 2);
  std::vector<int> slot;  // per position of the parent's row: the part's vertex there, or -1
  for (int v = 0; v < n; ++v) {
    const auto row = parent.vertex_vertices.row(to_parent[v]);
    slot.assign(row.size(), -1);
    for (int f : vf.row(v))
      for (int k = 0; k < 3; ++k) {
        const int u = F(f, k);
        if (u == v) continue;
        const auto at = std::lower_bound(row.begin(), row.end(), to_parent[u]);
        if (at == row.end() || *at != to_parent[u])
          throw InvalidArgument("derive_topology: face " + std::to_string(f) + " has an edge the parent does not");
        slot[at - row.begin()] = u;
      }
    for (int u : slot)
      if (u >= 0) vv.indices.push_back(u);
    vv.offsets[v + 1] = static_cast<int>(vv.indices.size());
  }
  return vv;
}

// extend_topology's vertex -> faces: each base row, then the added faces at that vertex (their
// indices exceed every base face's, so rows stay ascending).
Csr extended_vertex_faces(const Csr& base, const Faces& F, int first_added, int num_vertices) {
  Csr vf;
  vf.offsets.assign(num_vertices + 1, 0);
  for (int v = 0; v < base.rows(); ++v) vf.offsets[v + 1] = base.size(v);
  for (int f = first_added; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++vf.offsets[F(f, k) + 1];
  std::partial_sum(vf.offsets.begin(), vf.offsets.end(), vf.offsets.begin());
  vf.indices.resize(vf.offsets.back());
  std::vector<int> fill(vf.offsets.begin(), vf.offsets.end() - 1);
  for (int v = 0; v < base.rows(); ++v) {
    const auto row = base.row(v);
    std::copy(row.begin(), row.end(), vf.indices.begin() + fill[v]);
    fill[v] += static_cast<int>(row.size());
  }
  for (int f = first_added; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) vf.indices[fill[F(f, k)]++] = f;
  return vf;
}

// extend_topology's vertex -> neighbours: the base row where no added face touches the vertex,
// else the base row merged with the added faces' neighbours, sorted and deduplicated.
Csr extended_vertex_vertices(const Csr& base, const Faces& F, int first_added, const Csr& vf) {
  const int n = vf.rows();
  Csr vv;
  vv.offsets.assign(n + 1, 0);
  vv.indices.reserve(base.indices.size() + static_cast<std::size_t>(F.rows() - first_added) * 6);
  std::vector<int> scratch;
  for (int v = 0; v < n; ++v) {
    const std::span<const int> old = v < base.rows() ? base.row(v) : std::span<const int>{};
    const auto faces = vf.row(v);
    const auto added = std::lower_bound(faces.begin(), faces.end(), first_added);
    if (added == faces.end()) {
      vv.indices.insert(vv.indices.end(), old.begin(), old.end());
    } else {
      scratch.assign(old.begin(), old.end());
      for (auto f = added; f != faces.end(); ++f)
        for (int k = 0; k < 3; ++k)
          if (F(*f, k) != v) scratch.push_back(F(*f, k));
      std::sort(scratch.begin(), scratch.end());
      scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
      vv.indices.insert(vv.indices.end(), scratch.begin(), scratch.end());
    }
    vv.offsets[v + 1] = static_cast<int>(vv.indices.size());
  }
  return vv;
}

// The added faces' edges (from row first_added of F) that `base` does not have, as (min, max)
// pairs, sorted and unique.
std::vector<std::pair<int, int>> fresh_edges(const Topology& base, const Faces& F, int first_added) {
  std::vector<std::pair<int, int>> fresh;
  const auto base_has = [&](int v, int w) {
    if (v >= base.num_vertices) return false;
    const auto row = base.vertex_vertices.row(v);
    return std::binary_search(row.begin(), row.end(), w);
  };
  for (int f = first_added; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = std::min(F(f, k), F(f, (k + 1) % 3)), w = std::max(F(f, k), F(f, (k + 1) % 3));
      if (!base_has(v, w)) fresh.emplace_back(v, w);
    }
  std::sort(fresh.begin(), fresh.end());
  fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
  return fresh;
}

// The base's edges merged with `fresh` in lexicographic order into `edges`; returns each base
// edge's index among them (moved up by the fresh edges before it).
std::vector<int> merge_edges(const Edges& base, const std::vector<std::pair<int, int>>& fresh, Edges& edges) {
  const int base_edges = static_cast<int>(base.rows()), fresh_count = static_cast<int>(fresh.size());
  edges.resize(base_edges + fresh_count, 2);
  std::vector<int> moved(base_edges);
  for (int e = 0, i = 0, out = 0; e < base_edges || i < fresh_count; ++out) {
    if (i == fresh_count || (e < base_edges && std::make_pair(base(e, 0), base(e, 1)) < fresh[i])) {
      edges.row(out) = base.row(e);
      moved[e++] = out;
    } else {
      edges(out, 0) = fresh[i].first, edges(out, 1) = fresh[i].second;
      ++i;
    }
  }
  return moved;
}

// Index of the edge (a, b) in `edges` (sorted lexicographically, holding it), by bisection.
int sorted_edge_index(const Edges& edges, int a, int b) {
  const std::pair<int, int> key(std::min(a, b), std::max(a, b));
  int lo = 0, hi = static_cast<int>(edges.rows());
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (std::make_pair(edges(mid, 0), edges(mid, 1)) < key) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

// extend_topology's edges, face_edges and edge_faces: the base faces' entries follow their edges'
// move (merge_edges) instead of being searched again; only the added faces' are searched.
void add_extended_edges(const Topology& base, const Faces& F, Topology& t) {
  const int first_added = base.num_faces;
  const std::vector<int> moved = merge_edges(base.edges, fresh_edges(base, F, first_added), t.edges);
  t.face_edges.resize(static_cast<std::size_t>(F.rows()) * 3);
  for (std::size_t i = 0; i < base.face_edges.size(); ++i) t.face_edges[i] = moved[base.face_edges[i]];
  for (int f = first_added; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      t.face_edges[3 * static_cast<std::size_t>(f) + k] = sorted_edge_index(t.edges, F(f, k), F(f, (k + 1) % 3));

  // Each edge's faces: the base row (ascending, all below first_added), then the added faces.
  t.edge_faces.offsets.assign(t.edges.rows() + 1, 0);
  for (std::size_t e = 0; e < moved.size(); ++e) t.edge_faces.offsets[moved[e] + 1] = base.edge_faces.size(static_cast<int>(e));
  for (std::size_t i = 3 * static_cast<std::size_t>(first_added); i < t.face_edges.size(); ++i)
    ++t.edge_faces.offsets[t.face_edges[i] + 1];
  std::partial_sum(t.edge_faces.offsets.begin(), t.edge_faces.offsets.end(), t.edge_faces.offsets.begin());
  t.edge_faces.indices.resize(t.edge_faces.offsets.back());
  std::vector<int> fill(t.edge_faces.offsets.begin(), t.edge_faces.offsets.end() - 1);
  for (std::size_t e = 0; e < moved.size(); ++e) {
    const auto row = base.edge_faces.row(static_cast<int>(e));
    std::copy(row.begin(), row.end(), t.edge_faces.indices.begin() + fill[moved[e]]);
    fill[moved[e]] += static_cast<int>(row.size());
  }
  for (int f = first_added; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) t.edge_faces.indices[fill[t.face_edges[3 * static_cast<std::size_t>(f) + k]]++] = f;
}

}  // namespace

Topology extend_topology(const Topology& base, const Faces& F, int num_vertices) {
  if (F.rows() < base.num_faces || num_vertices < base.num_vertices)
    throw InvalidArgument("extend_topology: the mesh has fewer faces or vertices than the base connectivity's");
  check_faces(F, num_vertices, "extend_topology", base.num_faces);
  Topology t;
  t.num_vertices = num_vertices;
  t.num_faces = static_cast<int>(F.rows());
  t.vertex_faces = extended_vertex_faces(base.vertex_faces, F, base.num_faces, num_vertices);
  t.vertex_vertices = extended_vertex_vertices(base.vertex_vertices, F, base.num_faces, t.vertex_faces);
  add_extended_edges(base, F, t);
  return t;
}

std::uint64_t topology_builds() { return builds.load(std::memory_order_relaxed); }

Topology build_topology(const Faces& F, int num_vertices) {
  builds.fetch_add(1, std::memory_order_relaxed);
  check_faces(F, num_vertices, "build_topology");
  Topology t;
  t.num_vertices = num_vertices;
  t.num_faces = static_cast<int>(F.rows());
  t.vertex_faces = build_vertex_faces(F, num_vertices);
  t.vertex_vertices = build_vertex_vertices(F, t.vertex_faces);
  add_edges(F, t);
  return t;
}

Topology derive_topology(const Topology& parent, const Faces& F, std::span<const int> to_parent) {
  const int num_vertices = static_cast<int>(to_parent.size());
  for (int v = 0; v < num_vertices; ++v)
    if (to_parent[v] < 0 || to_parent[v] >= parent.num_vertices || (v > 0 && to_parent[v] <= to_parent[v - 1]))
      throw InvalidArgument("derive_topology: the parent vertices are not ascending indices in [0, " +
                            std::to_string(parent.num_vertices) + ")");
  check_faces(F, num_vertices, "derive_topology");
  Topology t;
  t.num_vertices = num_vertices;
  t.num_faces = static_cast<int>(F.rows());
  t.vertex_faces = build_vertex_faces(F, num_vertices);
  t.vertex_vertices = derived_vertex_vertices(F, t.vertex_faces, parent, to_parent);
  add_edges(F, t);
  return t;
}

std::vector<char> boundary_vertex_flags(const Topology& topo) {
  std::vector<char> flags(topo.num_vertices, 0);
  for (int e = 0; e < topo.edges.rows(); ++e)
    if (topo.is_boundary_edge(e)) flags[topo.edges(e, 0)] = flags[topo.edges(e, 1)] = 1;
  return flags;
}

std::vector<std::vector<int>> boundary_loops(const Faces& F, const Topology& topo) {
  // Directed border half-edges a->b, oriented like their single face.
  struct HalfEdge {
    int from, to;
  };
  std::vector<HalfEdge> half;
  for (int e = 0; e < topo.edges.rows(); ++e) {
    if (!topo.is_boundary_edge(e)) continue;
    const int f = topo.edge_faces.row(e)[0];
    for (int k = 0; k < 3; ++k)
      if (topo.face_edges[3 * f + k] == e) half.push_back({F(f, k), F(f, (k + 1) % 3)});
  }
  // Border half-edges at each vertex, both directions, so that a walk can continue across an
  // orientation flip instead of stopping there.
  Csr at;
  at.offsets.assign(topo.num_vertices + 1, 0);
  for (const auto& h : half) ++at.offsets[h.from + 1], ++at.offsets[h.to + 1];
  std::partial_sum(at.offsets.begin(), at.offsets.end(), at.offsets.begin());
  at.indices.resize(at.offsets.back());
  std::vector<int> fill(at.offsets.begin(), at.offsets.end() - 1);
  for (int h = 0; h < static_cast<int>(half.size()); ++h)
    at.indices[fill[half[h].from]++] = h, at.indices[fill[half[h].to]++] = h;

  std::vector<char> used(half.size(), 0);
  std::vector<std::vector<int>> loops;
  for (int start = 0; start < static_cast<int>(half.size()); ++start) {
    if (used[start]) continue;
    std::vector<int> loop{half[start].from};
    used[start] = 1;
    int current = half[start].to;
    while (current != loop.front()) {
      loop.push_back(current);
      int next = -1, reversed = -1;
      for (int h : at.row(current)) {
        if (used[h]) continue;
        if (half[h].from == current && next < 0) next = h;
        if (half[h].to == current && reversed < 0) reversed = h;
      }
      if (next < 0) next = reversed;  // orientation flips here; walk the edge backwards
      if (next < 0) break;            // an open chain: cannot happen on a closed border
      used[next] = 1;
      current = half[next].from == current ? half[next].to : half[next].from;
    }
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end(),
            [](const auto& a, const auto& b) { return a.front() < b.front(); });
  return loops;
}

Components connected_components(const Faces& F, const Topology& topo) {
  std::vector<int> parent(topo.num_vertices);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 1; k < 3; ++k) {
      const int a = find(F(f, 0)), b = find(F(f, k));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  Components c;
  c.vertex_component.assign(topo.num_vertices, -1);
  std::vector<int> id(topo.num_vertices, -1);
  for (int v = 0; v < topo.num_vertices; ++v) {
    if (topo.vertex_faces.size(v) == 0) continue;
    const int r = find(v);
    if (id[r] < 0) id[r] = c.count++;
    c.vertex_component[v] = id[r];
  }
  c.face_component.resize(F.rows());
  for (int f = 0; f < F.rows(); ++f) c.face_component[f] = c.vertex_component[F(f, 0)];
  return c;
}

std::vector<int> ring_distances(const Topology& topo, std::span<const int> seeds, int max_rings) {
  std::vector<int> dist(topo.num_vertices, -1);
  std::vector<int> frontier, next;
  for (int s : seeds) {
    if (s < 0 || s >= topo.num_vertices)
      throw InvalidArgument("ring_distances: seed vertex " + std::to_string(s) + " out of range");
    if (dist[s] < 0) dist[s] = 0, frontier.push_back(s);
  }
  for (int ring = 1; ring <= max_rings && !frontier.empty(); ++ring) {
    next.clear();
    for (int v : frontier)
      for (int w : topo.vertex_vertices.row(v))
        if (dist[w] < 0) dist[w] = ring, next.push_back(w);
    frontier.swap(next);
  }
  return dist;
}

std::vector<int> k_ring(const Topology& topo, std::span<const int> seeds, int k) {
  const auto dist = ring_distances(topo, seeds, k);
  std::vector<int> out;
  for (int v = 0; v < topo.num_vertices; ++v)
    if (dist[v] >= 0) out.push_back(v);
  return out;
}

void face_normals_and_areas(const Vertices& V, const Faces& F, Eigen::MatrixX3d& normals,
                            Eigen::VectorXd& areas) {
  normals.resize(F.rows(), 3);
  areas.resize(F.rows());
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double norm = cross.norm();
    areas[f] = 0.5 * norm;
    normals.row(f) = norm > 0 ? Eigen::Vector3d(cross / norm) : Eigen::Vector3d::Zero();
  }
}

double mean_edge_length(const Vertices& V, const Topology& topo) {
  double sum = 0;
  int measured = 0;
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e) {
    const Eigen::Vector3d d = V.row(topo.edges(e, 1)) - V.row(topo.edges(e, 0));
    if (!d.allFinite()) continue;
    sum += d.norm();
    ++measured;
  }
  return measured > 0 ? sum / measured : 0.0;
}

// The face areas (the costly part: three gathered corners per face) are computed in parallel; the
// scatter to the corners stays serial and in face order, so the sums do not depend on threads.
Eigen::VectorXd vertex_areas(const Vertices& V, const Faces& F) {
  const int num_faces = static_cast<int>(F.rows());
  Eigen::VectorXd thirds(num_faces);
#pragma omp parallel for if (detail::worth_parallel(num_faces)) schedule(static)
  for (int f = 0; f < num_faces; ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    thirds[f] = (b - a).cross(c - a).norm() / 6.0;
  }
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(V.rows());
  for (int f = 0; f < num_faces; ++f)
    for (int k = 0; k < 3; ++k) areas[F(f, k)] += thirds[f];
  return areas;
}

}  // namespace fairsurf
