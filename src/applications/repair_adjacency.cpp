// The light adjacency repair rebuilds after each edit: bucketing corners by their edge's lower
// vertex (a counting sort) keeps it linear, which matters on million-face scans.
#include "repair_internal.h"

#include <algorithm>
#include <numeric>

namespace fairsurf::repair_detail {
namespace {

// Counting sort of `items` (0..n-1) into CSR buckets given by key(item) in [0, buckets).
template <class Key>
void bucket(int n, int buckets, Key key, std::vector<int>& offsets, std::vector<int>& items) {
  offsets.assign(buckets + 1, 0);
  for (int i = 0; i < n; ++i) ++offsets[key(i) + 1];
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  items.resize(n);
  std::vector<int> next(offsets.begin(), offsets.end() - 1);
  for (int i = 0; i < n; ++i) items[next[key(i)]++] = i;
}

}  // namespace

Adjacency build_adjacency(const std::vector<Tri>& faces, int num_vertices) {
  Adjacency adj;
  const int corners = 3 * static_cast<int>(faces.size());
  auto from = [&](int c) { return faces[c / 3][c % 3]; };
  auto to = [&](int c) { return faces[c / 3][(c % 3 + 1) % 3]; };
  auto low = [&](int c) { return std::min(from(c), to(c)); };
  auto high = [&](int c) { return std::max(from(c), to(c)); };

  std::vector<int> offsets, sorted;
  bucket(corners, num_vertices, low, offsets, sorted);
  adj.corner_edge.resize(corners);
  adj.edge_corners.reserve(corners);
  adj.edge_offsets.reserve(corners / 2 + 2);
  for (int v = 0; v < num_vertices; ++v) {
    auto first = sorted.begin() + offsets[v], last = sorted.begin() + offsets[v + 1];
    // Buckets hold a vertex's few edges: an insertion sort (stable, so corners stay ascending)
    // beats std::stable_sort, which allocates a buffer per call.
    for (auto it = first; it != last; ++it)
      for (auto j = it; j != first && high(*(j - 1)) > high(*j); --j) std::iter_swap(j - 1, j);
    for (auto it = first; it != last; ++it) {
      if (it != first && high(*it) != high(*(it - 1))) adj.edge_offsets.push_back(static_cast<int>(adj.edge_corners.size()));
      adj.corner_edge[*it] = static_cast<int>(adj.edge_offsets.size()) - 1;
      adj.edge_corners.push_back(*it);
    }
    if (first != last) adj.edge_offsets.push_back(static_cast<int>(adj.edge_corners.size()));
  }
  bucket(corners, num_vertices, from, adj.vertex_offsets, adj.vertex_faces);
  for (int& c : adj.vertex_faces) c /= 3;  // corners ascend, so their faces do too
  return adj;
}

std::vector<int> fan_numbers(const std::vector<Tri>& faces, const Adjacency& adj,
                             const std::vector<char>& corner_joined) {
  std::vector<int> fan(3 * faces.size(), 0);
  std::vector<int> parent, number;
  const int num_vertices = static_cast<int>(adj.vertex_offsets.size()) - 1;
  for (int v = 0; v < num_vertices; ++v) {
    const auto star = adj.faces_of(v);
    const int n = static_cast<int>(star.size());
    if (n < 2) continue;
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    auto corner_of = [&](int f) {
      int k = 0;
      while (faces[f][k] != v) ++k;
      return 3 * f + k;
    };
    for (int i = 0; i < n; ++i) {
      const int c = corner_of(star[i]);
      for (int side : {c, 3 * (c / 3) + (c % 3 + 2) % 3}) {  // the two edges of the face at v
        if (!corner_joined[side]) continue;
        for (int other : adj.corners(adj.corner_edge[side])) {
          if (!corner_joined[other]) continue;
          const int j = static_cast<int>(std::lower_bound(star.begin(), star.end(), other / 3) - star.begin());
          const int a = find(i), b = find(j);
          if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
      }
    }
    number.assign(n, -1);
    int fans = 0;
    for (int i = 0; i < n; ++i) {
      const int root = find(i);
      if (number[root] < 0) number[root] = fans++;
      fan[corner_of(star[i])] = number[root];
    }
  }
  return fan;
}

std::vector<char> border_vertices(const Work& work, const Adjacency& adj) {
  std::vector<char> on_border(work.num_vertices(), 0);
  for (int e = 0; e < adj.num_edges(); ++e) {
    if (adj.corners(e).size() != 1) continue;
    const int c = adj.corners(e)[0];
    on_border[work.faces[c / 3][c % 3]] = on_border[work.faces[c / 3][(c % 3 + 1) % 3]] = 1;
  }
  return on_border;
}

double mean_edge_length(const Work& work) {
  double total = 0;
  for (const Tri& f : work.faces)
    for (int k = 0; k < 3; ++k) total += (work.position(f[k]) - work.position(f[(k + 1) % 3])).norm();
  return work.faces.empty() ? 0.0 : total / (3.0 * static_cast<double>(work.faces.size()));
}

}  // namespace fairsurf::repair_detail
