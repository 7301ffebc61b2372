#include <fairsurf/mesh/errors.h>
#include <fairsurf/patch/tube.h>

#include "loop_faces.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace fairsurf {
namespace {

using Vec3 = Eigen::Vector3d;

// A loop as a closed polyline with its outward directions, parametrized by normalized arc length.
struct ParametrizedLoop {
  std::vector<int> vertices;
  std::vector<Vec3> points, outward;
  std::vector<double> s;  // #points + 1 cumulative normalized arc lengths, s[0] = 0, s[n] = 1
  double mean_edge = 0.0;

  int size() const { return static_cast<int>(points.size()); }

  // Point and outward direction at parameter u ∈ [0, 1), linearly interpolated along the edges.
  std::pair<Vec3, Vec3> at(double u) const {
    u -= std::floor(u);
    const int t = std::clamp(static_cast<int>(std::upper_bound(s.begin(), s.end(), u) - s.begin()) - 1,
                             0, size() - 1);
    const double w = s[t + 1] > s[t] ? (u - s[t]) / (s[t + 1] - s[t]) : 0.0;
    const int next = (t + 1) % size();
    return {(1 - w) * points[t] + w * points[next], ((1 - w) * outward[t] + w * outward[next]).normalized()};
  }

  // The same loop started at position `start`.
  ParametrizedLoop rotated(int start) const {
    ParametrizedLoop r;
    const int n = size();
    for (int t = 0; t < n; ++t) {
      const int k = (start + t) % n;
      r.vertices.push_back(vertices[k]);
      r.points.push_back(points[k]);
      r.outward.push_back(outward[k]);
    }
    r.parametrize();
    return r;
  }

  void parametrize() {
    const int n = size();
    s.assign(n + 1, 0.0);
    for (int t = 0; t < n; ++t) s[t + 1] = s[t] + (points[(t + 1) % n] - points[t]).norm();
    mean_edge = s[n] / n;
    for (double& x : s) x /= s[n];
  }
};

// Points and outward directions of `loop`, listed in reverse if `reverse`.
ParametrizedLoop parametrize(const Vertices& V, const Faces& F, const Topology& topo,
                             std::span<const int> loop, bool reverse) {
  const std::vector<int> faces = detail::loop_edge_faces(F, topo, loop, "build_tube");
  const int n = static_cast<int>(loop.size());
  std::vector<Vec3> edge_outward(n);
  for (int t = 0; t < n; ++t) {
    const int f = faces[t];
    const Vec3 a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Vec3 edge = V.row(loop[(t + 1) % n]) - V.row(loop[t]);
    edge_outward[t] = edge.cross((b - a).cross(c - a)).normalized();
  }
  ParametrizedLoop p;
  for (int t = 0; t < n; ++t) {
    const int k = reverse ? n - 1 - t : t;
    p.vertices.push_back(loop[k]);
    p.points.push_back(V.row(loop[k]).transpose());
    p.outward.push_back((edge_outward[k] + edge_outward[(k + n - 1) % n]).normalized());
  }
  p.parametrize();
  return p;
}

double alignment_cost(const ParametrizedLoop& a, const ParametrizedLoop& b, int samples) {
  double cost = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double u = static_cast<double>(k) / samples;
    cost += (a.at(u).first - b.at(u).first).squaredNorm();
  }
  return cost / samples;
}

// Triangles joining ring p to ring q (both listed from their starts in the same direction), p
// being on the side of loop A: each step adds the triangle with the shorter new diagonal, unless
// that diagonal was drawn before. The diagonal (i, j) is (i mod #p, j mod #q), so it repeats when
// one ring wraps round to its start at a point the other ring had reached while the first stood at
// its start: then two strips of the annulus meet at that edge (a ring twisted against the other, as
// between 3-vertex loops, 4 faces at one edge). The other ring advances instead.
void zip(const std::vector<int>& p, const std::vector<int>& q, const Vertices& V,
         std::vector<Eigen::Vector3i>& out) {
  const int np = static_cast<int>(p.size()), nq = static_cast<int>(q.size());
  int i = 0, j = 0;
  int i_while_j_at_start = 0, j_while_i_at_start = 0;
  while (i < np || j < nq) {
    const int pi = p[i % np], pn = p[(i + 1) % np], qj = q[j % nq], qn = q[(j + 1) % nq];
    bool advance_p =
        j == nq || (i < np && (V.row(pn) - V.row(qj)).squaredNorm() <= (V.row(pi) - V.row(qn)).squaredNorm());
    if (advance_p && i + 1 == np && j < nq && j <= j_while_i_at_start) advance_p = false;
    else if (!advance_p && j + 1 == nq && i < np && i <= i_while_j_at_start) advance_p = true;
    if (advance_p) {
      out.emplace_back(pn, pi, qj);  // contains pn→pi: reversed against loop A's edge pi→pn
      ++i;
    } else {
      out.emplace_back(qj, qn, pi);
      ++j;
    }
    if (j == 0) i_while_j_at_start = i;
    if (i == 0) j_while_i_at_start = j;
  }
}

