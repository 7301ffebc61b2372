// Tests of the patch stage: Liepa hole triangulation, refinement, membrane relaxation, tubes.
#include <fairsurf/applications/repair.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/hole_triangulation.h>
#include <fairsurf/patch/membrane.h>
#include <fairsurf/patch/patch.h>
#include <fairsurf/patch/patch_refinement.h>
#include <fairsurf/patch/tube.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <set>

#include "analytic_meshes.h"
#include "hole_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

using Vec3 = Eigen::Vector3d;

// The mesh without the faces for which `drop(face)` holds; the vertex array is kept whole.
Mesh without_faces(const Mesh& in, const std::function<bool(int)>& drop) {
  Mesh out;
  out.V = in.V;
  std::vector<int> kept;
  for (int f = 0; f < in.num_faces(); ++f)
    if (!drop(f)) kept.push_back(f);
  out.F.resize(static_cast<int>(kept.size()), 3);
  for (int k = 0; k < static_cast<int>(kept.size()); ++k) out.F.row(k) = in.F.row(kept[k]);
  return out;
}

// Faces with a vertex whose position satisfies `inside`, removed.
Mesh cut(const Mesh& in, const std::function<bool(const Vec3&)>& inside) {
  return without_faces(in, [&](int f) {
    for (int k = 0; k < 3; ++k)
      if (inside(in.V.row(in.F(f, k)).transpose())) return true;
    return false;
  });
}

// What the stage guarantees about its output surface, counted independently of the library.
struct SurfaceCheck {
  int border_edges = 0;        // edges with one face
  int non_manifold_edges = 0;  // edges with more than two faces
  int repeated_directed = 0;   // directed edges used twice: inconsistent orientation
  int non_manifold_vertices = 0;  // interior vertices whose faces form more than one fan
  int degenerate_faces = 0;    // area below 1e-10 times the longest edge squared
  double min_angle_degrees = 180.0;
};

SurfaceCheck check_surface(const Mesh& m) {
  SurfaceCheck c;
  std::map<std::pair<int, int>, int> directed, undirected;
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
      ++directed[{a, b}];
      ++undirected[std::minmax(a, b)];
    }
  for (const auto& [e, n] : directed) c.repeated_directed += n > 1;
  for (const auto& [e, n] : undirected) c.border_edges += n == 1, c.non_manifold_edges += n > 2;
  // Fans: around v, face (v, a, b) links a to b; an interior vertex's links form a single cycle.
  std::vector<std::map<int, int>> link(m.num_vertices());
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) link[m.F(f, k)][m.F(f, (k + 1) % 3)] = m.F(f, (k + 2) % 3);
  for (int v = 0; v < m.num_vertices(); ++v) {
    if (link[v].empty()) continue;
    int steps = 0, at = link[v].begin()->first;
    do {
      const auto it = link[v].find(at);
      if (it == link[v].end()) break;
      at = it->second;
      ++steps;
    } while (at != link[v].begin()->first);
    const bool closed = at == link[v].begin()->first;
    if (closed && steps != static_cast<int>(link[v].size())) ++c.non_manifold_vertices;
  }
  for (int f = 0; f < m.num_faces(); ++f) {
    const Vec3 p[3] = {m.V.row(m.F(f, 0)), m.V.row(m.F(f, 1)), m.V.row(m.F(f, 2))};
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
      longest = std::max(longest, u.squaredNorm());
      c.min_angle_degrees =
          std::min(c.min_angle_degrees, std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / std::numbers::pi);
    }
    c.degenerate_faces += (p[1] - p[0]).cross(p[2] - p[0]).norm() < 1e-10 * longest;
  }
  return c;
}

void expect_closed_manifold(const Mesh& m, int border_edges = 0) {
  const SurfaceCheck c = check_surface(m);
  EXPECT_EQ(c.border_edges, border_edges);
  EXPECT_EQ(c.non_manifold_edges, 0);
  EXPECT_EQ(c.repeated_directed, 0);
  EXPECT_EQ(c.non_manifold_vertices, 0);
  EXPECT_EQ(c.degenerate_faces, 0);
}

void expect_input_kept(const Mesh& input, const Mesh& output) {
  ASSERT_GE(output.num_vertices(), input.num_vertices());
  ASSERT_GE(output.num_faces(), input.num_faces());
  EXPECT_TRUE(output.V.topRows(input.num_vertices()) == input.V);  // bit-exact, same order
  EXPECT_TRUE(output.F.topRows(input.num_faces()) == input.F);
}

struct EdgeLengths {
  double mean_border = 0.0;  // loop edges of the holes
  double mean_patch = 0.0;   // patch edges not on a loop
};

EdgeLengths edge_lengths(const Mesh& input, const std::vector<std::vector<int>>& loops, const InitialPatch& p) {
  EdgeLengths e;
  std::set<std::pair<int, int>> border;
  int nb = 0;
  for (const auto& loop : loops)
    for (std::size_t t = 0; t < loop.size(); ++t) {
      const int a = loop[t], b = loop[(t + 1) % loop.size()];
      border.insert(std::minmax(a, b));
      e.mean_border += (input.V.row(a) - input.V.row(b)).norm();
      ++nb;
    }
  e.mean_border /= nb;
  std::set<std::pair<int, int>> seen;
  for (int f = p.first_patch_face; f < p.mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto key = std::minmax(p.mesh.F(f, k), p.mesh.F(f, (k + 1) % 3));
      if (!border.count(key) && seen.insert(key).second)
        e.mean_patch += (p.mesh.V.row(key.first) - p.mesh.V.row(key.second)).norm();
    }
  e.mean_patch /= static_cast<double>(seen.size());
  return e;
}

// The annulus of hole_meshes.h round a gently waved polygon; the hole is the inner loop.
Mesh irregular_annulus(int n, unsigned seed, double waviness) { return test::wavy_annulus(n, seed, waviness); }

// The loop of a holed grid that is not the grid's outer border (vertex 0 is a grid corner).
std::vector<int> grid_hole(const Mesh& m) {
  const Topology topo = build_topology(m.F, m.num_vertices());
  for (auto& loop : boundary_loops(m.F, topo))
    if (std::find(loop.begin(), loop.end(), 0) == loop.end()) return loop;
  return {};
}

std::vector<int> inner_loop(const Mesh& m) {
  const Topology topo = build_topology(m.F, m.num_vertices());
  for (auto& loop : boundary_loops(m.F, topo))
    if (loop.front() == 0) return loop;
  return {};
}

