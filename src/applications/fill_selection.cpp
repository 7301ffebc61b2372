// Which boundary loops fill_holes fills, and why the others are not (fill_selection.h).
#include "fill_selection.h"

#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/validate.h>

#include "mesh/validated.h"
#include "patch/border_pinches.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>

namespace fairsurf::fill_detail {
namespace {

// The holes through each pinch of the border (a vertex with more than two border edges).
std::unordered_map<int, std::vector<int>> holes_at_pinches(const std::vector<std::vector<int>>& loops,
                                                           const std::vector<int>& border_edges) {
  std::unordered_map<int, std::vector<int>> at;
  for (int h = 0; h < static_cast<int>(loops.size()); ++h)
    for (int v : loops[h])
      if (border_edges[v] > 2 && (at[v].empty() || at[v].back() != h)) at[v].push_back(h);
  return at;
}

// Whether filling `loop` alone leaves its pinch v manifold: v has two fans of faces and four border
// edges, the loop passes v once, and its two border edges there bound different fans, so that its
// patch joins them and the other loop through v stays v's one opening (two holes touching at a
// corner). Where the loop's border edges at v bound one fan, its patch would close that fan into a
// cone beside the other.
bool fill_alone_joins_the_fans(const Faces& F, const Topology& topo, const std::vector<int>& loop, int v,
                               int border_edges_at_v) {
  if (border_edges_at_v != 4 || std::count(loop.begin(), loop.end(), v) != 1) return false;
  int count = 0;
  const std::vector<int> fan = detail::fans_at(F, topo, v, count);
  if (count != 2) return false;
  const std::size_t n = loop.size();
  const std::size_t at = static_cast<std::size_t>(std::find(loop.begin(), loop.end(), v) - loop.begin());
  const auto fan_towards = [&](int u) {  // the fan of the (border) face on the edge v-u
    const auto faces = topo.vertex_faces.row(v);
    for (int i = 0; i < static_cast<int>(faces.size()); ++i)
      if (F(faces[i], 0) == u || F(faces[i], 1) == u || F(faces[i], 2) == u) return fan[i];
    return -1;
  };
  const int before = fan_towards(loop[(at + n - 1) % n]), after = fan_towards(loop[(at + 1) % n]);
  return before >= 0 && after >= 0 && before != after;
}

// Why the loop cannot be filled, or "" if it can: at a pinch every loop through the vertex must be
// filled with it, since only their patches together can join the vertex's fans into one
// (border_pinches.h), unless the loop's patch alone joins them (fill_alone_joins_the_fans). The
// reason says why the other loop is not filled (`reports`, as select_holes or this check left
// them), and `pinched_by` names it; a lone triangle hanging at the vertex (debris a scan or a cut
// leaves) that is not taken into a patch is what repair removes.
std::string unfillable_border(int hole, const Faces& F, const Topology& topo, const std::vector<std::vector<int>>& loops,
                              const std::vector<int>& border_edges,
                              const std::unordered_map<int, std::vector<int>>& pinches,
                              const std::vector<char>& chosen, const std::vector<HoleReport>& reports,
                              int& pinched_by) {
  pinched_by = -1;
  if (loops[hole].size() < 3) return "the loop has fewer than three edges";
  for (int v : loops[hole]) {
    const auto it = pinches.find(v);
    if (it == pinches.end()) continue;
    for (int other : it->second) {
      if (chosen[other] || fill_alone_joins_the_fans(F, topo, loops[hole], v, border_edges[v])) continue;
      std::string why = "non-manifold border: vertex " + std::to_string(v) + " is also on hole " +
                        std::to_string(other) + ", which is not filled";
      const std::string& skipped = reports[other].reason;
      if (!skipped.empty()) why += " (" + skipped + ")";
      if (reports[other].around_a_face) why += kLoneTriangleRepairHint;
      pinched_by = other;
      return why;
    }
  }
  return "";
}

// Whether the 3-edge loop `loop` runs around a face of the mesh (a lone triangle, or a triangle
// whose three edges are all on the border): its fill could only be that face again, reversed.
bool around_a_face(const Faces& F, const Topology& topo, const std::vector<int>& loop) {
  if (loop.size() != 3) return false;
  for (int f : topo.vertex_faces.row(loop[0])) {
    const auto corner = [&](int v) { return F(f, 0) == v || F(f, 1) == v || F(f, 2) == v; };
    if (corner(loop[1]) && corner(loop[2])) return true;
  }
  return false;
}

// A face of the mesh whose three edges are all on `loop`, a loop of more than three edges (a lone
// triangle hanging at a vertex the loop passes twice), or -1.
int lone_triangle_on(const Faces& F, const Topology& topo, const std::vector<int>& loop) {
  if (loop.size() <= 3) return -1;
  std::set<std::pair<int, int>> edges;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    edges.insert({std::min(a, b), std::max(a, b)});
  }
  for (int v : loop)
    for (int f : topo.vertex_faces.row(v)) {
      bool all_on_loop = true;
      for (int k = 0; k < 3; ++k) {
        const int a = F(f, k), b = F(f, (k + 1) % 3);
        all_on_loop = all_on_loop && edges.contains({std::min(a, b), std::max(a, b)});
      }
      if (all_on_loop) return f;
    }
  return -1;
}

// Where `loop` is the whole border of a piece of more than one face with no vertex inside (the faces
// reached across edges from the face on its first edge, every vertex of which is on the loop) that
// touches the rest of the mesh at a vertex of the loop, that vertex; −1 otherwise. Such a piece hangs
// inside a hole (a ball cut through a thin part leaves one): filled alone it would close on itself
// there, a pillow joined to the mesh at one vertex, so only a patch of both loops that takes the piece
// in can fill them.
int hanging_piece_vertex(const Faces& F, const Topology& topo, const std::vector<int>& loop) {
  if (loop.size() <= 3) return -1;  // a lone triangle: around_a_face
  const std::set<int> on_loop(loop.begin(), loop.end());
  const std::size_t most_faces = loop.size() - 2;  // a triangulated polygon without inner vertices
  int first = -1;  // the face on the loop's first edge
  for (int f : topo.vertex_faces.row(loop[0]))
    if (F(f, 0) == loop[1] || F(f, 1) == loop[1] || F(f, 2) == loop[1]) first = f;
  if (first < 0) return -1;
  std::set<int> piece;
  std::vector<int> queue{first};
  while (!queue.empty()) {
    const int f = queue.back();
    queue.pop_back();
    if (!piece.insert(f).second) continue;
    if (piece.size() > most_faces) return -1;
    for (int k = 0; k < 3; ++k) {
      if (!on_loop.contains(F(f, k))) return -1;
      for (int g : topo.edge_faces.row(topo.face_edges[3 * f + k]))
        if (!piece.contains(g)) queue.push_back(g);
    }
  }
  if (piece.size() < 2) return -1;
  for (int v : loop)
    for (int f : topo.vertex_faces.row(v))
      if (!piece.contains(f)) return v;
  return -1;
}

// Whether `loop` is the whole border of a flat piece: a part of the mesh, connected through its
// vertices, all of whose vertices lie on the loop and all of whose faces lie in one plane (the two
// triangles of a face of an unwelded soup, a flat polygon on its own). Such a piece has no vertex
// inside, and its fill could only lay the piece again, reversed, on top of itself.
bool borders_a_flat_piece(const Vertices& V, const Faces& F, const Topology& topo, const std::vector<int>& loop) {
  const std::set<int> on_loop(loop.begin(), loop.end());
  const std::size_t most_faces = loop.size() - 2;  // a triangulated polygon without inner vertices
  std::set<int> piece;
  std::vector<int> queue(topo.vertex_faces.row(loop.front()).begin(), topo.vertex_faces.row(loop.front()).end());
  while (!queue.empty()) {
    const int f = queue.back();
    queue.pop_back();
    if (!piece.insert(f).second) continue;
    if (piece.size() > most_faces) return false;
    for (int k = 0; k < 3; ++k) {
      if (!on_loop.contains(F(f, k))) return false;
      for (int g : topo.vertex_faces.row(F(f, k)))
        if (!piece.contains(g)) queue.push_back(g);
    }
  }
  // All the piece's vertices are the loop's: the piece is flat where they lie in one face's plane.
  const int f = *piece.begin();
  const Eigen::Vector3d origin = V.row(F(f, 0)).transpose();
  const Eigen::Vector3d n = (V.row(F(f, 1)).transpose() - origin).cross(V.row(F(f, 2)).transpose() - origin);
  double scale = 0;
  for (int v : loop) scale = std::max(scale, (V.row(v).transpose() - origin).norm());
  constexpr double kFlat = 1e-9;  // relative: a plane up to round-off
  if (!(n.norm() > 0)) return false;
  for (int v : loop)
    if (std::abs(n.dot(V.row(v).transpose() - origin)) > kFlat * scale * n.norm()) return false;
  return true;
}

// Marks the loops that are not to be filled as skipped, with the reason; returns the others.
std::vector<int> select_holes(const Vertices& V, const Faces& F, const Topology& topo,
                              const std::vector<std::vector<int>>& loops, const std::vector<int>& border_edges,
                              const FillOptions& options, std::vector<HoleReport>& reports) {
  const int n = static_cast<int>(loops.size());
  std::vector<char> selected(n, options.holes.empty() ? 1 : 0);
  for (int i : options.holes) {
    if (i < 0 || i >= n)
      throw InvalidArgument("fill_holes: hole " + std::to_string(i) + " is outside [0, " + std::to_string(n) +
                            ") (the mesh has " + std::to_string(n) + " boundary loops)");
    selected[i] = 1;
  }
  for (int i = 0; i < n; ++i) {
    // Set on every loop, selected or not: a hole pinched by a lone triangle's loop then says that
    // repair removes it, whether or not that loop was selected.
    reports[i].around_a_face = around_a_face(F, topo, loops[i]);
    reports[i].hanging_piece_at = hanging_piece_vertex(F, topo, loops[i]);
    if (!selected[i]) reports[i].reason = "not selected";
  }
  if (options.skip_largest && n > 0) {
    const auto largest = std::max_element(loops.begin(), loops.end(),
                                          [](const auto& a, const auto& b) { return a.size() < b.size(); });
    const int i = static_cast<int>(largest - loops.begin());
    if (selected[i]) reports[i].reason = "the largest border, left open (skip largest)";
    selected[i] = 0;
  }
  std::vector<int> chosen;
  for (int i = 0; i < n; ++i) {
    if (!selected[i]) continue;
    if (options.max_hole_edges > 0 && reports[i].border_edges > options.max_hole_edges) {
      reports[i].reason = std::to_string(reports[i].border_edges) + " border edges, more than the maximum " +
                          std::to_string(options.max_hole_edges);
      continue;
    }
    const bool at_pinch =
        std::any_of(loops[i].begin(), loops[i].end(), [&](int v) { return border_edges[v] > 2; });
    if (reports[i].around_a_face && !at_pinch) {
      reports[i].reason = kLoneTriangleSkipped;
      continue;
    }
    reports[i].lone_triangle = lone_triangle_on(F, topo, loops[i]);
    if (borders_a_flat_piece(V, F, topo, loops[i])) {
      reports[i].reason =
          "the loop is the whole border of a flat piece with no vertex inside (a face of an unwelded triangle soup?): "
          "filling it would lay the piece again, reversed, on top of itself; repair welds a soup";
      continue;
    }
    chosen.push_back(i);
  }
  return chosen;
}

}  // namespace

