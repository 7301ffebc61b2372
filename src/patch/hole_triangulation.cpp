#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/patch/hole_triangulation.h>

#include "loop_delaunay.h"
#include "loop_faces.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace fairsurf {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Vec3 point(const Vertices& V, int v) { return V.row(v).transpose(); }

// Unnormalized normal of the triangle (pa, pb, pc), counter-clockwise; zero if degenerate.
Vec3 triangle_normal(const Vec3& pa, const Vec3& pb, const Vec3& pc) {
  const Vec3 n = (pb - pa).cross(pc - pa);
  const double longest = std::max({(pb - pa).squaredNorm(), (pc - pb).squaredNorm(),
                                   (pa - pc).squaredNorm()});
  return n.norm() <= 1e-12 * longest ? Vec3::Zero() : n;
}

Vec3 triangle_normal(const Vertices& V, int a, int b, int c) {
  return triangle_normal(point(V, a), point(V, b), point(V, c));
}

// The angle between two normals by its sine and cosine, each times |n1||n2|; `missing` where either
// normal is (a degenerate triangle).
struct Turn {
  double sine = 0, cosine = 1;
  bool missing = false;
};

Turn turn_between(const Vec3& n1, const Vec3& n2) {
  if (n1.isZero() || n2.isZero()) return {0, 1, true};
  return {n1.cross(n2).norm(), n1.dot(n2), false};
}

// The angle, in [0, π]; π where a normal is missing.
double angle_of(const Turn& t) { return t.missing ? std::numbers::pi : std::atan2(t.sine, t.cosine); }

// Angle between two normals, in [0, π]; π when either is missing (degenerate triangle). atan2 of
// the sine and cosine stays accurate near 0, where acos of the dot product would lose half the digits.
double dihedral(const Vec3& n1, const Vec3& n2) { return angle_of(turn_between(n1, n2)); }

// The sign of the turn's angle minus `limit` (in [0, π), given by its cosine and sine) where it is
// sure, 0 where it is too close to tell or a normal is missing: the sign of sin(angle − limit)
// times |n1||n2|, without the arctangent. The margin is far above the rounding of both sides, so a
// sure sign is the sign that angle_of(t) − limit has as computed.
int sure_sign(const Turn& t, double cos_limit, double sin_limit) {
  if (t.missing) return 0;
  const double x = t.sine * cos_limit - t.cosine * sin_limit, margin = 1e-12 * (t.sine + std::abs(t.cosine));
  return x > margin ? 1 : x < -margin ? -1 : 0;
}

// The cosine and sine of the last angle asked for: the programme asks for the same few angles
// (a sub-polygon's largest, the best candidate's) over and over.
class CachedSinCos {
 public:
  void set(double angle) {
    if (angle == angle_) return;
    angle_ = angle;
    cos_ = std::cos(angle), sin_ = std::sin(angle);
  }
  double cos() const { return cos_; }
  double sin() const { return sin_; }

 private:
  double angle_ = std::numeric_limits<double>::quiet_NaN(), cos_ = 1, sin_ = 0;
};

// Liepa's weight, preceded under the Delaunay restriction by the count of triangles that are not
// faces of the loop's tetrahedralization (`outside`, 0 without the restriction).
struct Weight {
  double angle = 0.0;
  double area = 0.0;
  int outside = 0;
};

constexpr int kUnreached = std::numeric_limits<int>::max();

bool lighter(const Weight& a, const Weight& b) {
  if (a.outside != b.outside) return a.outside < b.outside;
  if (a.angle < b.angle - kAngleTie) return true;
  if (a.angle > b.angle + kAngleTie) return false;
  return a.area < b.area;
}

std::uint64_t edge_key(int from, int to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) |
         static_cast<std::uint32_t>(to);
}

using detail::TriangleKey;

// The vertex set of a triangle, independent of its orientation and corner order.
TriangleKey triangle_key(int a, int b, int c) {
  TriangleKey v{a, b, c};
  std::sort(v.begin(), v.end());
  return v;
}