// Every triangulation of the polygon `loop`, each triangle as (v_k, v_j, v_i) (Liepa's order).
std::vector<std::vector<Eigen::Vector3i>> all_triangulations(const std::vector<int>& loop) {
  const int n = static_cast<int>(loop.size());
  std::map<std::pair<int, int>, std::vector<std::vector<Eigen::Vector3i>>> memo;
  std::function<const std::vector<std::vector<Eigen::Vector3i>>&(int, int)> all = [&](int i, int k)
      -> const std::vector<std::vector<Eigen::Vector3i>>& {
    auto& out = memo[{i, k}];
    if (!out.empty() || k - i < 2) {
      if (out.empty()) out.push_back({});
      return out;
    }
    for (int j = i + 1; j < k; ++j)
      for (const auto& left : all(i, j))
        for (const auto& right : all(j, k)) {
          auto t = left;
          t.insert(t.end(), right.begin(), right.end());
          t.emplace_back(loop[k], loop[j], loop[i]);
          out.push_back(std::move(t));
        }
    return out;
  };
  return all(0, n - 1);
}

// Brute force: the lightest of all triangulations of the polygon `loop` (Liepa's order), weighed
// directly on each complete triangulation.
TriangulationWeight brute_force_minimum(const Mesh& m, const std::vector<int>& loop) {
  TriangulationWeight best{std::numbers::pi * 10, 0.0};
  for (const auto& t : all_triangulations(loop)) {
    Faces faces(static_cast<int>(t.size()), 3);
    for (int f = 0; f < faces.rows(); ++f) faces.row(f) = t[f].transpose();
    const TriangulationWeight w = triangulation_weight(m.V, m.F, faces);
    if (w.max_dihedral_angle < best.max_dihedral_angle - kAngleTie ||
        (w.max_dihedral_angle <= best.max_dihedral_angle + kAngleTie && w.area < best.area))
      best = w;
  }
  return best;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Hole triangulation

TEST(HoleTriangulation, PlanarConvexHoleIsFlatAndCoversTheHoleExactly) {
  const Mesh grid = test::regular_grid(12, 12);
  // The faces around the 3x3 vertices (i, j in 5..7) removed: a convex hexagonal hole with collinear
  // vertices along its sides, where degenerate triangles must be avoided.
  const Mesh holed = cut(grid, [](const Vec3& p) { return p.x() > 4.5 && p.x() < 7.5 && p.y() > 4.5 && p.y() < 7.5; });
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  const auto hole = grid_hole(holed);
  ASSERT_EQ(hole.size(), 14u);
  const HoleTriangulation t = triangulate_hole(holed.V, holed.F, topo, hole);
  EXPECT_EQ(t.faces.rows(), 12);
  EXPECT_LT(t.max_dihedral_angle, 1e-12);
  EXPECT_NEAR(t.area, 0.5 * (grid.num_faces() - holed.num_faces()), 1e-12);  // unit cells
  EXPECT_FALSE(t.divided);
  Mesh filled = holed;
  filled.F.conservativeResize(holed.num_faces() + t.faces.rows(), 3);
  filled.F.bottomRows(t.faces.rows()) = t.faces;
  const SurfaceCheck c = check_surface(filled);
  EXPECT_EQ(c.border_edges, 48);  // the grid's outer border only
  EXPECT_EQ(c.repeated_directed, 0);  // the new faces are oriented like the grid
  EXPECT_EQ(c.non_manifold_edges, 0);
  EXPECT_EQ(c.degenerate_faces, 0);
  // Every new face's normal points to +z like the grid's.
  for (int f = 0; f < t.faces.rows(); ++f) {
    const Vec3 a = holed.V.row(t.faces(f, 0)), b = holed.V.row(t.faces(f, 1)), cc = holed.V.row(t.faces(f, 2));
    EXPECT_GT((b - a).cross(cc - a).z(), 0.0);
  }
}

TEST(HoleTriangulation, MatchesBruteForceOnSmallIrregularHoles) {
  // Exhaustive search over all Catalan(n-2) triangulations (132 for n = 8). Liepa's programme is
  // exact for quadrilaterals; beyond, it weighs the dihedral across a diagonal with the inner side
  // already fixed, so it may miss the optimum by a little (docs/patch.md): measured here.
  int cases = 0, exact = 0;
  double worst_gap = 0.0;
  for (const int n : {4, 5, 6, 7, 8})
    for (unsigned seed = 1; seed <= 8; ++seed) {
      const Mesh m = irregular_annulus(n, seed, 0.4);
      const auto loop = inner_loop(m);
      ASSERT_EQ(static_cast<int>(loop.size()), n);
      const Topology topo = build_topology(m.F, m.num_vertices());
      const HoleTriangulation t = triangulate_hole(m.V, m.F, topo, loop);
      const TriangulationWeight got = triangulation_weight(m.V, m.F, t.faces);
      EXPECT_NEAR(got.max_dihedral_angle, t.max_dihedral_angle, 1e-12);
      EXPECT_NEAR(got.area, t.area, 1e-12);
      const TriangulationWeight best = brute_force_minimum(m, loop);
      EXPECT_GE(t.max_dihedral_angle, best.max_dihedral_angle - kAngleTie);  // nothing beats the optimum
      const bool same = std::abs(t.max_dihedral_angle - best.max_dihedral_angle) <= kAngleTie &&
                        std::abs(t.area - best.area) <= 1e-12;
      if (n == 4) {
        EXPECT_TRUE(same) << "seed " << seed;
      }
      exact += same;
      worst_gap = std::max(worst_gap, t.max_dihedral_angle - best.max_dihedral_angle);
      ++cases;
    }
  EXPECT_EQ(cases, 40);
  // Measured: 34 of 40 optimal, the others within 0.12 rad of the optimal largest angle.
  EXPECT_GE(exact, 30);
  EXPECT_LT(worst_gap, 0.2);
}

TEST(HoleTriangulation, MoreStartsNeverWeighMoreAndTheFirstStartIsKeptWithinTheMargin) {
  // The programme's largest angle depends on where the loop starts (header). Every start of these
  // small holes tried and the lightest kept (no margin), the result is never heavier than the first
  // start's and more often optimal; with the default margin another start replaces the first only
  // where its largest angle is smaller by more than the margin.
  int exact_first = 0, exact_every = 0, replaced = 0;
  for (const int n : {5, 6, 7, 8})
    for (unsigned seed = 1; seed <= 8; ++seed) {
      const Mesh m = irregular_annulus(n, seed, 0.4);
      const auto loop = inner_loop(m);
      const Topology topo = build_topology(m.F, m.num_vertices());
      const HoleTriangulation first = triangulate_hole(m.V, m.F, topo, loop, {.start_vertices = 1});
      const HoleTriangulation every =
          triangulate_hole(m.V, m.F, topo, loop, {.start_vertices = n, .start_margin = 0.0});
      const HoleTriangulation by_default = triangulate_hole(m.V, m.F, topo, loop, {.start_vertices = n});
      const TriangulationWeight best = brute_force_minimum(m, loop);
      const auto optimal = [&](const HoleTriangulation& t) {
        return std::abs(t.max_dihedral_angle - best.max_dihedral_angle) <= kAngleTie &&
               std::abs(t.area - best.area) <= 1e-12;
      };
      EXPECT_LE(every.max_dihedral_angle, first.max_dihedral_angle + kAngleTie) << n << " " << seed;
      exact_first += optimal(first);
      exact_every += optimal(every);
      if (by_default.faces != first.faces) {
        ++replaced;
        EXPECT_LT(by_default.max_dihedral_angle, first.max_dihedral_angle - HoleTriangulationOptions{}.start_margin);
      }
    }
  EXPECT_GT(exact_every, exact_first);
  std::printf("optimal of 32: first start %d, every start %d; replaced beyond the margin: %d\n", exact_first,
              exact_every, replaced);
}

TEST(HoleTriangulation, DividesLargeHolesAndStaysFlatOnAPlane) {
  // The faces around 59x59 vertices removed: a hexagonal hole of 238 loop edges, above the default
  // threshold of 200.
  const Mesh grid = test::regular_grid(64, 64);
  const Mesh holed = cut(grid, [](const Vec3& p) { return p.x() > 2.5 && p.x() < 61.5 && p.y() > 2.5 && p.y() < 61.5; });
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  const auto hole = grid_hole(holed);
  ASSERT_EQ(hole.size(), 238u);
  const HoleTriangulation t = triangulate_hole(holed.V, holed.F, topo, hole);
  EXPECT_TRUE(t.divided);
  EXPECT_EQ(t.faces.rows(), 236);
  EXPECT_LT(t.max_dihedral_angle, 1e-12);
  EXPECT_NEAR(t.area, 0.5 * (grid.num_faces() - holed.num_faces()), 1e-9);
  Mesh filled = holed;
  filled.F.conservativeResize(holed.num_faces() + t.faces.rows(), 3);
  filled.F.bottomRows(t.faces.rows()) = t.faces;
  expect_closed_manifold(filled, 256);
}

TEST(HoleTriangulation, DividedAndWholeAgreeInQualityOnACurvedHole) {
  // A cap of a sphere (150 loop edges): cut in pieces of at most 64, the triangulation is a valid
  // fill whose largest dihedral angle stays close to Liepa's on the whole hole (0.92 against 0.77).
  const Mesh sphere = test::icosphere(5);
  const Mesh holed = cut(sphere, [](const Vec3& p) { return p.z() > 0.6; });
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  const auto loops = boundary_loops(holed.F, topo);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), 150u);
  const HoleTriangulation whole = triangulate_hole(holed.V, holed.F, topo, loops[0]);
  const HoleTriangulation divided =
      triangulate_hole(holed.V, holed.F, topo, loops[0], {.max_dynamic_programming_size = 64});
  EXPECT_FALSE(whole.divided);
  EXPECT_TRUE(divided.divided);
  EXPECT_LE(whole.max_dihedral_angle, divided.max_dihedral_angle + kAngleTie);
  EXPECT_LT(divided.max_dihedral_angle, 1.5 * whole.max_dihedral_angle);
  EXPECT_LT(std::abs(divided.area / whole.area - 1.0), 0.01);
  for (const auto* t : {&whole, &divided}) {
    Mesh filled = holed;
    filled.F.conservativeResize(holed.num_faces() + t->faces.rows(), 3);
    filled.F.bottomRows(t->faces.rows()) = t->faces;
    expect_closed_manifold(filled);
  }
}