Topology require_fillable(const Mesh& mesh) {
  Topology topo;
  ValidationReport report = detail::validate_keeping_topology(mesh, topo);
  const bool well_formed = !report.no_faces && report.out_of_range_indices.count == 0 &&
                           report.repeated_vertex_faces.count == 0 && report.nan_vertices.count == 0;
  if (well_formed) detail::allow_border_pinches(report, topo);
  require_valid(report, Requirements{}, "fill_holes");
  return topo;
}

std::vector<int> fillable_holes(const Vertices& V, const Faces& F, const Topology& topo,
                                const std::vector<std::vector<int>>& loops, const FillOptions& options,
                                std::vector<HoleReport>& reports) {
  const std::vector<int> border_edges = detail::border_edge_counts(topo);
  const std::vector<int> chosen = select_holes(V, F, topo, loops, border_edges, options, reports);
  std::vector<char> is_chosen(loops.size(), 0);
  for (int h : chosen) is_chosen[h] = 1;
  const auto pinches = holes_at_pinches(loops, border_edges);
  // A hole found unfillable is not filled either, so the holes it shares a pinch with are checked
  // again: along a chain of pinches that ends at a lone triangle not taken in, each hole is filled
  // only where its patch alone can make its pinch manifold.
  for (bool changed = true; changed;) {
    changed = false;
    for (int h : chosen) {
      if (!is_chosen[h]) continue;
      int pinched_by = -1;
      const std::string bad = unfillable_border(h, F, topo, loops, border_edges, pinches, is_chosen, reports, pinched_by);
      if (bad.empty()) continue;
      is_chosen[h] = 0;
      changed = true;
      if (reports[h].around_a_face) {  // not taken into a hole's patch: as elsewhere
        reports[h].reason = kLoneTriangleSkipped;
        continue;
      }
      reports[h].status = HoleStatus::failed, reports[h].reason = bad, reports[h].pinched_by = pinched_by;
    }
  }
  std::vector<int> fillable;
  for (int h : chosen)
    if (is_chosen[h]) fillable.push_back(h);
  return fillable;
}

