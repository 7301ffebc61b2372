// Orientation, small components and loose fins, all on the manifold mesh the splits leave.
#include "repair_internal.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace fairsurf::repair_detail {
namespace {

// Whether the face of corner c runs along its edge from the lower to the higher vertex.
bool upward(const std::vector<Tri>& faces, int c) {
  return faces[c / 3][c % 3] < faces[c / 3][(c % 3 + 1) % 3];
}

// Face f's corners in the order of their edges' indices. Edges are numbered by their vertex pairs,
// which flipping does not change, so a second repair walks the faces exactly as the first did and
// finds nothing left to flip, even on a non-orientable component.
std::array<int, 3> edge_order(const Adjacency& adj, int f) {
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return adj.corner_edge[3 * f + a] < adj.corner_edge[3 * f + b]; });
  return order;
}

}  // namespace

// Propagates "flip / keep" from each component's lowest face across two-face edges, as validate
// does, then flips the minority; a face met with both wishes marks its component non-orientable.
void orient_faces(Work& work, RepairReport& report, const Adjacency* adjacency) {
  Adjacency built;
  if (!adjacency) built = build_adjacency(work.faces, work.num_vertices());
  const Adjacency& adj = adjacency ? *adjacency : built;
  const int num_faces = static_cast<int>(work.faces.size());
  std::vector<signed char> flip(num_faces, -1);
  std::vector<int> stack;
  report.non_orientable_components = 0;  // a finding of the current faces, not a count of changes
  for (int seed = 0; seed < num_faces; ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    stack.assign(1, seed);
    bool conflict = false;
    std::vector<int> component{seed};
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k : edge_order(adj, f)) {
        const auto corners = adj.corners(adj.corner_edge[3 * f + k]);
        if (corners.size() != 2) continue;
        const int other = corners[0] == 3 * f + k ? corners[1] : corners[0];
        const int g = other / 3;
        const signed char wanted = flip[f] ^ (upward(work.faces, 3 * f + k) == upward(work.faces, other));
        if (flip[g] < 0) {
          flip[g] = wanted;
          stack.push_back(g);
          component.push_back(g);
        } else if (flip[g] != wanted) {
          conflict = true;
        }
      }
    }
    report.non_orientable_components += conflict;
    // The majority's orientation wins (a scan with one stray face keeps its normals); ties keep the
    // seed's. A second repair finds nothing to flip, so this stays idempotent.
    const auto flipped = std::count_if(component.begin(), component.end(), [&](int f) { return flip[f] == 1; });
    if (2 * flipped > static_cast<std::ptrdiff_t>(component.size()))
      for (int f : component) flip[f] ^= 1;
  }
  for (int f = 0; f < num_faces; ++f)
    if (flip[f] == 1) std::swap(work.faces[f][1], work.faces[f][2]), ++report.faces_flipped;
}