TEST(HoleTriangulation, RejectsBadLoopsWithPreciseMessages) {
  const Mesh m = irregular_annulus(6, 1, 0.2);
  const Topology topo = build_topology(m.F, m.num_vertices());
  auto loop = inner_loop(m);
  const auto message = [&](const std::vector<int>& l, HoleTriangulationOptions o = {}) {
    try {
      triangulate_hole(m.V, m.F, topo, l, o);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(message({0, 1}), "triangulate_hole: a loop needs at least 3 vertices, got 2");
  EXPECT_EQ(message({0, 1, 99}), "triangulate_hole: loop vertex 99 is out of range [0, 12)");
  std::vector<int> reversed(loop.rbegin(), loop.rend());
  EXPECT_EQ(message(reversed).rfind("triangulate_hole: loop edge ", 0), 0u);
  EXPECT_NE(message(reversed).find("is not a border edge with the surface on its left"), std::string::npos);
  EXPECT_EQ(message(loop, {.max_dynamic_programming_size = 2}),
            "triangulate_hole: max_dynamic_programming_size must be at least 3, got 2");
  EXPECT_EQ(message(loop, {.start_vertices = 0}), "triangulate_hole: start_vertices must be at least 1, got 0");
  EXPECT_EQ(message(loop, {.start_margin = -0.5}).rfind("triangulate_hole: start_margin must be at least 0, got -0.5", 0),
            0u);
  EXPECT_EQ(message(loop, {.max_crossing_rounds = -1}),
            "triangulate_hole: max_crossing_rounds must be at least 0, got -1");
  EXPECT_EQ(message(loop, {.bridge_cuts_weighed = 0}),
            "triangulate_hole: bridge_cuts_weighed must be at least 1, got 0");
}

// A square hole (8 by 8 grid, the faces at its middle 3 by 3 vertices cut out, z = 0.1 x y for some
// curvature: a 14-edge loop) with a lone
// triangle of its own vertices hanging at each of two border vertices, pointing inwards, as a cut
// through a thin part leaves them; the loop fill_holes patches them with runs through each of the
// two vertices twice. Weighing several cuts between the first vertex's passes keeps the lightest,
// never heavier than the first cut alone, and the patch stays manifold: every edge has one face on
// each side, the loop's with the mesh.
TEST(HoleTriangulation, WeighingCutsBetweenAPinchsPassesNeverGivesAHeavierPatch) {
  Mesh grid = test::regular_grid(8, 8, 1.0);
  for (int v = 0; v < grid.num_vertices(); ++v) grid.V(v, 2) = 0.1 * grid.V(v, 0) * grid.V(v, 1);
  const Mesh holed = cut(grid, [](const Vec3& p) { return p.x() > 2.5 && p.x() < 5.5 && p.y() > 2.5 && p.y() < 5.5; });
  const auto square = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  ASSERT_EQ(square.size(), 2u);
  const std::vector<int> hole = square[0].size() < square[1].size() ? square[0] : square[1];  // not the outer border
  const Vec3 centre(4, 4, 1.6);
  int lighter = 0;
  for (std::size_t i = 0; i < hole.size(); ++i)
    for (std::size_t j = i + 1; j < hole.size(); ++j) {
      Mesh m = holed;
      m.V.conservativeResize(holed.num_vertices() + 4, 3);
      m.F.conservativeResize(holed.num_faces() + 2, 3);
      std::vector<int> loop;
      for (std::size_t t = 0; t < hole.size(); ++t) {
        loop.push_back(hole[t]);
        if (t != i && t != j) continue;
        const int v = hole[t], x = static_cast<int>(m.V.rows()) - (t == i ? 4 : 2);
        const Vec3 p = holed.V.row(v).transpose(), d = (centre - p).normalized(), side = d.cross(Vec3::UnitZ());
        m.V.row(x) = (p + 0.8 * d + 0.3 * side).transpose();
        m.V.row(x + 1) = (p + 0.8 * d - 0.3 * side).transpose();
        m.F.row(holed.num_faces() + (t == i ? 0 : 1)) << v, x, x + 1;
        loop.insert(loop.end(), {x, x + 1, v});  // the triangle's border, surface on its left
      }
      const Topology topo = build_topology(m.F, m.num_vertices());
      HoleTriangulation first, weighed;
      try {
        first = triangulate_hole(m.V, m.F, topo, loop);
      } catch (const InvalidMeshError& e) {
        ADD_FAILURE() << "vertices " << hole[i] << ", " << hole[j] << ": " << e.what();
        continue;
      }
      weighed = triangulate_hole(m.V, m.F, topo, loop, {.bridge_cuts_weighed = 8});
      EXPECT_LE(weighed.max_dihedral_angle, first.max_dihedral_angle + kAngleTie)
          << "vertices " << hole[i] << ", " << hole[j];
      lighter += weighed.max_dihedral_angle < first.max_dihedral_angle - kAngleTie;
      std::map<std::pair<int, int>, int> directed;
      for (int f = 0; f < weighed.faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) ++directed[{weighed.faces(f, k), weighed.faces(f, (k + 1) % 3)}];
      for (std::size_t t = 0; t < loop.size(); ++t) ++directed[{loop[t], loop[(t + 1) % loop.size()]}];
      for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
        EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << "edge " << edge.first << "-" << edge.second;
      }
    }
  EXPECT_GT(lighter, 0);
}

// cgal_mech_holes_shark's hole 3 (80 edges) runs round a corner of the part whose fan of needle
// triangles curls over the hole: Liepa's lightest triangulation passes through 5 of its faces, and
// the ∆³ fairing of a patch refined from it crossed the mesh. Forbidding what crossed and solving
// again finds a triangulation that crosses nothing.
TEST(HoleTriangulation, ReSolvesUntilNoTriangleCrossesTheMesh) {
  const Mesh m = read_mesh(test::data_path("cgal_mech_holes_shark.off"));
  const Topology topo = build_topology(m.F, m.num_vertices());
  const auto loops = boundary_loops(m.F, topo);
  ASSERT_EQ(loops.size(), 4u);
  ASSERT_EQ(loops[3].size(), 80u);
  const auto crossings = [&](const Faces& faces) {
    Faces all(m.F.rows() + faces.rows(), 3);
    all << m.F, faces;
    std::vector<int> added(static_cast<std::size_t>(faces.rows()));
    std::iota(added.begin(), added.end(), static_cast<int>(m.F.rows()));
    return find_face_intersections(m.V, all, added).size();
  };
  const HoleTriangulation unchecked = triangulate_hole(m.V, m.F, topo, loops[3], {.max_crossing_rounds = 0});
  EXPECT_GT(crossings(unchecked.faces), 0u);
  EXPECT_EQ(unchecked.crossings, 0);  // not checked: not counted
  const HoleTriangulation checked = triangulate_hole(m.V, m.F, topo, loops[3]);
  EXPECT_EQ(checked.crossings, 0);
  EXPECT_EQ(crossings(checked.faces), 0u);
  EXPECT_EQ(checked.faces.rows(), 78);
  Mesh filled = m;
  filled.F.conservativeResize(m.F.rows() + checked.faces.rows(), 3);
  filled.F.bottomRows(checked.faces.rows()) = checked.faces;
  const auto still_open = boundary_loops(filled.F, build_topology(filled.F, filled.num_vertices()));
  EXPECT_EQ(still_open.size(), 3u);
}

namespace {

// Whether the triangle (a, b, c) of `points` is a face of their Delaunay tetrahedralization, by
// brute force: some sphere through its corners holds none of the other points. The spheres through
// a, b, c are centred at cc + t·n (cc the circumcentre, n the unit normal), of radius² R² + t², and
// point p stays outside one iff |p − cc|² − R² ≥ 2t·n·(p − cc): a bound on t from each point.
bool is_delaunay_face(const std::vector<Vec3>& points, int a, int b, int c) {
  const Vec3 u = points[b] - points[a], v = points[c] - points[a], w = u.cross(v);
  const Vec3 cc = points[a] + (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u)) / (2 * w.squaredNorm());
  const Vec3 n = w.normalized();
  const double r2 = (points[a] - cc).squaredNorm();
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  for (int p = 0; p < static_cast<int>(points.size()); ++p) {
    if (p == a || p == b || p == c) continue;
    const double power = (points[p] - cc).squaredNorm() - r2, side = n.dot(points[p] - cc);
    if (std::abs(side) < 1e-12) {
      if (power < 0) return false;
    } else if (side > 0) {
      hi = std::min(hi, power / (2 * side));
    } else {
      lo = std::max(lo, power / (2 * side));
    }
  }
  return lo <= hi;
}

}  // namespace