std::pair<int, int> flagged_loop_at_a_pinch(const std::vector<std::vector<int>>& loops, int h,
                                            const std::vector<char>& candidates) {
  std::vector<int> flagged;
  for (int other = 0; other < static_cast<int>(loops.size()); ++other)
    if (other != h && candidates[static_cast<std::size_t>(other)]) flagged.push_back(other);
  for (int v : loops[static_cast<std::size_t>(h)])  // the first such vertex along loop h
    for (int other : flagged) {
      const std::vector<int>& loop = loops[static_cast<std::size_t>(other)];
      if (std::find(loop.begin(), loop.end(), v) != loop.end()) return {other, v};
    }
  return {-1, -1};
}

void report_lone_triangles_not_taken_in(const std::vector<std::vector<int>>& loops, std::vector<HoleReport>& reports) {
  std::vector<char> reverted(loops.size(), 0);
  for (HoleReport& r : reports)
    if (r.around_a_face && r.status == HoleStatus::failed) {
      r.status = HoleStatus::skipped, r.reason = kLoneTriangleSkipped, r.pinched_by = -1;
      reverted[static_cast<std::size_t>(r.index)] = 1;
    }
  if (std::find(reverted.begin(), reverted.end(), 1) == reverted.end()) return;
  for (HoleReport& r : reports) {
    if (r.status != HoleStatus::failed || r.around_a_face) continue;
    const auto [lone, v] = flagged_loop_at_a_pinch(loops, r.index, reverted);
    if (lone < 0) continue;
    r.reason = "non-manifold border: vertex " + std::to_string(v) + " is also on hole " + std::to_string(lone) +
               ", which is not filled (" + std::string(kLoneTriangleSkipped) + "; the fill that took it in failed (" +
               r.reason + "))" + std::string(kLoneTriangleRepairHint);
    r.pinched_by = lone;
  }
}

}  // namespace fairsurf::fill_detail
