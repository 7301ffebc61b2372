// Vertex merging: exact duplicates, vertices within a tolerance, and coincident borders. A group
// of coincident vertices is merged only when the merged vertex comes out manifold: a pinch would
// only be split again (and a second repair would undo the first one's split).
#include "repair_internal.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace fairsurf::repair_detail {
namespace {

// Union-find with the lowest index as root, so every group is represented by its first vertex.
struct Groups {
  explicit Groups(int n) : rep(n) { std::iota(rep.begin(), rep.end(), 0); }
  int find(int v) {
    while (rep[v] != v) v = rep[v] = rep[rep[v]];
    return v;
  }
  void join(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) rep[std::max(a, b)] = std::min(a, b);
  }
  std::vector<int> rep;
};

void join_exact(const Work& work, const std::vector<int>& candidates, Groups& groups) {
  std::vector<std::pair<std::array<double, 3>, int>> keyed;
  keyed.reserve(candidates.size());
  for (int v : candidates) {
    const Eigen::Vector3d p = work.position(v);
    keyed.push_back({{p.x(), p.y(), p.z()}, v});
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 1; i < keyed.size(); ++i)
    if (keyed[i].first == keyed[i - 1].first) groups.join(keyed[i].second, keyed[i - 1].second);
}

// Joins candidates closer than `tolerance` through a hash grid of cells `tolerance` wide.
void join_close(const Work& work, const std::vector<int>& candidates, double tolerance, Groups& groups) {
  // Clamped so that the conversion stays defined; far-off cells then share a key, which costs only
  // distance tests.
  auto cell_of = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector3<long long>((p / tolerance).array().floor().max(-1e15).min(1e15).cast<long long>());
  };
  auto key = [](const Eigen::Vector3<long long>& c) {
    return static_cast<std::uint64_t>(c.x() * 73856093LL ^ c.y() * 19349663LL ^ c.z() * 83492791LL);
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (int v : candidates) grid[key(cell_of(work.position(v)))].push_back(v);
  for (int v : candidates) {
    const Eigen::Vector3d p = work.position(v);
    const auto c = cell_of(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto found = grid.find(key(c + Eigen::Vector3<long long>(dx, dy, dz)));
          if (found == grid.end()) continue;
          for (int w : found->second)
            if (w != v && (work.position(w) - p).norm() <= tolerance) groups.join(v, w);
        }
  }
}

std::vector<Tri> remapped(const std::vector<Tri>& faces, const std::vector<int>& rep) {
  std::vector<Tri> out;
  out.reserve(faces.size());
  for (const Tri& f : faces) {
    const Tri g{rep[f[0]], rep[f[1]], rep[f[2]]};
    if (g[0] != g[1] && g[1] != g[2] && g[2] != g[0]) out.push_back(g);
  }
  return out;
}

// Undoes the groups whose merged vertex would have several fans or an edge with more than two
// faces; returns how many groups were refused.
int refuse_pinches(const Work& work, Groups& groups) {
  std::vector<int> size(work.num_vertices(), 0);
  for (int v = 0; v < work.num_vertices(); ++v) ++size[groups.find(v)];
  const std::vector<Tri> faces = remapped(work.faces, groups.rep);
  const Adjacency adj = build_adjacency(faces, work.num_vertices());
  const std::vector<int> fan = fan_numbers(faces, adj, std::vector<char>(3 * faces.size(), 1));
  std::vector<char> bad(work.num_vertices(), 0);
  for (int c = 0; c < static_cast<int>(fan.size()); ++c)
    if (fan[c] > 0) bad[faces[c / 3][c % 3]] = 1;
  for (int e = 0; e < adj.num_edges(); ++e) {
    if (adj.corners(e).size() <= 2) continue;
    const int c = adj.corners(e)[0];
    bad[faces[c / 3][c % 3]] = bad[faces[c / 3][(c % 3 + 1) % 3]] = 1;
  }
  int refused = 0;
  for (int r = 0; r < work.num_vertices(); ++r)
    if (size[r] > 1 && bad[r]) ++refused;
  for (int v = 0; v < work.num_vertices(); ++v) {
    const int r = groups.rep[v];  // compressed by apply_groups
    if (size[r] > 1 && bad[r]) groups.rep[v] = v;
  }
  return refused;
}

// Merges the accepted groups into their first vertex; returns how many vertices were merged away.
int apply_groups(Work& work, Groups& groups, RepairReport& report) {
  for (int v = 0; v < work.num_vertices(); ++v) groups.rep[v] = groups.find(v);
  bool any = false;
  for (int v = 0; v < work.num_vertices() && !any; ++v) any = groups.rep[v] != v;
  if (!any) return 0;
  // Refusing a group can turn a neighbouring accepted group into a pinch (a zipper needs both ends
  // of an edge merged), so refuse until the accepted groups are stable, or give up merging at all.
  constexpr int kMaxRounds = 16;
  int round = 0;
  while (const int refused = refuse_pinches(work, groups)) {
    report.merges_refused += refused;
    if (++round == kMaxRounds) {
      std::iota(groups.rep.begin(), groups.rep.end(), 0);
      break;
    }
  }
  int merged = 0;
  for (int v = 0; v < work.num_vertices(); ++v)
    if (groups.rep[v] != v) work.merged_into[v] = groups.rep[v], ++merged;
  for (Tri& f : work.faces)
    for (int& v : f) v = groups.rep[v];
  return merged;
}

}  // namespace

void merge_vertices(Work& work, const RepairOptions& options, RepairReport& report) {
  // Only vertices in use: one merged away earlier stays behind unreferenced, and must not be
  // merged (and counted) again. Faces hold finite vertices only (remove_invalid_faces).
  std::vector<char> used(work.num_vertices(), 0);
  for (const Tri& f : work.faces)
    for (int v : f) used[v] = 1;
  std::vector<int> in_use;
  for (int v = 0; v < work.num_vertices(); ++v)
    if (used[v]) in_use.push_back(v);
  Groups groups(work.num_vertices());
  join_exact(work, in_use, groups);
  const double tolerance = options.merge_tolerance > 0 ? options.merge_tolerance * mean_edge_length(work) : 0.0;
  if (tolerance > 0 && std::isfinite(tolerance)) join_close(work, in_use, tolerance, groups);
  report.vertices_merged += apply_groups(work, groups, report);
}

void stitch_borders(Work& work, const RepairOptions& options, RepairReport& report) {
  const std::vector<char> border = border_vertices(work, build_adjacency(work.faces, work.num_vertices()));
  std::vector<int> candidates;
  for (int v = 0; v < work.num_vertices(); ++v)
    if (border[v]) candidates.push_back(v);
  if (candidates.empty()) return;
  Groups groups(work.num_vertices());
  const double tolerance = options.stitch_tolerance > 0 ? options.stitch_tolerance * mean_edge_length(work) : 0.0;
  if (tolerance > 0 && std::isfinite(tolerance))
    join_close(work, candidates, tolerance, groups);
  else
    join_exact(work, candidates, groups);
  report.border_vertices_stitched += apply_groups(work, groups, report);
}

}  // namespace fairsurf::repair_detail