// HoleTriangulationOptions::delaunay_restricted: on these loops a triangulation lies within the faces
// of the loop's 3D Delaunay tetrahedralization, and every triangle is one (checked by brute force
// above).
TEST(HoleTriangulation, TheDelaunayRestrictionUsesOnlyFacesOfTheLoopsTetrahedralization) {
  int restricted = 0, differ = 0, full_outside = 0;
  for (const int n : {8, 12, 16, 24})
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const Mesh m = irregular_annulus(n, seed, 0.4);
      const auto loop = inner_loop(m);
      const Topology topo = build_topology(m.F, m.num_vertices());
      const HoleTriangulation full = triangulate_hole(m.V, m.F, topo, loop);
      const HoleTriangulation t = triangulate_hole(m.V, m.F, topo, loop, {.delaunay_restricted = true});
      EXPECT_FALSE(full.delaunay);
      ASSERT_EQ(t.faces.rows(), n - 2) << n << " " << seed;
      Mesh filled = m;
      filled.F.conservativeResize(m.F.rows() + t.faces.rows(), 3);
      filled.F.bottomRows(t.faces.rows()) = t.faces;
      expect_closed_manifold(filled, n);  // the annulus's outer circle
      if (!t.delaunay) continue;
      ++restricted;
      EXPECT_EQ(t.outside_delaunay, 0) << n << " " << seed;
      differ += t.faces != full.faces;
      std::vector<Vec3> points;
      std::map<int, int> position;
      for (int v : loop) position[v] = static_cast<int>(points.size()), points.push_back(m.V.row(v).transpose());
      const auto delaunay_face = [&](const Faces& faces, int f) {
        return is_delaunay_face(points, position[faces(f, 0)], position[faces(f, 1)], position[faces(f, 2)]);
      };
      for (int f = 0; f < t.faces.rows(); ++f)
        EXPECT_TRUE(delaunay_face(t.faces, f)) << n << " " << seed << " face " << f;
      // The check can fail: the full search's lightest triangulation often uses other faces.
      for (int f = 0; f < full.faces.rows(); ++f)
        if (!delaunay_face(full.faces, f)) {
          ++full_outside;
          break;
        }
    }
  EXPECT_GT(restricted, 12);
  EXPECT_GT(differ, 0);
  EXPECT_GT(full_outside, 0);
  std::printf("Delaunay-restricted on %d of 24 loops, a triangulation other than the full search's on %d, "
              "whose lightest triangulation has a face outside the tetrahedralization on %d\n",
              restricted, differ, full_outside);
}