namespace {

// Per vertex, the lowest vertex of its component: faces connected through shared vertices
// (validate's and topology.h's notion).
std::vector<int> component_roots(const Work& work) {
  std::vector<int> parent(work.num_vertices());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Tri& f : work.faces)
    for (int k = 1; k < 3; ++k) {
      const int a = find(f[0]), b = find(f[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  for (int v = 0; v < work.num_vertices(); ++v) parent[v] = find(v);
  return parent;
}

// Faces that hang by one edge from the rest of their piece, at a vertex that is theirs alone and
// a copy of a vertex inside a surface, along an edge that doubles an edge of the surface (the same
// two input vertices): pages a split cut loose at a non-manifold edge. A hole through such a page
// runs along that surface edge, where any patch touches the surface.
// `inside`: per working vertex, whether it has faces and is on no border edge.
std::vector<char> hanging_pages(const Work& work, const Adjacency& adj, const std::vector<char>& inside) {
  const long long stride = work.V.rows();
  const auto input_edge = [&](int a, int b) {
    const long long x = work.origin[a], y = work.origin[b];
    return std::min(x, y) * stride + std::max(x, y);
  };
  std::unordered_set<int> inside_at;  // input vertices with a working copy inside a surface
  for (int v = 0; v < work.num_vertices(); ++v)
    if (inside[v]) inside_at.insert(work.origin[v]);
  std::unordered_map<long long, int> working_edges;  // input edge -> the working edges on it
  for (int e = 0; e < adj.num_edges(); ++e) {
    const int c = adj.corners(e)[0];
    const Tri& f = work.faces[c / 3];
    ++working_edges[input_edge(f[c % 3], f[(c % 3 + 1) % 3])];
  }
  const auto doubled = [&](int a, int b) { return working_edges[input_edge(a, b)] > 1; };
  std::vector<char> page(work.faces.size(), 0);
  for (std::size_t i = 0; i < work.faces.size(); ++i) {
    const Tri& f = work.faces[i];
    for (int k = 0; k < 3 && !page[i]; ++k) {
      const int v = f[k];
      if (adj.faces_of(v).size() != 1 || !inside_at.contains(work.origin[v])) continue;
      page[i] = doubled(v, f[(k + 1) % 3]) || doubled(v, f[(k + 2) % 3]);
    }
  }
  return page;
}

}  // namespace

// Components with fewer faces than min_faces.
void remove_small_components(Work& work, int min_faces, RepairReport& report) {
  const int n = work.num_vertices();
  const std::vector<int> root = component_roots(work);
  std::vector<int> size(n, 0);
  for (const Tri& f : work.faces) ++size[root[f[0]]];
  for (int v = 0; v < n; ++v)
    if (root[v] == v && size[v] > 0 && size[v] < min_faces)
      ++report.small_components_removed, report.small_component_faces_removed += size[v];
  std::vector<Tri> kept;
  kept.reserve(work.faces.size());
  for (const Tri& f : work.faces)
    if (size[root[f[0]]] >= min_faces) kept.push_back(f);
  work.faces = std::move(kept);
}

// A fin is a component with no vertex inside (every vertex on a border edge) that shares an input
// vertex with a component that has one: a strip of faces a split cut loose from a surface at a
// non-manifold edge or vertex, as a scanner's zipper leaves them. Left in, it lies against the
// surface it hung from, where a fill of its border or of a hole beside it runs into that surface.
// A page hanging by one edge (hanging_pages) is the fin of one face that is still joined to its piece.
void remove_loose_fins(Work& work, RepairReport& report) {
  const int n = work.num_vertices();
  if (n == work.V.rows()) return;  // no split made a copy: nothing was cut loose
  const std::vector<int> root = component_roots(work);
  const Adjacency adj = build_adjacency(work.faces, n);
  const std::vector<char> on_border = border_vertices(work, adj);
  std::vector<char> inside(n, 0), has_inside(n, 0);  // per vertex; per component root
  for (int v = 0; v < n; ++v)
    if (!adj.faces_of(v).empty() && !on_border[v]) inside[v] = has_inside[root[v]] = 1;
  std::unordered_set<int> on_a_surface;  // input vertices used by a component with a vertex inside
  for (int v = 0; v < n; ++v)
    if (!adj.faces_of(v).empty() && has_inside[root[v]]) on_a_surface.insert(work.origin[v]);
  std::vector<char> fin(n, 0);
  for (int v = 0; v < n; ++v)
    if (!adj.faces_of(v).empty() && !has_inside[root[v]] && on_a_surface.contains(work.origin[v]))
      fin[root[v]] = 1;
  const std::vector<char> page = hanging_pages(work, adj, inside);
  std::vector<int> fin_faces(n, 0);
  std::vector<Tri> kept;
  kept.reserve(work.faces.size());
  for (std::size_t i = 0; i < work.faces.size(); ++i) {
    const Tri& f = work.faces[i];
    if (fin[root[f[0]]]) ++fin_faces[root[f[0]]];
    else if (page[i]) ++report.fins_removed, ++report.fin_faces_removed;
    else kept.push_back(f);
  }
  for (int v = 0; v < n; ++v)
    if (fin_faces[v] > 0) ++report.fins_removed, report.fin_faces_removed += fin_faces[v];
  work.faces = std::move(kept);
}

}  // namespace fairsurf::repair_detail