// Weight of `faces` against the outside faces whose normals are given per directed edge a→b
// (the outside face contains a→b, so the new face across it contains b→a).
TriangulationWeight weigh(const Vertices& V, const Faces& faces,
                          const std::unordered_map<std::uint64_t, Vec3>& outside) {
  std::unordered_map<std::uint64_t, Vec3> inside;
  TriangulationWeight w;
  for (int f = 0; f < faces.rows(); ++f) {
    const Vec3 n = triangle_normal(V, faces(f, 0), faces(f, 1), faces(f, 2));
    w.area += 0.5 * n.norm();
    for (int k = 0; k < 3; ++k) inside[edge_key(faces(f, k), faces(f, (k + 1) % 3))] = n;
  }
  for (const auto& [key, n] : inside) {
    const std::uint64_t twin = (key << 32) | (key >> 32);
    const auto across = inside.find(twin);
    const auto mesh = outside.find(twin);
    if (across != inside.end() && key < twin)
      w.max_dihedral_angle = std::max(w.max_dihedral_angle, dihedral(n, across->second));
    if (mesh != outside.end())
      w.max_dihedral_angle = std::max(w.max_dihedral_angle, dihedral(n, mesh->second));
  }
  return w;
}

using detail::is_mesh_edge;

std::uint64_t undirected_key(int u, int v) { return edge_key(std::min(u, v), std::max(u, v)); }

// Diagonals and triangles of earlier rounds that crossed the mesh (triangulate_hole).
struct Forbidden {
  std::unordered_set<std::uint64_t> diagonals;  // undirected_key
  std::set<TriangleKey> triangles;
};

// Forbids what makes new face `q` of `all` cross face `o`: each edge of q through o's interior
// (every triangle on that diagonal would cross o too), else q itself (an edge of o pierces it).
void forbid_crossing(const Vertices& V, const Topology& topo, const Faces& all, int q, int o,
                     Forbidden& forbidden) {
  const auto p = [&](int f, int k) -> Vec3 { return V.row(all(f, k)).transpose(); };
  bool edge_through = false;
  for (int k = 0; k < 3; ++k) {
    const int u = all(q, k), v = all(q, (k + 1) % 3);
    if (!is_mesh_edge(topo, u, v) &&
        segment_crosses_triangle(p(q, k), p(q, (k + 1) % 3), p(o, 0), p(o, 1), p(o, 2))) {
      forbidden.diagonals.insert(undirected_key(u, v));
      edge_through = true;
    }
  }
  if (!edge_through) forbidden.triangles.insert(triangle_key(all(q, 0), all(q, 1), all(q, 2)));
}

// One polygon to triangulate: vertex indices in loop order and, for each side (t, t+1 mod m), the
// normal of the face outside it (zero if there is none, e.g. along a cut not yet weighed).
struct Polygon {
  std::vector<int> vertices;
  std::vector<Vec3> side_normals;
  int size() const { return static_cast<int>(vertices.size()); }
};

class Triangulator {
 public:
  // `allowed`, where not null, holds the faces of the loop's tetrahedralization: the programme
  // takes as few other triangles as it can (the Delaunay restriction, which delaunay_restricted
  // applies only to polygons the programme solves whole).
  Triangulator(const Vertices& V, const Topology& topo, const HoleTriangulationOptions& options,
               const Forbidden& forbidden, const std::set<TriangleKey>* allowed)
      : V_(V), topo_(topo), options_(options), forbidden_(forbidden), allowed_(allowed) {}

  // Appends the triangles of `poly` to `out` (each as (v_k, v_j, v_i), reversing the loop order).
  void triangulate(const Polygon& poly, std::vector<Eigen::Vector3i>& out) {
    const auto repeat = repeated_positions(poly);
    if (repeat.first < 0 && poly.size() <= options_.max_dynamic_programming_size) return solve(poly, out);
    if (repeat.first < 0) {
      divided_ = true;
      return divide(poly, best_cut(poly), out);
    }
    const std::vector<std::pair<int, int>> cuts = bridge_cuts(poly, repeat.first, repeat.second);
    ++bridged_;
    if (bridged_ == 1 && options_.bridge_cuts_weighed > 1 && cuts.size() > 1)
      divide_along_lightest(poly, cuts, out);
    else
      divide(poly, cuts.front(), out);
  }