// Where no triangulation of a loop lies within the faces of its tetrahedralization, the restricted
// search takes as few other triangles as any triangulation must: checked against every triangulation
// of small loops, so wavy that on a few of them no triangulation lies within those faces.
TEST(HoleTriangulation, TheDelaunayRestrictionTakesAsFewOtherTrianglesAsItMust) {
  int restricted = 0, short_of = 0;
  for (const int n : {8, 9, 10, 11})
    for (unsigned seed = 1; seed <= 40; ++seed) {
      const Mesh m = irregular_annulus(n, seed, 4.0);
      const auto loop = inner_loop(m);
      const Topology topo = build_topology(m.F, m.num_vertices());
      const HoleTriangulation t = triangulate_hole(m.V, m.F, topo, loop, {.delaunay_restricted = true});
      if (!t.delaunay) continue;
      ++restricted;
      std::vector<Vec3> points;
      std::map<int, int> position;
      for (int v : loop) position[v] = static_cast<int>(points.size()), points.push_back(m.V.row(v).transpose());
      int fewest = std::numeric_limits<int>::max();
      for (const auto& candidate : all_triangulations(loop)) {
        const int outside = static_cast<int>(std::count_if(candidate.begin(), candidate.end(), [&](const auto& f) {
          return !is_delaunay_face(points, position[f[0]], position[f[1]], position[f[2]]);
        }));
        fewest = std::min(fewest, outside);
      }
      EXPECT_EQ(t.outside_delaunay, fewest) << n << " " << seed;
      short_of += fewest > 0;
    }
  EXPECT_GT(restricted, 120);
  EXPECT_GT(short_of, 0);
  std::printf("Delaunay-restricted on %d of 160 loops; on %d no triangulation lies within the faces\n", restricted,
              short_of);
}

// Which loops the restriction can apply to, before any tetrahedralization: not one through a vertex
// twice, nor one longer than the programme solves whole.
TEST(HoleTriangulation, TheDelaunayRestrictionAppliesToSimpleLoopsTheProgrammeSolvesWhole) {
  const std::vector<int> simple{0, 1, 2, 3, 4}, pinched{0, 1, 2, 0, 3, 4};
  EXPECT_FALSE(passes_a_vertex_twice(simple));
  EXPECT_TRUE(passes_a_vertex_twice(pinched));
  EXPECT_TRUE(delaunay_restriction_applies(simple, {}));
  EXPECT_FALSE(delaunay_restriction_applies(pinched, {}));
  EXPECT_TRUE(delaunay_restriction_applies(simple, {.max_dynamic_programming_size = 5}));
  EXPECT_FALSE(delaunay_restriction_applies(simple, {.max_dynamic_programming_size = 4}));
}

// A flat loop spans no volume: no tetrahedralization restricts the search, which then is the full one.
TEST(HoleTriangulation, AFlatLoopIsTriangulatedByTheFullSearch) {
  const Mesh grid = test::regular_grid(12, 12);
  const Mesh holed = cut(grid, [](const Vec3& p) { return p.x() > 2.5 && p.x() < 8.5 && p.y() > 2.5 && p.y() < 8.5; });
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  const auto hole = grid_hole(holed);
  const HoleTriangulation full = triangulate_hole(holed.V, holed.F, topo, hole);
  const HoleTriangulation t = triangulate_hole(holed.V, holed.F, topo, hole, {.delaunay_restricted = true});
  EXPECT_FALSE(t.delaunay);
  EXPECT_EQ(t.faces, full.faces);
}

// ---------------------------------------------------------------------------------------------
// Refinement and relaxation

TEST(HolePatch, SphereCapIsFilledWatertightWithMatchingEdgeLengths) {
  const Mesh sphere = test::icosphere(4);  // 2562 vertices
  const Mesh holed = cut(sphere, [](const Vec3& p) { return p.z() > 0.7; });
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  ASSERT_EQ(loops.size(), 1u);
  const InitialPatch p = hole_patch(holed, loops);
  expect_input_kept(holed, p.mesh);
  expect_closed_manifold(p.mesh);
  ASSERT_FALSE(p.free_vertices.empty());
  EXPECT_EQ(p.free_vertices.front(), holed.num_vertices());  // new vertices are appended
  EXPECT_EQ(p.free_vertices.back(), p.mesh.num_vertices() - 1);
  const EdgeLengths e = edge_lengths(holed, loops, p);
  EXPECT_NEAR(e.mean_patch / e.mean_border, 1.0, 0.3);
  EXPECT_GT(check_surface(p.mesh).min_angle_degrees, 10.0);
  // The membrane of a planar circle-like border is close to flat: every new vertex lies near the
  // plane of the border (z ≈ 0.7 give or take the border's zig-zag).
  for (int v : p.free_vertices) EXPECT_NEAR(p.mesh.V(v, 2), 0.7, 0.05);
  // Relaxation lowered the area of the patch.
  ASSERT_EQ(p.membrane.area.size(), 4u);
  EXPECT_LE(p.membrane.area.back(), p.membrane.area.front() + 1e-12);
}

