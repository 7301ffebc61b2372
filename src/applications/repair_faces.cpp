// Face-level repairs: invalid, collapsed and duplicate faces, and degenerate (zero-area, needle,
// cap) faces, which are collapsed, flipped or removed without moving a vertex.
#include "repair_internal.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace fairsurf::repair_detail {
namespace {

// Keeps the faces for which keep(f) holds, in order; returns how many were removed.
template <class Keep>
int filter_faces(Work& work, Keep keep) {
  std::vector<Tri> kept;
  kept.reserve(work.faces.size());
  for (const Tri& f : work.faces)
    if (keep(f)) kept.push_back(f);
  const int removed = static_cast<int>(work.faces.size() - kept.size());
  work.faces = std::move(kept);
  return removed;
}

bool repeats_vertex(const Tri& f) { return f[0] == f[1] || f[1] == f[2] || f[2] == f[0]; }

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

int third_vertex(const Tri& f, int a, int b) {
  for (int v : f)
    if (v != a && v != b) return v;
  return -1;
}

// One pass over the degenerate faces, each fixed at most once: faces an edit touched are left for
// the next pass, since the local maps no longer describe them. Returns whether anything changed.
class DegeneratePass {
 public:
  DegeneratePass(Work& work, const RepairOptions& options, RepairReport& report)
      : work_(work), options_(options), report_(report) {}

  bool run(const std::vector<int>& degenerate) {
    index_neighbourhood(degenerate);
    bool changed = false;
    for (int f : degenerate)
      if (!touched_[f]) changed |= fix(f);
    return changed;
  }

  std::vector<char> removed;

 private:
  void index_neighbourhood(const std::vector<int>& degenerate) {
    std::vector<char> near(work_.num_vertices(), 0);
    for (int f : degenerate)
      for (int v : work_.faces[f]) near[v] = 1;
    touched_.assign(work_.faces.size(), 0);
    removed.assign(work_.faces.size(), 0);
    for (int f = 0; f < static_cast<int>(work_.faces.size()); ++f) {
      const Tri& t = work_.faces[f];
      if (!near[t[0]] && !near[t[1]] && !near[t[2]]) continue;
      for (int k = 0; k < 3; ++k) {
        edge_faces_[edge_key(t[k], t[(k + 1) % 3])].push_back(f);
        vertex_faces_[t[k]].push_back(f);
      }
    }
  }

  bool fix(int f) {
    const Tri t = work_.faces[f];
    double length[3];
    for (int k = 0; k < 3; ++k) length[k] = (work_.position(t[(k + 1) % 3]) - work_.position(t[k])).norm();
    const int shortest = static_cast<int>(std::min_element(length, length + 3) - length);
    const int longest = static_cast<int>(std::max_element(length, length + 3) - length);
    if (length[shortest] <= options_.needle_tolerance * length[longest])
      return collapse(t[shortest], t[(shortest + 1) % 3]);
    return fix_cap(f, t[longest], t[(longest + 1) % 3], t[(longest + 2) % 3]);
  }

  // Merges the higher endpoint into the lower one; faces holding both lose a corner and are
  // removed afterwards as collapsed.
  bool collapse(int u, int v) {
    const int keep = std::min(u, v), gone = std::max(u, v);
    for (int g : vertex_faces_[gone])
      if (touched_[g]) return false;
    for (int g : vertex_faces_[gone]) {
      for (int& w : work_.faces[g])
        if (w == gone) w = keep;
      touched_[g] = 1;
    }
    for (int g : vertex_faces_[keep]) touched_[g] = 1;
    work_.merged_into[gone] = keep;
    ++report_.needles_collapsed;
    return true;
  }

  const std::vector<int>& faces_on(int a, int b) { return edge_faces_[edge_key(a, b)]; }