  // Divides `poly` along each of the first bridge_cuts_weighed `cuts` in turn, and keeps the
  // lightest triangulation (Liepa's weight against the faces outside the loop).
  void divide_along_lightest(const Polygon& poly, const std::vector<std::pair<int, int>>& cuts,
                             std::vector<Eigen::Vector3i>& out) {
    std::optional<Triangulator> best;
    std::vector<Eigen::Vector3i> best_faces;
    Weight best_weight{kInfinity, kInfinity, 0};
    const std::size_t tried = std::min(cuts.size(), static_cast<std::size_t>(options_.bridge_cuts_weighed));
    for (std::size_t c = 0; c < tried; ++c) {
      Triangulator trial = *this;
      std::vector<Eigen::Vector3i> faces;
      try {
        trial.divide(poly, cuts[c], faces);
      } catch (const InvalidMeshError&) {
        continue;  // no admissible triangulation of a piece: the next cut
      }
      const TriangulationWeight w = piece_weight(poly, faces);
      const Weight weight{w.max_dihedral_angle, w.area, 0};
      if (best && !lighter(weight, best_weight)) continue;
      best.emplace(std::move(trial));
      best_faces = std::move(faces);
      best_weight = weight;
    }
    if (!best) return divide(poly, cuts.front(), out);  // throws what the first cut throws
    made_ = std::move(best->made_);
    divided_ = best->divided_;
    out.insert(out.end(), best_faces.begin(), best_faces.end());
  }

  // Divides `poly` along the cut between positions a < b and triangulates both pieces.
  void divide(const Polygon& poly, std::pair<int, int> cut, std::vector<Eigen::Vector3i>& out) {
    const auto [a, b] = cut;
    // The cut is a side of both pieces; a piece may pass one of its ends again (a loop through a
    // vertex twice), so it is taken now, before either piece could choose it as a diagonal.
    made_.insert(undirected_key(poly.vertices[a], poly.vertices[b]));
    Polygon first, second;
    for (int t = a; t <= b; ++t) first.vertices.push_back(poly.vertices[t]);
    first.side_normals.assign(poly.side_normals.begin() + a, poly.side_normals.begin() + b);
    first.side_normals.push_back(Vec3::Zero());  // the cut b→a
    const std::size_t first_begin = out.size();
    triangulate(first, out);
    // The second piece runs b..a (wrapping); its closing side a→b is the cut, seen across from the
    // first piece's triangle on it.
    for (int t = b; t != a; t = (t + 1) % poly.size()) {
      second.vertices.push_back(poly.vertices[t]);
      second.side_normals.push_back(poly.side_normals[t]);
    }
    second.vertices.push_back(poly.vertices[a]);
    second.side_normals.push_back(normal_on_cut(out, first_begin, poly.vertices[a], poly.vertices[b]));
    triangulate(second, out);
  }

  bool divided() const { return divided_; }

 private:
  // A diagonal may not join a vertex to itself (a loop through a vertex twice), be a mesh edge, or
  // repeat a diagonal of an earlier piece (two pieces can share a vertex of such a loop): each would
  // give an edge more than two faces.
  bool admissible_diagonal(int u, int v) const {
    const std::uint64_t key = undirected_key(u, v);
    return u != v && !is_mesh_edge(topo_, u, v) && !made_.contains(key) && !forbidden_.diagonals.contains(key);
  }

  // Under the Delaunay restriction, whether a triangle is no face of the loop's tetrahedralization.
  bool outside_restriction(int a, int b, int c) const {
    return allowed_ != nullptr && !allowed_->contains(triangle_key(a, b, c));
  }

  // Positions s < t of the first vertex the polygon passes twice; (-1, -1) if none.
  static std::pair<int, int> repeated_positions(const Polygon& poly) {
    std::unordered_map<int, int> seen;
    for (int t = 0; t < poly.size(); ++t) {
      const auto [it, fresh] = seen.emplace(poly.vertices[t], t);
      if (!fresh) return {it->second, t};
    }
    return {-1, -1};
  }