// PatchOptions::solver is the membrane's: UMFPACK there gives the same membrane as MUMPS, and a
// MUMPS control the library reserves is refused by that solve.
TEST(HolePatch, TheMembraneSolvesWithThePatchOptionsSolver) {
  const Mesh sphere = test::icosphere(3);
  const Mesh holed = cut(sphere, [](const Vec3& p) { return p.z() > 0.7; });
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  const InitialPatch mumps = hole_patch(holed, loops);
  PatchOptions options;
  options.solver.kind = LinearSolverKind::umfpack;
  const InitialPatch umfpack = hole_patch(holed, loops, options);
  ASSERT_EQ(umfpack.mesh.num_vertices(), mumps.mesh.num_vertices());
  EXPECT_LT((umfpack.mesh.V - mumps.mesh.V).cwiseAbs().maxCoeff(), 1e-10);
  options = PatchOptions{};
  options.solver.mumps_controls = {{1, 6}};  // MUMPS's output stream: the library's own
  EXPECT_THROW(hole_patch(holed, loops, options), InvalidArgument);
  options.relax = false;  // no membrane, no solve
  EXPECT_NO_THROW(hole_patch(holed, loops, options));
}

TEST(HolePatch, IrregularHoleRefinesToTheBorderLength) {
  const Mesh m = irregular_annulus(40, 7, 0.3);
  const std::vector<std::vector<int>> loops{inner_loop(m)};
  const InitialPatch p = hole_patch(m, loops);
  expect_input_kept(m, p.mesh);
  expect_closed_manifold(p.mesh, 40);  // the annulus's outer circle stays open
  const EdgeLengths e = edge_lengths(m, loops, p);
  EXPECT_NEAR(e.mean_patch / e.mean_border, 1.0, 0.3);
}

TEST(PatchRefinement, TargetLengthSetsTheDensityAndBorderNeverMoves) {
  const Mesh grid = test::regular_grid(12, 12);
  const Mesh holed = cut(grid, [](const Vec3& p) { return p.x() > 2.5 && p.x() < 9.5 && p.y() > 2.5 && p.y() < 9.5; });
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  const auto hole = grid_hole(holed);
  const HoleTriangulation t = triangulate_hole(holed.V, holed.F, topo, hole);
  std::vector<double> means;
  for (const double target : {1.0, 0.5, 0.25}) {
    const RefinedPatch r = refine_patch(holed.V, holed.F, t.faces, {.target_edge_length = target});
    EXPECT_TRUE(r.V.topRows(holed.num_vertices()) == holed.V);
    EXPECT_EQ(r.free_vertices.size(), static_cast<std::size_t>(r.V.rows() - holed.num_vertices()));
    Mesh out;
    out.V = r.V;
    out.F = r.F;
    expect_closed_manifold(out, 48);
    double sum = 0.0;
    int count = 0;
    for (int f = r.first_patch_face; f < r.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) sum += (r.V.row(r.F(f, k)) - r.V.row(r.F(f, (k + 1) % 3))).norm(), ++count;
    means.push_back(sum / count);
    EXPECT_NEAR(means.back() / target, 1.0, 0.3) << target;
    // The refined patch is still planar: tangential relaxation moves vertices within the plane.
    for (int v : r.free_vertices) EXPECT_NEAR(r.V(v, 2), 0.0, 1e-12);
  }
}

// A one-ring hole (the faces of one vertex removed) is triangulated without an interior vertex;
// Liepa's split test can miss the vertex that is missing, leaving a flat patch no fairing can bend.
// Refinement puts one back where the hole holds the area of the triangles round it; two missing
// faces (a 4-edge hole of two triangles' area) stay as they are.
TEST(PatchRefinement, AOneRingHoleGetsItsVertexBackAndTwoMissingFacesStayFlat) {
  const Mesh sphere = test::jittered_sphere(3, 1.0, 0.02);  // the jitter makes Liepa's fans thin
  for (int centre = 0; centre < sphere.num_vertices(); centre += 37) {
    const Mesh holed = without_faces(sphere, [&](int f) { return (sphere.F.row(f).array() == centre).any(); });
    const Topology topo = build_topology(holed.F, holed.num_vertices());
    const auto loops = boundary_loops(holed.F, topo);
    ASSERT_EQ(loops.size(), 1u);
    const HoleTriangulation t = triangulate_hole(holed.V, holed.F, topo, loops.front());
    ASSERT_EQ(t.faces.rows(), static_cast<int>(loops.front().size()) - 2);
    const RefinedPatch r = refine_patch(holed.V, holed.F, t.faces);
    Mesh out;
    out.V = r.V;
    out.F = r.F;
    expect_closed_manifold(out, 0);
    EXPECT_EQ(r.free_vertices.size(), 1u) << "centre " << centre;
  }

  // Two faces that share an edge: a 4-edge hole.
  const int first = 0;
  int second = -1;
  for (int f = 1; f < sphere.num_faces() && second < 0; ++f) {
    int shared = 0;
    for (int k = 0; k < 3; ++k) shared += (sphere.F.row(first).array() == sphere.F(f, k)).any();
    if (shared == 2) second = f;
  }
  ASSERT_GE(second, 0);
  const Mesh holed = without_faces(sphere, [&](int f) { return f == first || f == second; });
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  const auto loops = boundary_loops(holed.F, topo);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops.front().size(), 4u);
  const HoleTriangulation t = triangulate_hole(holed.V, holed.F, topo, loops.front());
  EXPECT_TRUE(refine_patch(holed.V, holed.F, t.faces).free_vertices.empty());
}

TEST(PatchRefinement, RejectsNonManifoldPatches) {
  const Mesh m = irregular_annulus(6, 1, 0.2);
  Faces twice(2, 3);
  twice << 0, 1, 2, 0, 1, 3;  // edge 0→1 used twice in the same direction
  try {
    refine_patch(m.V, m.F, twice);
    FAIL() << "no exception";
  } catch (const InvalidMeshError& e) {
    EXPECT_STREQ(e.what(), "refine_patch: patch edge 0-1 is used twice in the same direction");
  }
}