  // Face f runs a -> b -> c with c (nearly) on the edge ab.
  bool fix_cap(int f, int a, int b, int c) {
    std::vector<int> others;
    for (int g : faces_on(a, b))
      if (g != f && !removed[g]) others.push_back(g);
    for (int g : others)
      if (touched_[g]) return false;
    if (others.empty()) return remove_cap(f);
    // The neighbour may run the edge either way: the orientation step settles it afterwards.
    if (others.size() != 1) return false;
    const int g = others[0], d = third_vertex(work_.faces[g], a, b);
    const Tri left{a, d, c}, right{d, b, c};
    const bool flat = is_degenerate(work_, left, options_.degenerate_tolerance) ||
                      is_degenerate(work_, right, options_.degenerate_tolerance);
    if (flat) return is_degenerate(work_, work_.faces[g], options_.degenerate_tolerance) && remove_cap(f);
    for (int h : faces_on(c, d))
      if (!removed[h]) return false;  // the flipped edge exists already
    work_.faces[f] = left;
    work_.faces[g] = right;
    edge_faces_[edge_key(c, d)] = {f, g};
    touched_[f] = touched_[g] = 1;
    ++report_.caps_flipped;
    return true;
  }

  bool remove_cap(int f) {
    removed[f] = touched_[f] = 1;
    ++report_.caps_removed;
    return true;
  }

  Work& work_;
  const RepairOptions& options_;
  RepairReport& report_;
  std::vector<char> touched_;
  std::unordered_map<std::uint64_t, std::vector<int>> edge_faces_;
  std::unordered_map<int, std::vector<int>> vertex_faces_;
};

std::vector<int> degenerate_faces(const Work& work, double tolerance) {
  std::vector<int> found;
  for (int f = 0; f < static_cast<int>(work.faces.size()); ++f)
    if (is_degenerate(work, work.faces[f], tolerance)) found.push_back(f);
  return found;
}

}  // namespace

bool is_degenerate(const Work& work, const Tri& f, double tolerance) {
  const Eigen::Vector3d a = work.position(f[0]), b = work.position(f[1]), c = work.position(f[2]);
  const Eigen::Vector3d cross = (b - a).cross(c - a);
  if (cross.isZero(0.0)) return true;
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return cross.norm() <= tolerance * longest;
}

void remove_invalid_faces(Work& work, RepairReport& report) {
  const int n = work.num_vertices();
  std::vector<char> finite(n);
  for (int v = 0; v < n; ++v) finite[v] = work.V.row(v).allFinite();
  report.invalid_faces_removed += filter_faces(work, [&](const Tri& f) {
    for (int v : f)
      if (v < 0 || v >= n || !finite[v]) return false;
    return !repeats_vertex(f);
  });
}

void remove_collapsed_faces(Work& work, RepairReport& report) {
  report.faces_collapsed += filter_faces(work, [](const Tri& f) { return !repeats_vertex(f); });
}

void remove_duplicate_faces(Work& work, RepairReport& report) {
  std::vector<std::pair<Tri, int>> keyed(work.faces.size());
  for (int f = 0; f < static_cast<int>(work.faces.size()); ++f) {
    Tri key = work.faces[f];
    std::sort(key.begin(), key.end());
    keyed[f] = {key, f};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<char> repeat(work.faces.size(), 0);
  for (std::size_t i = 1; i < keyed.size(); ++i)
    if (keyed[i].first == keyed[i - 1].first) repeat[keyed[i].second] = 1;
  int f = 0;
  report.duplicate_faces_removed += filter_faces(work, [&](const Tri&) { return !repeat[f++]; });
}

void fix_degenerate_faces(Work& work, const RepairOptions& options, RepairReport& report) {
  // Each pass fixes every degenerate face whose neighbourhood no earlier fix of the pass touched;
  // a flip or a collapse can make a neighbour degenerate, hence the bounded repetition.
  constexpr int kMaxPasses = 32;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const std::vector<int> degenerate = degenerate_faces(work, options.degenerate_tolerance);
    if (degenerate.empty()) break;
    DegeneratePass step(work, options, report);
    const bool changed = step.run(degenerate);
    int f = 0;
    filter_faces(work, [&](const Tri&) { return !step.removed[f++]; });
    remove_collapsed_faces(work, report);
    if (!changed) break;
  }
  report.degenerate_faces_left = static_cast<int>(degenerate_faces(work, options.degenerate_tolerance).size());
}

}  // namespace fairsurf::repair_detail