  // A loop through a vertex twice (a pinch of the border, both occurrences on this hole) is cut by
  // a diagonal from between the occurrences s < t to outside them, so that each piece passes
  // through the vertex once and the dynamic programme never sees it twice. The admissible such
  // diagonals (positions lo < hi), best first: those that leave each end the loop passes more than
  // once into the hole at that pass (into_hole), then the others (a vertex's passes too bent to
  // tell), each by the ratio of its length to the shorter arc it cuts off, as in best_cut. A
  // diagonal drawn to the wrong pass divides the loop across a face hanging there, and no
  // triangulation of the pieces is then free of folds.
  std::vector<std::pair<int, int>> bridge_cuts(const Polygon& poly, int s, int t) const {
    const int m = poly.size();
    std::vector<double> arc(m + 1, 0.0);
    for (int q = 0; q < m; ++q)
      arc[q + 1] = arc[q] + (point(V_, poly.vertices[(q + 1) % m]) - point(V_, poly.vertices[q])).norm();
    std::unordered_map<int, int> passes;
    for (int v : poly.vertices) ++passes[v];
    const auto into_hole_at = [&](int from, int to) {
      return passes[poly.vertices[from]] < 2 || into_hole(poly, from, point(V_, poly.vertices[to]));
    };
    struct Candidate { bool fits; double ratio; std::pair<int, int> cut; };
    std::vector<Candidate> candidates;
    for (int a = s + 1; a < t; ++a)
      for (int b = 0; b < m; ++b) {
        if (b >= s && b <= t) continue;
        const int lo = std::min(a, b), hi = std::max(a, b);
        const int u = poly.vertices[lo], v = poly.vertices[hi];
        if (!admissible_diagonal(u, v)) continue;
        const double shorter_arc = std::min(arc[hi] - arc[lo], arc[m] - (arc[hi] - arc[lo]));
        const double ratio = (point(V_, u) - point(V_, v)).norm() / shorter_arc;
        candidates.push_back({into_hole_at(lo, hi) && into_hole_at(hi, lo), ratio, {lo, hi}});
      }
    if (candidates.empty())
      throw InvalidMeshError("triangulate_hole: no admissible diagonal separates the two passes of the loop "
                             "through vertex " + std::to_string(poly.vertices[s]));
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
      return x.fits != y.fits ? x.fits : x.ratio < y.ratio;
    });
    std::vector<std::pair<int, int>> cuts;
    for (const Candidate& c : candidates) cuts.push_back(c.cut);
    return cuts;
  }

  // Whether the direction from the loop's vertex at position t to point q lies within the angle the
  // loop turns through there on the hole's side: counter-clockwise about the surface's normal from
  // the side coming in to the side going out (the loop has the surface on its left). The normal is
  // that of the faces outside the two sides (the sum of the polygon's side normals there), or, at a
  // cut, the opposite of the loop's Newell normal.
  bool into_hole(const Polygon& poly, int t, const Vec3& q) const {
    const int m = poly.size();
    const Vec3 p = point(V_, poly.vertices[t]);
    Vec3 n = poly.side_normals[(t + m - 1) % m] + poly.side_normals[t];
    if (n.squaredNorm() < 1e-24) {
      n.setZero();
      for (int k = 0; k < m; ++k) n += point(V_, poly.vertices[k]).cross(point(V_, poly.vertices[(k + 1) % m]));
      n = -n;
    }
    const auto tangent = [&](const Vec3& d) { return Vec3(d - d.dot(n) / n.squaredNorm() * n); };
    const Vec3 in = tangent(point(V_, poly.vertices[(t + m - 1) % m]) - p);
    const Vec3 out = tangent(point(V_, poly.vertices[(t + 1) % m]) - p);
    const Vec3 to = tangent(q - p);
    const auto turn = [&](const Vec3& from, const Vec3& d) {  // counter-clockwise angle in [0, 2π)
      const double angle = std::atan2(n.normalized().dot(from.cross(d)), from.dot(d));
      return angle < 0 ? angle + 2 * std::numbers::pi : angle;
    };
    return turn(in, to) < turn(in, out);
  }

  // Positions (a, b), a < b, of the admissible diagonal with the smallest ratio of its length to
  // the shorter of the two loop arcs it cuts off, among those leaving at least a quarter of the
  // vertices on each side. On a round hole that is a diameter (fat halves, not slivers); on an
  // elongated one, the waist.
  std::pair<int, int> best_cut(const Polygon& poly) const {
    const int m = poly.size(), quarter = std::max(1, m / 4);
    std::vector<double> arc(m + 1, 0.0);  // loop length from vertex 0 to vertex t
    for (int t = 0; t < m; ++t)
      arc[t + 1] = arc[t] + (point(V_, poly.vertices[(t + 1) % m]) - point(V_, poly.vertices[t])).norm();
    double best = kInfinity;
    std::pair<int, int> cut{-1, -1};
    for (int a = 0; a < m; ++a)
      for (int b = a + quarter + 1; b < m && (m - (b - a)) > quarter; ++b) {
        const int u = poly.vertices[a], v = poly.vertices[b];
        const double shorter_arc = std::min(arc[b] - arc[a], arc[m] - (arc[b] - arc[a]));
        const double ratio = (point(V_, u) - point(V_, v)).norm() / shorter_arc;
        if (ratio < best && admissible_diagonal(u, v)) best = ratio, cut = {a, b};
      }
    if (cut.first < 0)
      throw InvalidMeshError("triangulate_hole: no admissible diagonal cuts a hole of " +
                             std::to_string(m) + " edges (every candidate is a mesh edge)");
    return cut;
  }

  // Normal of the triangle among out[begin..] that contains the directed edge a→b (the first
  // piece's triangle on the cut; the second piece's triangle there will contain b→a).
  Vec3 normal_on_cut(const std::vector<Eigen::Vector3i>& out, std::size_t begin, int a, int b) const {
    for (std::size_t f = begin; f < out.size(); ++f)
      for (int k = 0; k < 3; ++k)
        if (out[f][k] == a && out[f][(k + 1) % 3] == b)
          return triangle_normal(V_, out[f][0], out[f][1], out[f][2]);
    return Vec3::Zero();
  }

  // Liepa's dynamic programme on one polygon, from `start_vertices` starts evenly spaced round it.
  // The first start's triangulation is kept unless another's is lighter by the exact weight with
  // its largest angle raised by `start_margin` (HoleTriangulationOptions). A side with no face
  // outside (a cut not yet weighed, or a degenerate face across a loop edge) is left out of the
  // weight only as the closing side, where the first start has a cut: another start would weigh it
  // as π and could never win, so such a polygon is solved from its first start alone.
  void solve(const Polygon& poly, std::vector<Eigen::Vector3i>& out) {
    const bool unweighed_side = std::any_of(poly.side_normals.begin(), poly.side_normals.end(),
                                            [](const Vec3& n) { return n.isZero(); });
    const int m = poly.size(), starts = unweighed_side ? 1 : std::min(options_.start_vertices, m);
    std::vector<Eigen::Vector3i> best;
    Weight best_weight{kInfinity, kInfinity, kUnreached};
    for (int q = 0; q < starts; ++q) {
      const Polygon rotated = rotate(poly, static_cast<int>(static_cast<long long>(q) * m / starts));
      // A later start can only replace the best below this largest angle: candidates above it are
      // skipped, which prunes most of its programme. Not under the Delaunay restriction, where a
      // start with fewer triangles outside it wins whatever its angle.
      const double bound = q == 0 || allowed_ != nullptr ? kInfinity
                                                         : best_weight.angle - options_.start_margin + kAngleTie;
      std::vector<Eigen::Vector3i> faces = solve_from_start(rotated, bound);
      if (faces.empty()) continue;  // nothing below the bound
      const TriangulationWeight w = piece_weight(rotated, faces);
      const int outside = static_cast<int>(std::count_if(faces.begin(), faces.end(), [&](const Eigen::Vector3i& f) {
        return outside_restriction(f[0], f[1], f[2]);
      }));
      const Weight handicapped{w.max_dihedral_angle + (q > 0 ? options_.start_margin : 0.0), w.area, outside};
      if (best.empty() || lighter(handicapped, best_weight)) best = std::move(faces), best_weight = handicapped;
    }
    for (const Eigen::Vector3i& f : best) {
      out.push_back(f);
      for (int k = 0; k < 3; ++k)  // its diagonals (and sides, already mesh edges or cuts) are taken
        made_.insert(undirected_key(f[k], f[(k + 1) % 3]));
    }
  }

  // The polygon with vertex `r` first, its sides following their vertices.
  static Polygon rotate(const Polygon& poly, int r) {
    Polygon rotated;
    for (int t = 0; t < poly.size(); ++t) {
      rotated.vertices.push_back(poly.vertices[(r + t) % poly.size()]);
      rotated.side_normals.push_back(poly.side_normals[(r + t) % poly.size()]);
    }
    return rotated;
  }

  // The header's weight of `faces` triangulating `poly`, against the faces outside its sides.
  TriangulationWeight piece_weight(const Polygon& poly, const std::vector<Eigen::Vector3i>& faces) const {
    std::unordered_map<std::uint64_t, Vec3> outside;
    for (int t = 0; t < poly.size(); ++t)
      outside[edge_key(poly.vertices[t], poly.vertices[(t + 1) % poly.size()])] = poly.side_normals[t];
    Faces F(static_cast<Eigen::Index>(faces.size()), 3);
    for (std::size_t f = 0; f < faces.size(); ++f) F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
    return weigh(V_, F, outside);
  }

  // Liepa's dynamic programme from the polygon's first vertex: its triangles, each as
  // (v_k, v_j, v_i), reversing the loop order. Candidates whose largest angle exceeds `bound` are
  // not considered (their sub-polygons' weights are kept exact below it); none if none is left
  // below a finite bound.
  std::vector<Eigen::Vector3i> solve_from_start(const Polygon& poly, double bound) const {
    const int m = poly.size();
    std::vector<Weight> weight(static_cast<std::size_t>(m) * m);
    std::vector<int> apex(static_cast<std::size_t>(m) * m, -1);
    std::vector<Vec3> apex_normal(static_cast<std::size_t>(m) * m, Vec3::Zero());
    const auto at = [m](int i, int k) { return static_cast<std::size_t>(i) * m + k; };
    const auto vertex = [&](int i) { return poly.vertices[i]; };
    std::vector<Vec3> position(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) position[i] = point(V_, vertex(i));
    // New triangles list the loop positions i < j < k as (k, j, i): reversed loop order.
    const auto normal = [&](int i, int j, int k) { return triangle_normal(position[k], position[j], position[i]); };
    CachedSinCos at_limit, at_below;
    // Normal of the face across the side or diagonal (i, k) seen from inside [i, k].
    const auto inner_normal = [&](int i, int k) -> const Vec3& {
      return k == i + 1 ? poly.side_normals[i] : apex_normal[at(i, k)];
    };
    for (int span = 2; span < m; ++span)
      for (int i = 0; i + span < m; ++i) {
        const int k = i + span;
        const bool top = i == 0 && k == m - 1;
        Weight best{kInfinity, kInfinity, kUnreached};
        if (top || admissible_diagonal(vertex(i), vertex(k)))
          for (int j = i + 1; j < k; ++j) {
            const Weight& left = weight[at(i, j)];
            const Weight& right = weight[at(j, k)];
            if (left.outside == kUnreached || right.outside == kUnreached) continue;
            const int outside = left.outside + right.outside + outside_restriction(vertex(i), vertex(j), vertex(k));
            if (outside > best.outside) continue;
            // The sub-polygons' angles bound this candidate's from below: skip hopeless ones
            // before any trigonometry (this prunes most candidates).
            const double below = std::max(left.angle, right.angle);
            if (below > bound || (outside == best.outside && below > best.angle + kAngleTie)) continue;
            if (!forbidden_.triangles.empty() &&
                forbidden_.triangles.contains(triangle_key(vertex(i), vertex(j), vertex(k))))
              continue;
            const Vec3 n = normal(i, j, k);
            const bool closing = top && !poly.side_normals[m - 1].isZero();
            const std::array<Turn, 3> turns{turn_between(n, inner_normal(i, j)), turn_between(n, inner_normal(j, k)),
                                            closing ? turn_between(n, poly.side_normals[m - 1]) : Turn{}};
            const int count = closing ? 3 : 2;
            // Above `limit` the candidate is rejected (by `bound`, or as heavier than `best`): a turn
            // surely above it rejects the candidate before any arctangent. A turn surely below the
            // sub-polygons' largest angle cannot raise it: on a folded loop most candidates tie
            // there, and area decides. The angle is the same as from every arctangent.
            const double limit = outside == best.outside ? std::min(bound, best.angle + kAngleTie) : bound;
            if (limit < std::numbers::pi) {
              at_limit.set(limit);
              if (std::any_of(turns.begin(), turns.begin() + count,
                              [&](const Turn& t) { return sure_sign(t, at_limit.cos(), at_limit.sin()) > 0; }))
                continue;
            }
            double angle = below;
            if (below < std::numbers::pi) at_below.set(below);
            for (int t = 0; t < count; ++t)
              if (below >= std::numbers::pi || sure_sign(turns[t], at_below.cos(), at_below.sin()) >= 0)
                angle = std::max(angle, angle_of(turns[t]));
            if (angle > bound) continue;
            const Weight w{angle, left.area + right.area + 0.5 * n.norm(), outside};
            if (lighter(w, best)) best = w, apex[at(i, k)] = j;
          }
        weight[at(i, k)] = best;
        if (apex[at(i, k)] >= 0) apex_normal[at(i, k)] = normal(i, apex[at(i, k)], k);
      }
    if (apex[at(0, m - 1)] < 0 && bound < kInfinity) return {};
    if (apex[at(0, m - 1)] < 0)
      throw InvalidMeshError("triangulate_hole: no admissible triangulation of a hole of " +
                             std::to_string(m) + " edges (every candidate duplicates a mesh edge)");
    std::vector<Eigen::Vector3i> faces;
    std::vector<std::pair<int, int>> stack{{0, m - 1}};
    while (!stack.empty()) {
      const auto [i, k] = stack.back();
      stack.pop_back();
      if (k - i < 2) continue;
      const int j = apex[at(i, k)];
      faces.emplace_back(vertex(k), vertex(j), vertex(i));
      stack.emplace_back(i, j);
      stack.emplace_back(j, k);
    }
    return faces;
  }

  const Vertices& V_;
  const Topology& topo_;
  const HoleTriangulationOptions& options_;
  const Forbidden& forbidden_;  // what crossed the mesh in an earlier round
  const std::set<TriangleKey>* allowed_;  // the Delaunay restriction's triangles, or null
  bool divided_ = false;
  int bridged_ = 0;  // polygons divided between two passes through a vertex so far
  std::unordered_set<std::uint64_t> made_;  // diagonals of the pieces solved so far
};