TEST(Membrane, FlattensAPlanarPatchExactly) {
  // A planar grid with its border fixed. Cotangent weights have linear precision: the plane is a
  // fixed point, and vertices lifted off it return to it exactly in one solve.
  Mesh grid = test::regular_grid(10, 10, 0.1);
  const Topology topo = build_topology(grid.F, grid.num_vertices());
  const auto flags = boundary_vertex_flags(topo);
  std::vector<int> free;
  for (int v = 0; v < grid.num_vertices(); ++v)
    if (!flags[v]) free.push_back(v);
  const Vertices exact = grid.V;
  Vertices still = grid.V;
  const MembraneReport flat = relax_membrane(still, grid.F, free, {.iterations = 2});
  EXPECT_LT((still - exact).cwiseAbs().maxCoeff(), 1e-13);

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.03, 0.03);
  for (int v : free) grid.V(v, 2) += noise(rng);
  const MembraneReport r = relax_membrane(grid.V, grid.F, free, {.iterations = 1});
  EXPECT_LT(grid.V.col(2).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_EQ(r.iterations, 1);
  ASSERT_EQ(r.area.size(), 2u);
  EXPECT_GT(r.area.front(), flat.area.front() + 1e-3);
  EXPECT_NEAR(r.area.back(), flat.area.front(), 1e-12);  // flat, and no triangle folded over
}

// ---------------------------------------------------------------------------------------------
// Tubes

namespace {

Mesh concatenate(const Mesh& a, const Mesh& b) {
  Mesh m;
  m.V.resize(a.num_vertices() + b.num_vertices(), 3);
  m.V << a.V, b.V;
  m.F.resize(a.num_faces() + b.num_faces(), 3);
  m.F << a.F, b.F.array() + a.num_vertices();
  return m;
}

}  // namespace

// The real-hole protocol's cut of blub at (0.00697216, -0.181279, -1.03702), radius 8 h: two loops
// (82 and 68 edges) on a strongly curved part. Their minimum-weight triangulations keep every border
// face within 46° and 84° of the mesh face across; Delaunay flips during refinement used to turn
// border triangles over (93.8° and 95.2°), the crease the flow then starts from. The refinement now
// refuses such flips; the membrane can still fold the border, and border_dihedral_angle says so.
// without_membrane takes the membrane back: the refined patch, as built without it.
TEST(PatchFolds, RefinementNeverFoldsABorderTriangleOfARealHole) {
  const Mesh holed = test::cut_ball(read_mesh(test::data_path("blub.obj")), Vec3(0.00697216, -0.181279, -1.03702),
                                    0.307912);
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  ASSERT_EQ(loops.size(), 2u);
  PatchOptions unrelaxed;
  unrelaxed.relax = false;
  PatchOptions triangulated = unrelaxed;
  triangulated.refinement.max_rounds = 0;
  triangulated.refinement.relaxation_sweeps = 0;
  for (const auto& loop : loops) {
    const InitialPatch coarse = hole_patch(holed, {loop}, triangulated);
    const InitialPatch refined = hole_patch(holed, {loop}, unrelaxed);
    const InitialPatch relaxed = hole_patch(holed, {loop});
    EXPECT_LT(coarse.border_dihedral_angle, std::numbers::pi / 2) << loop.size() << " edges";
    EXPECT_LE(coarse.border_dihedral_angle, coarse.holes.front().max_dihedral_angle + 1e-12);
    EXPECT_GT(refined.refinement.splits, 20);
    EXPECT_LT(refined.border_dihedral_angle, std::numbers::pi / 2) << loop.size() << " edges";
    EXPECT_GT(relaxed.border_dihedral_angle, 0.0);
    // The membrane's patch with its free vertices put back is the patch built without it.
    const InitialPatch restored = without_membrane(relaxed);
    EXPECT_TRUE(restored.mesh.V == refined.mesh.V);
    EXPECT_TRUE(restored.mesh.F == refined.mesh.F);
    EXPECT_EQ(restored.free_vertices, refined.free_vertices);
    EXPECT_EQ(restored.refined_free.rows(), 0);
    EXPECT_EQ(restored.border_dihedral_angle, refined.border_dihedral_angle);
    EXPECT_FALSE(relaxed.mesh.V == refined.mesh.V);
    std::cout << loop.size() << "-edge loop: border dihedral " << coarse.border_dihedral_angle * 180 / std::numbers::pi
              << "° triangulated, " << refined.border_dihedral_angle * 180 / std::numbers::pi << "° refined, "
              << relaxed.border_dihedral_angle * 180 / std::numbers::pi << "° after the membrane\n";
  }
}

// data/hemisphere.off's 120-edge border circle: its minimum-weight triangulation puts a sliver
// (177°) on every other border vertex, which keeps its largest dihedral against the sphere at 91°.
// The refinement flips them away although that turns those border triangles to 96–102°: every
// border vertex then has an interior neighbour and no patch triangle keeps an angle above 160°.
TEST(PatchFolds, RefinementFlipsAwayTheSliversAlongAFlatBorder) {
  const Mesh hemisphere = read_mesh(test::data_path("hemisphere.off"));
  const auto loops = boundary_loops(hemisphere.F, build_topology(hemisphere.F, hemisphere.num_vertices()));
  ASSERT_EQ(loops.size(), 1u);
  PatchOptions unrelaxed;
  unrelaxed.relax = false;
  const InitialPatch p = hole_patch(hemisphere, loops, unrelaxed);
  const auto angle = [&](int a, int b, int c) {
    const Vec3 u = p.mesh.V.row(b) - p.mesh.V.row(a), v = p.mesh.V.row(c) - p.mesh.V.row(a);
    return std::atan2(u.cross(v).norm(), u.dot(v));
  };
  std::set<int> touching_interior;
  double largest = 0;
  for (int f = p.first_patch_face; f < p.mesh.num_faces(); ++f) {
    const int a = p.mesh.F(f, 0), b = p.mesh.F(f, 1), c = p.mesh.F(f, 2);
    largest = std::max({largest, angle(a, b, c), angle(b, c, a), angle(c, a, b)});
    if (a >= hemisphere.num_vertices() || b >= hemisphere.num_vertices() || c >= hemisphere.num_vertices())
      for (int v : {a, b, c}) touching_interior.insert(v);
  }
  for (int v : loops.front()) EXPECT_TRUE(touching_interior.contains(v)) << "border vertex " << v;
  EXPECT_LT(largest, 160 * std::numbers::pi / 180);
  EXPECT_LT(p.border_dihedral_angle, 2 * std::numbers::pi / 3);
}

