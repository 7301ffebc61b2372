// Non-manifold vertices and edges. At an edge with more than two faces two of them stay joined
// and the others are cut loose there; then every vertex whose faces form several fans (joined
// through the remaining edges) gives each fan beyond the first its own copy.
#include "repair_internal.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <utility>

namespace fairsurf::repair_detail {
namespace {

int from(const std::vector<Tri>& faces, int c) { return faces[c / 3][c % 3]; }
int to(const std::vector<Tri>& faces, int c) { return faces[c / 3][(c % 3 + 1) % 3]; }

Eigen::Vector3d unit_normal(const Work& work, int f) {
  const Tri& t = work.faces[f];
  const Eigen::Vector3d a = work.position(t[0]);
  return (work.position(t[1]) - a).cross(work.position(t[2]) - a).normalized();
}

// The two corners of an edge with more than two faces that stay joined: the pair that continues
// the surface most smoothly, i.e. whose normals agree best once the pair is consistently oriented;
// pairs running the edge the same way (they would need a flip) come after every other pair.
std::pair<int, int> kept_pair(const Work& work, std::span<const int> corners) {
  const auto& faces = work.faces;
  std::pair<int, int> best{corners[0], corners[1]};
  double best_score = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = i + 1; j < corners.size(); ++j) {
      const bool opposite = from(faces, corners[j]) == to(faces, corners[i]);
      const double agreement = unit_normal(work, corners[i] / 3).dot(unit_normal(work, corners[j] / 3));
      const double score = opposite ? agreement : -agreement - 4;  // NaN normals (degenerate) lose
      if (score > best_score) best_score = score, best = {corners[i], corners[j]};
    }
  return best;
}

struct Cut {
  std::vector<char> joined;    ///< per corner
  std::vector<char> on_cut;    ///< per vertex: end of an edge with more than two faces
  std::vector<int> extra;      ///< corners of faces cut loose, for the fallback
  int edges = 0;
};

Cut cut_non_manifold_edges(const Work& work, const Adjacency& adj, bool resolve) {
  const auto& faces = work.faces;
  const int num_vertices = work.num_vertices();
  Cut cut{std::vector<char>(3 * faces.size(), 1), std::vector<char>(num_vertices, 0), {}, 0};
  for (int e = 0; e < adj.num_edges(); ++e) {
    const auto corners = adj.corners(e);
    if (corners.size() <= 2) continue;
    ++cut.edges;
    if (!resolve) continue;
    const auto [first, second] = kept_pair(work, corners);
    cut.on_cut[from(faces, corners[0])] = cut.on_cut[to(faces, corners[0])] = 1;
    for (int c : corners)
      if (c != first && c != second) cut.joined[c] = 0, cut.extra.push_back(c);
  }
  return cut;
}

bool on_border(const Adjacency& adj, int corner) { return adj.corners(adj.corner_edge[corner]).size() == 1; }

// At each vertex, which fans keep the vertex (false) and which get a copy of it (true): every fan
// beyond the first of a non-manifold vertex, except at a pinch of the border with
// keep_border_pinches, where only lone triangles go (RepairOptions::keep_border_pinches). Indexed
// by the vertex's first fan entry, `first_fan[v]` + fan number.
struct FanSplit {
  std::vector<int> first_fan;  ///< #V + 1: offsets into `copy`
  std::vector<char> copy;
};

FanSplit fans_to_split(const Work& work, const Adjacency& adj, const std::vector<int>& fan, const Cut& cut,
                       bool split_all, bool keep_border_pinches) {
  const int n = work.num_vertices();
  std::vector<int> fans(n, 1);
  for (int c = 0; c < static_cast<int>(fan.size()); ++c)
    fans[from(work.faces, c)] = std::max(fans[from(work.faces, c)], fan[c] + 1);
  FanSplit split{std::vector<int>(n + 1, 0), {}};
  for (int v = 0; v < n; ++v) split.first_fan[v + 1] = split.first_fan[v] + fans[v];
  split.copy.assign(split.first_fan[n], 0);
  // Per fan: open (a border edge at the vertex), and its faces; a lone triangle is a fan of one
  // face whose three edges are on the border.
  std::vector<char> open(split.first_fan[n], 0);
  std::vector<int> faces_in(split.first_fan[n], 0), lone(split.first_fan[n], 0);
  for (int c = 0; c < static_cast<int>(fan.size()); ++c) {
    const int f = c / 3, slot = split.first_fan[from(work.faces, c)] + fan[c];
    const int before = 3 * f + (c % 3 + 2) % 3;  // the corner of the edge into this vertex
    open[slot] = open[slot] || on_border(adj, c) || on_border(adj, before);
    ++faces_in[slot];
    lone[slot] = on_border(adj, 3 * f) && on_border(adj, 3 * f + 1) && on_border(adj, 3 * f + 2);
  }
  for (int v = 0; v < n; ++v) {
    if (fans[v] < 2 || !(split_all || cut.on_cut[v])) continue;
    const int first = split.first_fan[v];
    const auto is_lone = [&](int i) { return faces_in[first + i] == 1 && lone[first + i]; };
    bool pinch = keep_border_pinches && split_all && !cut.on_cut[v];
    int lone_fans = 0;
    for (int i = 0; i < fans[v]; ++i) pinch = pinch && open[first + i], lone_fans += is_lone(i);
    if (!pinch || lone_fans == fans[v]) {
      for (int i = 1; i < fans[v]; ++i) split.copy[first + i] = 1;
      continue;
    }
    for (int i = 0; i < fans[v]; ++i) split.copy[first + i] = is_lone(i);
  }
  return split;
}

// Gives the fans fans_to_split picks their own copies of their vertex; returns the vertices split.
int split_fans(Work& work, const Adjacency& adj, const Cut& cut, const RepairOptions& options,
               RepairReport& report) {
  const std::vector<int> fan = fan_numbers(work.faces, adj, cut.joined);
  const FanSplit split = fans_to_split(work, adj, fan, cut, options.split_non_manifold_vertices,
                                       options.keep_border_pinches);
  const int n = work.num_vertices();
  std::vector<int> copy_of(split.copy.size(), -1);  // per fan: the vertex it ends on
  int vertices_split = 0;
  for (int v = 0; v < n; ++v) {
    bool any = false;
    for (int slot = split.first_fan[v]; slot < split.first_fan[v + 1]; ++slot)
      if (split.copy[slot]) copy_of[slot] = work.add_copy(v), ++report.vertices_added, any = true;
    vertices_split += any;
  }
  for (int c = 0; c < static_cast<int>(fan.size()); ++c) {
    int& v = work.faces[c / 3][c % 3];
    const int slot = split.first_fan[v] + fan[c];
    if (copy_of[slot] >= 0) v = copy_of[slot];
  }
  return vertices_split;
}

// Last resort for an edge the fans could not separate (its extra faces reach the kept pair around
// both ends): the extra faces get private copies of the edge's ends.
void detach_extra_faces(Work& work, const Cut& cut, RepairReport& report) {
  for (int c : cut.extra)
    for (int k : {c % 3, (c % 3 + 1) % 3}) {
      int& v = work.faces[c / 3][k];
      v = work.add_copy(v);
      ++report.vertices_added;
    }
}

}  // namespace

void split_non_manifold(Work& work, const RepairOptions& options, RepairReport& report, Adjacency* unchanged) {
  const bool resolve = options.resolve_non_manifold_edges;
  if (!resolve && !options.split_non_manifold_vertices) return;
  constexpr int kMaxRounds = 5;
  for (int round = 0; round < kMaxRounds; ++round) {
    Adjacency adj = build_adjacency(work.faces, work.num_vertices());
    const Cut cut = cut_non_manifold_edges(work, adj, resolve);
    if (round == 0 && resolve) report.non_manifold_edges += cut.edges;
    if (round > 0 && resolve && cut.edges > 0) {
      detach_extra_faces(work, cut, report);
      continue;  // the adjacency no longer describes the faces
    }
    const int split = split_fans(work, adj, cut, options, report);
    if (round == 0) report.vertices_split += split;
    if (split == 0 && (cut.edges == 0 || !resolve)) {
      if (round == 0 && unchanged) *unchanged = std::move(adj);
      break;
    }
  }
}

}  // namespace fairsurf::repair_detail