// Tangent length over chord length of the cubic Hermite that approximates a circular arc of angle
// φ (4R·tan(φ/4) over 2R·sin(φ/2)): 1 for a straight line, 2 for a half circle, 6.83 for 3π/2.
// The arc's angle is the sum of the angles the end directions make with the chord (each φ/2 on a
// circle); it is capped at 3π/2, beyond which the factor grows without bound.
double arc_tangent_factor(const Vec3& chord, const Vec3& start_direction, const Vec3& end_direction) {
  constexpr double kMaxArc = 1.5 * std::numbers::pi;
  const double length = chord.norm();
  if (length == 0.0) return 1.0;
  const Vec3 u = chord / length;
  const auto angle = [&u](const Vec3& d) { return std::acos(std::clamp(d.dot(u), -1.0, 1.0)); };
  const double phi = std::min(angle(start_direction) + angle(end_direction), kMaxArc);
  return phi < 1e-6 ? 1.0 : 2.0 * std::tan(phi / 4) / std::sin(phi / 2);
}

Vec3 hermite(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * t0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * t1;
}

}  // namespace

Tube build_tube(const Vertices& V, const Faces& F, const Topology& topo, std::span<const int> loop_a,
                std::span<const int> loop_b, const TubeOptions& options) {
  if (V.rows() != topo.num_vertices) throw InvalidArgument("build_tube: the topology is of another mesh");
  const ParametrizedLoop a = parametrize(V, F, topo, loop_a, false);
  const ParametrizedLoop b_reversed = parametrize(V, F, topo, loop_b, true);
  for (int v : loop_a)
    if (std::find(loop_b.begin(), loop_b.end(), v) != loop_b.end())
      throw InvalidArgument("build_tube: the loops share vertex " + std::to_string(v));

  Tube tube;
  const int samples = std::max(a.size(), b_reversed.size());
  double best = std::numeric_limits<double>::infinity();
  for (int start = 0; start < b_reversed.size(); ++start) {
    const double cost = alignment_cost(a, b_reversed.rotated(start), samples);
    if (cost < best) best = cost, tube.start_b = start;
  }
  tube.mean_squared_distance = best;
  const ParametrizedLoop b = b_reversed.rotated(tube.start_b);
  // Position in the caller's loop B of the vertex now first.
  tube.start_b = static_cast<int>(std::find(loop_b.begin(), loop_b.end(), b.vertices[0]) - loop_b.begin());

  double gap = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double u = static_cast<double>(k) / samples;
    gap += (a.at(u).first - b.at(u).first).norm() / samples;
  }
  const double h = 0.5 * (a.mean_edge + b.mean_edge);
  tube.rings = options.rings >= 0 ? options.rings : std::max(0, static_cast<int>(std::lround(gap / h)) - 1);

  std::vector<Vec3> new_points;
  std::vector<std::vector<int>> rings{a.vertices};
  for (int r = 1; r <= tube.rings; ++r) {
    const double t = static_cast<double>(r) / (tube.rings + 1);
    const int count = std::max(3, static_cast<int>(std::lround(a.size() + (b.size() - a.size()) * t)));
    std::vector<int> ring;
    for (int k = 0; k < count; ++k) {
      const double u = static_cast<double>(k) / count;
      const auto [pa, da] = a.at(u);
      const auto [pb, db] = b.at(u);
      const double length =
          options.tangent_scale * arc_tangent_factor(pb - pa, da, -db) * (pb - pa).norm();
      ring.push_back(static_cast<int>(V.rows() + new_points.size()));
      new_points.push_back(options.hermite ? hermite(pa, length * da, pb, -length * db, t)
                                           : ((1 - t) * pa + t * pb).eval());
    }
    rings.push_back(std::move(ring));
  }
  rings.push_back(b.vertices);

  tube.V.resize(V.rows() + static_cast<int>(new_points.size()), 3);
  tube.V.topRows(V.rows()) = V;
  for (std::size_t k = 0; k < new_points.size(); ++k) {
    tube.V.row(V.rows() + static_cast<int>(k)) = new_points[k].transpose();
    tube.ring_vertices.push_back(static_cast<int>(V.rows() + k));
  }
  std::vector<Eigen::Vector3i> faces;
  for (std::size_t r = 0; r + 1 < rings.size(); ++r) zip(rings[r], rings[r + 1], tube.V, faces);
  tube.faces.resize(static_cast<int>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) tube.faces.row(static_cast<int>(f)) = faces[f].transpose();
  return tube;
}

LoopPair closest_loop_pair(const Vertices& V, const std::vector<std::vector<int>>& loops) {
  if (loops.size() < 2)
    throw InvalidArgument("closest_loop_pair: need at least two loops, got " + std::to_string(loops.size()));
  for (const auto& loop : loops)
    for (int v : loop)
      if (v < 0 || v >= V.rows())
        throw InvalidArgument("closest_loop_pair: loop vertex " + std::to_string(v) + " is out of range");
  // Mean over `from` of the distance to the nearest vertex of `to`.
  const auto mean_nearest = [&V](const std::vector<int>& from, const std::vector<int>& to) {
    double sum = 0.0;
    for (int u : from) {
      double nearest = std::numeric_limits<double>::infinity();
      for (int w : to) nearest = std::min(nearest, (V.row(u) - V.row(w)).squaredNorm());
      sum += std::sqrt(nearest);
    }
    return sum / std::max<std::size_t>(1, from.size());
  };
  LoopPair best{-1, -1, std::numeric_limits<double>::infinity()};
  for (int i = 0; i < static_cast<int>(loops.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(loops.size()); ++j) {
      const double d = 0.5 * (mean_nearest(loops[i], loops[j]) + mean_nearest(loops[j], loops[i]));
      if (d < best.distance) best = {i, j, d};
    }
  return best;
}

}  // namespace fairsurf