TEST(Tube, JoinsCoaxialCylindersOfDifferentCountsIntoOneManifold) {
  // z in [-2, 1] and [2, 5]: the facing ends are 1 apart, each cylinder's own ends 3 apart.
  Mesh lower = test::open_cylinder(32, 8, 1.0, 3.0);
  Mesh upper = test::open_cylinder(48, 12, 1.0, 3.0);
  lower.V.col(2).array() -= 2.0;
  upper.V.col(2).array() += 2.0;
  const Mesh both = concatenate(lower, upper);
  const Topology topo = build_topology(both.F, both.num_vertices());
  const auto loops = boundary_loops(both.F, topo);
  ASSERT_EQ(loops.size(), 4u);
  const LoopPair pair = closest_loop_pair(both.V, loops);
  const auto& a = loops[pair.first];
  const auto& b = loops[pair.second];
  // The facing ends: z = 1 on the lower cylinder, z = 2 on the upper one.
  EXPECT_DOUBLE_EQ(both.V(a.front(), 2), 1.0);
  EXPECT_DOUBLE_EQ(both.V(b.front(), 2), 2.0);
  EXPECT_NEAR(pair.distance, 1.0, 0.01);  // the rings' vertices are not above each other

  const InitialPatch p = tube_patch(both, a, b);
  expect_input_kept(both, p.mesh);
  expect_closed_manifold(p.mesh, 32 + 48);  // only the two far ends stay open
  EXPECT_GT(p.tube.rings, 0);
  const auto remaining = boundary_loops(p.mesh.F, build_topology(p.mesh.F, p.mesh.num_vertices()));
  EXPECT_EQ(remaining.size(), 2u);
  // The tube is a surface of revolution-like neck: between the cylinders' radius and a catenoid's
  // waist, never collapsing to the axis.
  for (int v : p.free_vertices) {
    const double r = std::hypot(p.mesh.V(v, 0), p.mesh.V(v, 1));
    EXPECT_GT(r, 0.5);
    EXPECT_LT(r, 1.05);
    EXPECT_GT(p.mesh.V(v, 2), 1.0);
    EXPECT_LT(p.mesh.V(v, 2), 2.0);
  }
}

TEST(Tube, HermiteRingsLeaveTheSurfacesTangentially) {
  // Without relaxation, the Hermite rings between two coaxial cylinders stay on the cylinder (the
  // outward directions are ±z), while straight lines between loops of different radii do not.
  Mesh lower = test::open_cylinder(24, 8, 1.0, 4.0);
  Mesh upper = test::open_cylinder(24, 8, 1.0, 4.0);
  lower.V.col(2).array() -= 3.0;  // ends at z = 1 and z = 3 face each other
  upper.V.col(2).array() += 3.0;
  const Mesh both = concatenate(lower, upper);
  const Topology topo = build_topology(both.F, both.num_vertices());
  const auto loops = boundary_loops(both.F, topo);
  const LoopPair pair = closest_loop_pair(both.V, loops);
  const Tube tube = build_tube(both.V, both.F, topo, loops[pair.first], loops[pair.second], {.rings = 5});
  EXPECT_EQ(tube.rings, 5);
  EXPECT_EQ(tube.ring_vertices.size(), 5u * 24u);
  EXPECT_NEAR(tube.mean_squared_distance, 4.0, 1e-12);  // aligned: matched points 2 apart
  for (int v : tube.ring_vertices) EXPECT_NEAR(std::hypot(tube.V(v, 0), tube.V(v, 1)), 1.0, 1e-12);
}

// data/lagrange_prout.obj, repaired: a flat sheet whose closest loops are two 3-vertex holes. The
// Hermite rings between them lie in the sheet, turned against the loops, and the shortest-diagonal
// zipper wrapped the loop fully round while the first ring stood still, drawing one diagonal twice
// (4 faces at an edge: refine_patch refused the tube, "patch edge ... is used twice in the same
// direction"). The tube is now one manifold.
TEST(Tube, ThreeVertexLoopsJoinIntoOneManifold) {
  Mesh mesh = read_mesh(test::data_path("lagrange_prout.obj"));
  repair(mesh);
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const auto loops = boundary_loops(mesh.F, topo);
  const LoopPair pair = closest_loop_pair(mesh.V, loops);
  ASSERT_EQ(loops[pair.first].size(), 3u);
  ASSERT_EQ(loops[pair.second].size(), 3u);
  const Tube tube = build_tube(mesh.V, mesh.F, topo, loops[pair.first], loops[pair.second]);
  Mesh joined;
  joined.V = tube.V;
  joined.F.resize(mesh.num_faces() + tube.faces.rows(), 3);
  joined.F << mesh.F, tube.faces;
  const SurfaceCheck c = check_surface(joined);
  EXPECT_EQ(c.non_manifold_edges, 0);
  EXPECT_EQ(c.repeated_directed, 0);
  EXPECT_NO_THROW(tube_patch(mesh, loops[pair.first], loops[pair.second]));
}

TEST(Tube, RejectsLoopsThatShareVertices) {
  const Mesh c = test::open_cylinder(8, 2, 1.0, 1.0);
  const Topology topo = build_topology(c.F, c.num_vertices());
  const auto loops = boundary_loops(c.F, topo);
  try {
    build_tube(c.V, c.F, topo, loops[0], loops[0]);
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("build_tube: the loops share vertex ", 0), 0u);
  }
}

// ---------------------------------------------------------------------------------------------
// Real data: every hole of three scanned or modelled meshes

class RealHoles : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(RealHoles, EveryHoleIsFilledWatertight) {
  const auto [name, holes] = GetParam();
  const Mesh mesh = read_mesh(test::data_path(name));
  const auto loops = boundary_loops(mesh.F, build_topology(mesh.F, mesh.num_vertices()));
  ASSERT_EQ(static_cast<int>(loops.size()), holes);
  const InitialPatch p = hole_patch(mesh, loops);
  expect_input_kept(mesh, p.mesh);
  expect_closed_manifold(p.mesh);
  const EdgeLengths e = edge_lengths(mesh, loops, p);
  EXPECT_NEAR(e.mean_patch / e.mean_border, 1.0, 0.3) << name;
}

INSTANTIATE_TEST_SUITE_P(Data, RealHoles,
                         ::testing::Values(std::pair{"cgal_mech_holes_shark.off", 4},
                                           std::pair{"airplane_holes.obj", 27},
                                           std::pair{"stanford_bunny_zipper.obj", 5}));