// The mesh's faces followed by `faces`; `added` receives the indices of the latter.
Faces with_faces(const Faces& F, const std::vector<Eigen::Vector3i>& faces, std::vector<int>& added) {
  Faces all(F.rows() + static_cast<Eigen::Index>(faces.size()), 3);
  all.topRows(F.rows()) = F;
  added.clear();
  for (std::size_t f = 0; f < faces.size(); ++f) {
    added.push_back(static_cast<int>(F.rows() + static_cast<Eigen::Index>(f)));
    all.row(added.back()) = faces[f].transpose();
  }
  return all;
}

// Liepa's triangulation of `poly`, solved again with what crossed the mesh forbidden while it
// crosses (HoleTriangulationOptions::max_crossing_rounds); the round with the fewest crossings wins.
// Weights are left to the caller.
HoleTriangulation triangulate_avoiding_crossings(const Vertices& V, const Faces& F, const Topology& topo,
                                                 const Polygon& poly, const HoleTriangulationOptions& options,
                                                 const std::set<TriangleKey>* allowed) {
  HoleTriangulation result;
  Forbidden forbidden;
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  std::vector<int> added;
  // Rounds after the first are solved from the first start only: each costs a whole programme, and
  // a loop that crosses the mesh may take tens of them (docs/patch.md).
  HoleTriangulationOptions later = options;
  later.start_vertices = 1;
  for (int round = 0; round <= options.max_crossing_rounds; ++round) {
    Triangulator triangulator(V, topo, round == 0 ? options : later, forbidden, allowed);
    std::vector<Eigen::Vector3i> faces;
    try {
      triangulator.triangulate(poly, faces);
    } catch (const InvalidMeshError&) {
      if (round == 0) throw;
      break;  // what is forbidden leaves no triangulation: keep the best one found
    }
    const Faces all = with_faces(F, faces, added);
    const auto crossings = options.max_crossing_rounds > 0 ? find_face_intersections(V, all, added)
                                                           : std::vector<FaceIntersection>{};
    if (crossings.size() < fewest) {
      fewest = crossings.size();
      result.faces = all.bottomRows(static_cast<Eigen::Index>(faces.size()));
      result.divided = triangulator.divided();
      result.crossings = static_cast<int>(crossings.size());
    }
    if (crossings.empty()) break;
    for (const FaceIntersection& c : crossings) {
      forbid_crossing(V, topo, all, c.query_face, c.other_face, forbidden);
      if (c.other_face >= F.rows()) forbid_crossing(V, topo, all, c.other_face, c.query_face, forbidden);
    }
  }
  return result;
}

// The programme restricted to the faces of the loop's Delaunay tetrahedralization (CGAL's search),
// taking as few other triangles as it must. Not restricted (`delaunay` false, no faces) where the
// loop passes a vertex twice, is too large for the programme undivided, or spans no volume.
HoleTriangulation delaunay_restricted(const Vertices& V, const Faces& F, const Topology& topo, const Polygon& poly,
                                      const HoleTriangulationOptions& options) {
  if (!delaunay_restriction_applies(poly.vertices, options)) return {};
  const std::set<TriangleKey> allowed = detail::delaunay_triangles(V, poly.vertices);
  if (allowed.empty()) return {};
  try {
    HoleTriangulation result = triangulate_avoiding_crossings(V, F, topo, poly, options, &allowed);
    result.delaunay = true;
    for (Eigen::Index f = 0; f < result.faces.rows(); ++f) {
      const TriangleKey key = triangle_key(result.faces(f, 0), result.faces(f, 1), result.faces(f, 2));
      result.outside_delaunay += !allowed.contains(key);
    }
    return result;
  } catch (const InvalidMeshError&) {
    return {};
  }
}

}  // namespace

HoleTriangulation triangulate_hole(const Vertices& V, const Faces& F, const Topology& topo,
                                   std::span<const int> loop, const HoleTriangulationOptions& options) {
  if (options.max_dynamic_programming_size < 3)
    throw InvalidArgument("triangulate_hole: max_dynamic_programming_size must be at least 3, got " +
                          std::to_string(options.max_dynamic_programming_size));
  if (options.start_vertices < 1)
    throw InvalidArgument("triangulate_hole: start_vertices must be at least 1, got " +
                          std::to_string(options.start_vertices));
  if (options.bridge_cuts_weighed < 1)
    throw InvalidArgument("triangulate_hole: bridge_cuts_weighed must be at least 1, got " +
                          std::to_string(options.bridge_cuts_weighed));
  if (!(options.start_margin >= 0))
    throw InvalidArgument("triangulate_hole: start_margin must be at least 0, got " +
                          std::to_string(options.start_margin));
  if (options.max_crossing_rounds < 0)
    throw InvalidArgument("triangulate_hole: max_crossing_rounds must be at least 0, got " +
                          std::to_string(options.max_crossing_rounds));
  if (V.rows() != topo.num_vertices)
    throw InvalidArgument("triangulate_hole: the topology is of another mesh");
  const std::vector<int> across = detail::loop_edge_faces(F, topo, loop, "triangulate_hole");
  const int n = static_cast<int>(loop.size());
  Polygon poly;
  poly.vertices.assign(loop.begin(), loop.end());
  std::unordered_map<std::uint64_t, Vec3> outside;
  for (int t = 0; t < n; ++t) {
    const int f = across[t];
    poly.side_normals.push_back(triangle_normal(V, F(f, 0), F(f, 1), F(f, 2)));
    outside[edge_key(loop[t], loop[(t + 1) % n])] = poly.side_normals.back();
  }

  HoleTriangulation result = options.delaunay_restricted ? delaunay_restricted(V, F, topo, poly, options)
                                                        : HoleTriangulation{};
  if (!result.delaunay) result = triangulate_avoiding_crossings(V, F, topo, poly, options, nullptr);
  const TriangulationWeight w = weigh(V, result.faces, outside);
  result.max_dihedral_angle = w.max_dihedral_angle;
  result.area = w.area;
  return result;
}

bool passes_a_vertex_twice(std::span<const int> loop) {
  return std::set<int>(loop.begin(), loop.end()).size() < loop.size();
}

bool delaunay_restriction_applies(std::span<const int> loop, const HoleTriangulationOptions& options) {
  return !passes_a_vertex_twice(loop) && static_cast<int>(loop.size()) <= options.max_dynamic_programming_size;
}

TriangulationWeight triangulation_weight(const Vertices& V, const Faces& F, const Faces& faces) {
  std::unordered_map<std::uint64_t, Vec3> outside;
  for (int f = 0; f < F.rows(); ++f) {
    const Vec3 n = triangle_normal(V, F(f, 0), F(f, 1), F(f, 2));
    for (int k = 0; k < 3; ++k) outside[edge_key(F(f, k), F(f, (k + 1) % 3))] = n;
  }
  return weigh(V, faces, outside);
}

}  // namespace fairsurf
