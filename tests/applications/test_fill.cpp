// Tests of hole filling end to end (fill.h): analytic holes against the exact surface, the G2 > G1 >
// G0 > harmonic ordering, real meshes filled watertight, per-hole failures, and the pair test of
// face_intersection.h.
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/repair.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>

#include "analytic_meshes.h"
#include "flow_meshes.h"
#include "hole_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

using Vec3 = Eigen::Vector3d;

FillOptions options_for(Continuity c, FairMethod method = FairMethod::flow) {
  FillOptions o;
  o.continuity = c;
  o.method = method;
  return o;
}

// Max |distance| of the new vertices to a reference surface given as signed distances.
double max_new_vertex_deviation(const Mesh& filled, int input_vertices,
                                const std::function<Eigen::VectorXd(const Vertices&)>& distances) {
  const Eigen::VectorXd d = distances(filled.V.bottomRows(filled.num_vertices() - input_vertices));
  return d.cwiseAbs().maxCoeff();
}

// What every successful fill guarantees, checked with validate and topology.
void expect_watertight(const Mesh& input, const Mesh& filled) {
  ASSERT_GE(filled.num_vertices(), input.num_vertices());
  EXPECT_TRUE(filled.V.topRows(input.num_vertices()) == input.V) << "an input vertex moved";
  EXPECT_TRUE(filled.F.topRows(input.num_faces()) == input.F) << "an input face changed";
  const ValidationReport v = validate(filled);
  EXPECT_TRUE(v.manifold());
  EXPECT_EQ(v.degenerate_faces.count, 0);
  EXPECT_EQ(v.inconsistent_orientation_edges.count, 0);
  EXPECT_EQ(v.duplicate_faces.count, 0);
  EXPECT_TRUE(boundary_loops(filled.F, build_topology(filled.F, filled.num_vertices())).empty());
}

struct SphereFill {
  double deviation = 0;    // max |r − 1| over the new vertices
  double h_jump = 0;       // max H jump across the border
  double normal_angle = 0; // max normal angle across the border
  HoleReport hole;
};

// The unit icosphere of `level` with the faces above z = 0.5 removed, filled.
SphereFill fill_sphere_cap(int level, const FillOptions& options) {
  const Mesh holed = test::cut_hole(test::icosphere(level), [](const Vec3& p) { return p.z() > 0.5; });
  Mesh filled = holed;
  const FillReport report = fill_holes(filled, options);
  EXPECT_EQ(report.holes.size(), 1u);
  EXPECT_EQ(report.filled, 1) << report.holes.front().reason;
  expect_watertight(holed, filled);
  SphereFill out;
  out.hole = report.holes.front();
  out.deviation = max_new_vertex_deviation(filled, holed.num_vertices(),
                                           [](const Vertices& V) { return test::sphere_distances(V, 1.0); });
  out.h_jump = out.hole.continuity.max_mean_curvature_jump;
  out.normal_angle = out.hole.continuity.max_normal_angle;
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Analytic holes

TEST(FillSphere, G2CapConvergesToTheSphereAndBeatsTheHarmonicBaseline) {
  const SphereFill coarse = fill_sphere_cap(3, options_for(Continuity::G2));
  const SphereFill fine = fill_sphere_cap(4, options_for(Continuity::G2));
  const SphereFill harmonic = fill_sphere_cap(4, options_for(Continuity::G2, FairMethod::harmonic));
  std::cout << "sphere cap z > 0.5 removed, G2 fill: max|r-1| " << coarse.deviation << " (642 vertices), "
            << fine.deviation << " (2562), harmonic " << harmonic.deviation << " (2562); max H jump "
            << fine.h_jump << " vs harmonic " << harmonic.h_jump << "; " << fine.hole.steps << " steps, "
            << fine.hole.vertices_added << " new vertices, " << fine.hole.harmonic_solves << " ∆³ solves first\n";
  EXPECT_EQ(fine.hole.supported, Continuity::G2);
  EXPECT_TRUE(fine.hole.note.empty()) << fine.hole.note;
  // From the re-evaluated ∆³ start the flow settles in a few Newton-like steps (from the membrane
  // with τ doubling from 1e-9 it took 145).
  EXPECT_LE(fine.hole.steps, 15);
  EXPECT_LT(fine.deviation, 5e-4);  // 2.8e-4 (5.3e-4 from the membrane in 145 steps)
  EXPECT_LT(fine.deviation, 0.6 * coarse.deviation);
  // The baseline is the re-evaluated cotangent ∆³ solution (3.7e-3; frozen at the membrane it was
  // 0.13), the floor the G2 fill starts from and falls back to.
  EXPECT_LT(fine.deviation, 0.1 * harmonic.deviation);
  EXPECT_LT(fine.h_jump, 0.01);
  EXPECT_LT(fine.h_jump, 0.1 * harmonic.h_jump);
  EXPECT_FALSE(fine.hole.linear);
  EXPECT_TRUE(harmonic.hole.linear);
  EXPECT_EQ(delivered_label(harmonic.hole.supported, harmonic.hole.linear), "C2 (linear)");
  EXPECT_TRUE(std::isnan(harmonic.hole.final_max_velocity));
}

// A sphere is stationary for f = H and for Willmore flow alike, so on the cap G2 and G1 both reach
// the sphere (G1 slightly closer on the refined patch: 1.2e-3 vs 1.3e-3 here) while G0 stays flat.
// A cylinder separates them: stationary for f = H, inflated by Willmore flow (method.md §8.5).
TEST(FillOrdering, G2BeatsG1BeatsG0) {
  const SphereFill g2 = fill_sphere_cap(3, options_for(Continuity::G2));
  const SphereFill g1 = fill_sphere_cap(3, options_for(Continuity::G1));
  const SphereFill g0 = fill_sphere_cap(3, options_for(Continuity::G0));
  std::cout << "sphere cap, 642 vertices: max|r-1| G2 " << g2.deviation << ", G1 " << g1.deviation << ", G0 "
            << g0.deviation << "; max normal angle G2 " << g2.normal_angle << ", G1 " << g1.normal_angle
            << ", G0 " << g0.normal_angle << "\n";
  EXPECT_LT(100 * g2.deviation, g0.deviation);
  EXPECT_LT(100 * g1.deviation, g0.deviation);
  EXPECT_LT(10 * g2.normal_angle, g0.normal_angle);
  EXPECT_EQ(g1.hole.supported, Continuity::G1);

  const Mesh holed = test::cut_hole(test::open_cylinder(32, 16, 1.0, 3.0),
                                    [](const Vec3& p) { return (p - Vec3(1, 0, 1.5)).norm() < 0.6; });
  auto radius_error = [](const Vertices& V) { return (test::axis_distances(V).array() - 1.0).matrix().eval(); };
  std::vector<double> deviation;
  for (const Continuity c : {Continuity::G2, Continuity::G1, Continuity::G0}) {
    FillOptions o = options_for(c);
    o.max_hole_edges = 31;  // the two open ends stay open
    Mesh filled = holed;
    ASSERT_EQ(fill_holes(filled, o).filled, 1);
    deviation.push_back(max_new_vertex_deviation(filled, holed.num_vertices(), radius_error));
  }
  std::cout << "cylinder hole, 32 around: max|rho-1| G2 " << deviation[0] << ", G1 " << deviation[1] << ", G0 "
            << deviation[2] << "\n";
  EXPECT_LT(5 * deviation[0], deviation[1]);
  EXPECT_LT(5 * deviation[1], deviation[2]);
}

TEST(FillCylinder, G2HoleStaysOnTheCylinder) {
  // A cylinder is stationary for f = H (constant H): the G2 fill should reproduce it.
  for (const int around : {32, 64}) {
    const int along = around / 2;
    const Mesh cylinder = test::open_cylinder(around, along, 1.0, 3.0);
    const Mesh holed = test::cut_hole(cylinder, [](const Vec3& p) { return (p - Vec3(1, 0, 1.5)).norm() < 0.6; });
    FillOptions o = options_for(Continuity::G2);
    o.max_hole_edges = around - 1;  // the two open ends stay open
    Mesh filled = holed, harmonic = holed;
    const FillReport r = fill_holes(filled, o);
    ASSERT_EQ(r.filled, 1);
    EXPECT_EQ(r.skipped, 2);
    o.method = FairMethod::harmonic;
    ASSERT_EQ(fill_holes(harmonic, o).filled, 1);
    auto radius_error = [](const Vertices& V) { return (test::axis_distances(V).array() - 1.0).matrix().eval(); };
    const double g2 = max_new_vertex_deviation(filled, holed.num_vertices(), radius_error);
    const double baseline = max_new_vertex_deviation(harmonic, holed.num_vertices(), radius_error);
    std::cout << "cylinder " << around << " around: G2 max|rho-1| " << g2 << ", harmonic " << baseline << "\n";
    EXPECT_LT(g2, 2e-3);
    EXPECT_LT(g2, 0.2 * baseline);
  }
}

TEST(FillTorus, G2HoleStaysCloseToTheTorus) {
  for (const int n : {48, 96}) {
    const Mesh torus = test::torus_grid(n, n / 2, 2.0, 1.0).mesh;
    const Mesh holed = test::cut_hole(torus, [](const Vec3& p) { return (p - Vec3(3, 0, 0)).norm() < 0.7; });
    Mesh filled = holed, harmonic = holed;
    ASSERT_EQ(fill_holes(filled, options_for(Continuity::G2)).filled, 1);
    ASSERT_EQ(fill_holes(harmonic, options_for(Continuity::G2, FairMethod::harmonic)).filled, 1);
    auto torus_error = [](const Vertices& V) { return test::torus_distances(V, 2.0, 1.0); };
    const double g2 = max_new_vertex_deviation(filled, holed.num_vertices(), torus_error);
    const double baseline = max_new_vertex_deviation(harmonic, holed.num_vertices(), torus_error);
    std::cout << "torus " << n << "x" << n / 2 << ": G2 max distance " << g2 << ", harmonic " << baseline << "\n";
    EXPECT_LT(g2, 1e-2);
    EXPECT_LT(g2, 0.5 * baseline);
  }
}

// Irregular sampling is not what makes G2 lose to ∆³ on real meshes (docs/real-holes.md, "The surface is
// not fair at the scale of a hole"): on a torus whose grid parameters are jittered by 0.3 spacings,
// with every vertex still on the torus, a 4h ball hole gets the default G2 fill, an order of
// magnitude closer to the torus than the linear ∆³ fill of the same hole.
TEST(FillTorus, OnAnIrregularTorusTheDefaultFillIsG2AndFarCloserThanTheLinearOne) {
  const Mesh torus = test::torus_grid(100, 40, 1.0, 0.4, 0.3, 7).mesh;
  const double h = test::mean_edge_length(torus);
  const auto mean_distance = [](const Mesh& filled, int input_vertices) {
    return test::torus_distances(filled.V.bottomRows(filled.num_vertices() - input_vertices), 1.0, 0.4)
        .cwiseAbs()
        .mean();
  };
  for (const int centre : {795, 3836}) {
    const Mesh holed = test::cut_ball(torus, torus.V.row(centre).transpose(), 4 * h);
    Mesh filled = holed, harmonic = holed;
    const FillReport report = fill_holes(filled, FillOptions{});
    ASSERT_EQ(report.filled, 1);
    ASSERT_EQ(fill_holes(harmonic, options_for(Continuity::G2, FairMethod::harmonic)).filled, 1);
    EXPECT_EQ(report.holes[0].supported, Continuity::G2) << report.holes[0].note;
    EXPECT_FALSE(report.holes[0].linear) << report.holes[0].note;
    const double g2 = mean_distance(filled, holed.num_vertices()) / h;
    const double linear = mean_distance(harmonic, holed.num_vertices()) / h;
    std::cout << "irregular torus, hole at " << centre << ": G2 mean distance " << g2 << " h, linear " << linear
              << " h\n";
    EXPECT_LT(g2, 0.01);
    EXPECT_LT(g2, 0.25 * linear);
  }
}

// ---------------------------------------------------------------------------------------------
// Real meshes

// The scans' noisy borders and the shark's sharp-edged holes make the G2 flow slow to settle (the
// bunny's small holes run the full 200 steps, then fall back to G1: ~25 s); those two use G1 here
// to keep the test in seconds, the shark's flows capped at 60 steps (its 365-vertex hole does not
// settle in 200 G1 steps either). The airplane's 27 windows and doors are filled with G2.
struct RealCase {
  const char* name;
  Continuity continuity;
  int max_steps;  // 0: fair_region's default
};
class RealHoles : public ::testing::TestWithParam<RealCase> {};

TEST_P(RealHoles, EveryHoleIsFilledWatertight) {
  const auto [name, continuity, max_steps] = GetParam();
  const Mesh input = read_mesh(test::data_path(name));
  Mesh filled = input;
  FillOptions o = options_for(continuity);
  if (max_steps > 0) o.flow.max_steps = max_steps;
  const FillReport r = fill_holes(filled, o);
  for (const auto& h : r.holes) EXPECT_EQ(h.status, HoleStatus::filled) << "hole " << h.index << ": " << h.reason;
  EXPECT_EQ(r.filled, static_cast<int>(r.holes.size()));
  int fallbacks = 0;
  for (const auto& h : r.holes) fallbacks += h.supported != continuity;
  std::cout << name << ": " << r.filled << " holes filled with " << to_string(continuity) << " in " << r.seconds
            << " s (" << fallbacks << " at a lower continuity)\n";
  expect_watertight(input, filled);
}

INSTANTIATE_TEST_SUITE_P(Data, RealHoles,
                         ::testing::Values(RealCase{"cgal_mech_holes_shark.off", Continuity::G1, 60},
                                           RealCase{"airplane_holes.obj", Continuity::G2, 0},
                                           RealCase{"stanford_bunny_zipper.obj", Continuity::G1, 0}));

// A loop of three edges around a face of the mesh (here a lone triangle) already bounds that face:
// filling it could only add the face again, reversed. It is skipped with the reason, and the mesh
// is left as it was.
TEST(FillLoneTriangle, ALoopAroundAFaceIsSkippedNotFilledWithTheFaceReversed) {
  Mesh m;
  m.V.resize(3, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  const Mesh input = m;
  const FillReport r = fill_holes(m);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_EQ(r.holes[0].status, HoleStatus::skipped);
  EXPECT_EQ(r.holes[0].reason, "the loop runs around a lone triangle: filling it would add that face again, reversed");
  EXPECT_TRUE(r.holes[0].around_a_face);
  EXPECT_EQ(r.filled, 0);
  EXPECT_EQ(r.skipped, 1);
  EXPECT_EQ(m.F, input.F);
  EXPECT_EQ(m.V, input.V);
}

namespace {

// test::regular_grid(16, 16, 1) with a square hole, (6, 10)², in which some of its faces are left.
struct GridWithSquareHole {
  Mesh grid = test::regular_grid(16, 16, 1.0);
  bool in_square(int f) const {
    const Vec3 c = (grid.V.row(grid.F(f, 0)) + grid.V.row(grid.F(f, 1)) + grid.V.row(grid.F(f, 2))) / 3.0;
    return c.x() > 6 && c.x() < 10 && c.y() > 6 && c.y() < 10;
  }
  bool on_square_border(int v) const {
    const Vec3 p = grid.V.row(v).transpose();
    return !(p.x() > 6.5 && p.x() < 9.5 && p.y() > 6.5 && p.y() < 9.5);
  }
  // The faces of the square with one corner on its border and two inside.
  std::vector<int> hanging_at_one_corner() const {
    std::vector<int> faces;
    for (int f = 0; f < grid.num_faces(); ++f) {
      if (!in_square(f)) continue;
      int on_border = 0;
      for (int k = 0; k < 3; ++k) on_border += on_square_border(grid.F(f, k));
      if (on_border == 1) faces.push_back(f);
    }
    return faces;
  }
  // The grid without the square's faces except `left` (grid face indices); `row_of_left` gets their
  // rows in the result.
  Mesh holed(const std::vector<int>& left, std::vector<int>* row_of_left = nullptr) const {
    Mesh out;
    out.V = grid.V;
    std::vector<int> kept;
    for (int f = 0; f < grid.num_faces(); ++f) {
      const auto at = std::find(left.begin(), left.end(), f);
      if (at == left.end() && in_square(f)) continue;
      if (at != left.end() && row_of_left) (*row_of_left)[static_cast<std::size_t>(at - left.begin())] = static_cast<int>(kept.size());
      kept.push_back(f);
    }
    out.F.resize(static_cast<int>(kept.size()), 3);
    for (int i = 0; i < static_cast<int>(kept.size()); ++i) out.F.row(i) = grid.F.row(kept[i]);
    return out;
  }
};

int loop_count(const Mesh& m) {
  return static_cast<int>(boundary_loops(m.F, build_topology(m.F, m.num_vertices())).size());
}

}  // namespace

// A square hole in a grid with one face of the square left, hanging at a corner of the hole's border
// whose loop (as boundary_loops traces it) runs round the face too: one loop of 16 + 3 edges. The
// report names the face (HoleReport::lone_triangle). In the plane the patch wraps round it and
// the hole is filled, manifold: the face is not refused, only named (where such a hole fails, the
// reason says that repair removes it: RealHoleLoneTriangle).
TEST(FillLoneTriangle, AHoleWhoseLoopAlsoRunsRoundALoneTriangleIsFilledRoundIt) {
  const GridWithSquareHole square;
  // Keep the first face hanging at one corner whose loop boundary_loops traces into the square's.
  for (int lone : square.hanging_at_one_corner()) {
    std::vector<int> row(1);
    const Mesh holed = square.holed({lone}, &row);
    if (loop_count(holed) != 2) continue;
    FillOptions o = options_for(Continuity::G2);
    o.skip_largest = true;
    Mesh filled = holed;
    const FillReport r = fill_holes(filled, o);
    const auto hole = std::find_if(r.holes.begin(), r.holes.end(), [](const HoleReport& h) { return h.border_edges == 19; });
    ASSERT_NE(hole, r.holes.end());
    EXPECT_EQ(hole->lone_triangle, row[0]);
    EXPECT_FALSE(hole->around_a_face);
    EXPECT_EQ(hole->status, HoleStatus::filled) << hole->reason;
    EXPECT_FALSE(open_at_lone_triangle(r, *hole));
    EXPECT_TRUE(validate(filled).manifold());
    return;
  }
  FAIL() << "no face of the square is traced into the hole's loop";
}

// The same square with two of its faces left, each hanging at a corner on the square's border: one
// traced into the hole's loop, the other a loop of its own that pinches the border and, not
// selected, is not taken into the hole's patch. The hole fails at that pinch, and its reason names
// both triangles with one repair hint.
TEST(FillLoneTriangle, AHoleFailingAtOneLoneTriangleAndRunningRoundAnotherGetsOneRepairHint) {
  const GridWithSquareHole square;
  const std::vector<int> hanging = square.hanging_at_one_corner();
  for (std::size_t i = 0; i < hanging.size(); ++i)
    for (std::size_t j = i + 1; j < hanging.size(); ++j) {
      const Mesh holed = square.holed({hanging[i], hanging[j]});
      const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
      const auto traced = std::find_if(loops.begin(), loops.end(), [](const auto& l) { return l.size() == 19; });
      if (loops.size() != 3 || traced == loops.end()) continue;
      FillOptions o = options_for(Continuity::G2, FairMethod::harmonic);
      o.holes = {static_cast<int>(traced - loops.begin())};  // the other triangle's loop is not taken in
      Mesh filled = holed;
      const FillReport r = fill_holes(filled, o);
      const auto hole = std::find_if(r.holes.begin(), r.holes.end(), [](const HoleReport& h) { return h.border_edges == 19; });
      if (hole == r.holes.end() || hole->lone_triangle < 0) continue;
      EXPECT_EQ(hole->status, HoleStatus::failed);
      const std::string ending = "; the loop also runs round a lone triangle, face " +
                                 std::to_string(hole->lone_triangle) +
                                 ", hanging at a vertex it passes twice: repair splits those vertices and removes "
                                 "the lone triangles";
      EXPECT_TRUE(hole->reason.ends_with(ending)) << hole->reason;
      EXPECT_EQ(hole->reason.find("repair"), hole->reason.rfind("repair")) << hole->reason;
      EXPECT_TRUE(open_at_lone_triangle(r, *hole));
      return;
    }
  FAIL() << "no two faces of the square leave a lone triangle on the hole's loop and one beside it";
}

// The square hole with two lone triangles of their own vertices, each hanging at a vertex of the
// hole's border and pointing to the square's centre. The joint patch's loop passes both vertices
// twice. Dividing it at one of them, the programme may cut to the other, and the piece holding
// that vertex's second pass could take the cut again as a diagonal: an edge of four faces, which
// refine_patch refused ("patch edge ... is used twice in the same direction"; bench_stress --cut
// irregular --seed 1, hammer trial 30; here the two vertices (9, 6) and (10, 6)). For every pair
// of border vertices the hole is now filled, manifold, with both triangles taken in.
TEST(FillLoneTriangle, LoneTrianglesHangingAtTwoVerticesOfAHoleAreBothTakenIn) {
  const GridWithSquareHole square;
  const Mesh holed = square.holed({});
  std::vector<int> border;
  for (int v = 0; v < holed.num_vertices(); ++v) {
    const Vec3 p = holed.V.row(v).transpose();
    if (p.x() >= 6 && p.x() <= 10 && p.y() >= 6 && p.y() <= 10 && square.on_square_border(v)) border.push_back(v);
  }
  ASSERT_EQ(border.size(), 16u);
  const Vec3 centre(8, 8, 0);
  for (std::size_t i = 0; i < border.size(); ++i)
    for (std::size_t j = i + 1; j < border.size(); ++j) {
      Mesh lone = holed;
      lone.V.conservativeResize(holed.num_vertices() + 4, 3);
      lone.F.conservativeResize(holed.num_faces() + 2, 3);
      int row = holed.num_vertices();
      for (const int v : {border[i], border[j]}) {
        const Vec3 p = holed.V.row(v).transpose();
        const Vec3 d = (centre - p).normalized(), side(-d.y(), d.x(), 0);
        lone.V.row(row) = (p + 0.8 * d - 0.3 * side).transpose();
        lone.V.row(row + 1) = (p + 0.8 * d + 0.3 * side).transpose();
        lone.F.row(holed.num_faces() + (row - holed.num_vertices()) / 2) << v, row, row + 1;  // +z, as the grid
        row += 2;
      }
      FillOptions o = options_for(Continuity::G2, FairMethod::harmonic);
      o.skip_largest = true;
      Mesh filled = lone;
      const FillReport r = fill_holes(filled, o);
      for (const HoleReport& h : r.holes)
        EXPECT_NE(h.status, HoleStatus::failed) << "vertices " << border[i] << ", " << border[j] << ": " << h.reason;
      EXPECT_TRUE(validate(filled).manifold());
      EXPECT_EQ(loop_count(filled), 1);  // the grid's outer border
      EXPECT_EQ(filled.F.topRows(lone.num_faces()), lone.F);
    }
}

// Two faces of a square hole's inside left hanging at one vertex of its border (a cut through a thin
// part leaves such pieces): the piece's 4-edge loop is its whole border, with no vertex inside
// (HoleReport::hanging_piece_at, this loop's own even where the report repeats the shared patch's),
// and filled alone it would close on itself there. The hole's patch, relinked at the vertex with
// the piece's loop, takes the piece in, manifold; where the piece's loop fails, its reason says
// what the loop is (bench_stress --seed 2001, spot trial 2002: the joint patch crossed the mesh).
TEST(FillLoneTriangle, APieceWithNoVertexInsideHangingInAHoleIsTakenInOrNamed) {
  const GridWithSquareHole square;
  const Mesh& grid = square.grid;
  const Topology topo = build_topology(grid.F, grid.num_vertices());
  for (int e = 0; e < topo.edges.rows(); ++e) {
    if (topo.edge_faces.size(e) != 2) continue;
    const int a = topo.edge_faces.row(e)[0], b = topo.edge_faces.row(e)[1];
    if (!square.in_square(a) || !square.in_square(b)) continue;
    std::set<int> corners;
    for (int k = 0; k < 3; ++k) corners.insert({grid.F(a, k), grid.F(b, k)});
    const auto on_border = [&](int v) { return square.on_square_border(v); };
    if (std::count_if(corners.begin(), corners.end(), on_border) != 1) continue;
    const int hanging = *std::find_if(corners.begin(), corners.end(), on_border);
    const Mesh holed = square.holed({a, b});
    if (loop_count(holed) != 3) continue;
    FillOptions o = options_for(Continuity::G2, FairMethod::harmonic);
    o.skip_largest = true;
    const auto with_edges = [](const FillReport& r, int edges) {
      return std::find_if(r.holes.begin(), r.holes.end(), [&](const HoleReport& h) { return h.border_edges == edges; });
    };
    Mesh flat = holed;
    const FillReport taken_in = fill_holes(flat, o);
    const auto piece = with_edges(taken_in, 4), hole = with_edges(taken_in, 16);
    ASSERT_NE(piece, taken_in.holes.end());
    ASSERT_NE(hole, taken_in.holes.end());
    EXPECT_EQ(piece->hanging_piece_at, hanging);
    EXPECT_EQ(hole->hanging_piece_at, -1);
    EXPECT_EQ(taken_in.filled, 2) << piece->reason << hole->reason;
    EXPECT_TRUE(validate(flat).manifold());

    // Selected alone, the piece's loop cannot be filled (its patch would close the piece into a
    // pillow beside the hole): it fails at the pinch, and its reason says what the loop is.
    FillOptions alone = o;
    alone.holes = {piece->index};
    Mesh untouched = holed;
    const FillReport named = fill_holes(untouched, alone);
    const HoleReport& piece_alone = named.holes[static_cast<std::size_t>(piece->index)];
    EXPECT_EQ(piece_alone.status, HoleStatus::failed);
    EXPECT_EQ(piece_alone.pinched_by, hole->index);
    EXPECT_TRUE(piece_alone.reason.ends_with("; the loop is the whole border of a piece with no vertex inside that "
                                             "hangs at vertex " +
                                             std::to_string(hanging) + " (debris?): no patch took it in"))
        << piece_alone.reason;
    EXPECT_EQ(untouched.F, holed.F);
    return;
  }
  FAIL() << "no two faces of the square hang at one vertex of its border";
}

// data/cube_soup.obj: a cube's 12 triangles, unwelded, so each square face is a piece of its own
// whose border is a loop of 4 edges and which has no vertex inside. A fill could only lay each
// square again, reversed, on itself (before, all 6 were "filled" so, C0 (linear)): the loops are
// skipped with the reason, and the mesh is left as it was. The same two triangles folded along
// their diagonal are no flat piece: the loop is filled, closing them into a tetrahedron.
TEST(FillLoneTriangle, TheBorderOfAFlatPieceIsSkippedNotFilledWithThePieceReversed) {
  Mesh soup = read_mesh(test::data_path("cube_soup.obj"));
  const Mesh input = soup;
  const FillReport r = fill_holes(soup);
  ASSERT_EQ(r.holes.size(), 6u);
  for (const HoleReport& h : r.holes) {
    EXPECT_EQ(h.status, HoleStatus::skipped);
    EXPECT_EQ(h.reason.rfind("the loop is the whole border of a flat piece with no vertex inside", 0), 0u) << h.reason;
  }
  EXPECT_EQ(r.filled, 0);
  EXPECT_EQ(soup.F, input.F);
  EXPECT_EQ(soup.V, input.V);

  Mesh folded;
  folded.V.resize(4, 3);
  folded.V << 0, 0, 0, 1, 0, 0, 1, 1, 0.5, 0, 1, 0;
  folded.F.resize(2, 3);
  folded.F << 0, 1, 2, 0, 2, 3;
  FillOptions o;
  o.method = FairMethod::harmonic;
  const FillReport t = fill_holes(folded, o);
  ASSERT_EQ(t.holes.size(), 1u);
  EXPECT_EQ(t.holes[0].status, HoleStatus::filled) << t.holes[0].reason;
  EXPECT_EQ(folded.num_faces(), 4);
}

TEST(FillFolds, APatchFoldsBackBeyondARightAngleAcrossItsBorder) {
  HoleReport h;
  h.status = HoleStatus::filled;
  h.continuity.max_normal_angle = 100 * std::numbers::pi / 180;
  EXPECT_TRUE(folds_back(h));
  h.continuity.max_normal_angle = 80 * std::numbers::pi / 180;
  EXPECT_FALSE(folds_back(h));
  h.continuity.max_normal_angle = 100 * std::numbers::pi / 180;
  h.status = HoleStatus::failed;  // a failed hole has no patch
  EXPECT_FALSE(folds_back(h));
}

// The shark's hole 3 runs round a corner of the part. Its lightest triangulation crossed the
// corner's fan, and both the G2 and the C2 fairing of it crossed the mesh, so the hole fell to C1;
// the triangulation now avoids the crossing and the hole gets at least the C2 floor.
TEST(FillShark, TheHoleRoundACornerGetsTheRequestedContinuityWithoutCrossing) {
  const Mesh input = read_mesh(test::data_path("cgal_mech_holes_shark.off"));
  Mesh filled = input;
  FillOptions o;
  o.holes = {3};
  const FillReport r = fill_holes(filled, o);
  const HoleReport& h = r.holes[3];
  ASSERT_EQ(h.status, HoleStatus::filled) << h.reason;
  EXPECT_EQ(h.supported, Continuity::G2) << delivered_label(h.supported, h.linear) << ": " << h.note;
  EXPECT_FALSE(test::new_faces_cross(input, filled));
  EXPECT_LT(h.continuity.max_normal_angle, 45.0 * std::numbers::pi / 180);  // no fold (16° now)
}

// The same hole with the flow kept (keep_settled_flow): its flow's patch crosses itself (10+
// crossings), and so does the flow again with its trial states relaxed. The ∆³ fill that replaces
// them is clear of the mesh, so the flow runs once more from it, rejecting every trial that crosses
// the mesh; it settles clear of it and is delivered: G2, turning the normal across the border by
// 19° where the ∆³ floor, delivered before, turns it by 18.8°.
TEST(FillShark, AKeptFlowWhosePatchCrossesItselfIsFlowedAgainRejectingTheCrossings) {
  const Mesh input = read_mesh(test::data_path("cgal_mech_holes_shark.off"));
  FillOptions o;
  o.holes = {3};
  keep_settled_flow(o);
  Mesh filled = input;
  const HoleReport h = fill_holes(filled, o).holes[3];
  ASSERT_EQ(h.status, HoleStatus::filled) << h.reason;
  EXPECT_EQ(delivered_label(h.supported, h.linear), "G2") << h.note;
  EXPECT_NE(h.note.find("crosses the mesh"), std::string::npos) << h.note;
  EXPECT_NE(h.note.find("relaxed tangentially, which crossed too, and again with each trial that crosses the mesh "
                        "rejected"),
            std::string::npos)
      << h.note;
  EXPECT_FALSE(test::new_faces_cross(input, filled));

  o.retry_rejecting_crossings = false;
  Mesh floor = input;
  const HoleReport linear = fill_holes(floor, o).holes[3];
  ASSERT_EQ(linear.status, HoleStatus::filled) << linear.reason;
  EXPECT_EQ(delivered_label(linear.supported, linear.linear), "C2 (linear)") << linear.note;
  EXPECT_FALSE(test::new_faces_cross(input, floor));
  // The G2 fill does not fold against the floor it replaces.
  EXPECT_LT(h.continuity.max_normal_angle, 1.5 * linear.continuity.max_normal_angle);
}

// blub's 64-edge hole gets G2 (from the membrane with fair_region's defaults the G2 flow ran its
// 200 steps without settling and fell back to G1).
TEST(FillBlub, TheFilledHoleStaysCloseToTheOriginal) {
  const Mesh open = read_mesh(test::data_path("blub_open.obj"));
  const Mesh exact = read_mesh(test::data_path("blub.obj"));
  const double diagonal = (exact.V.colwise().maxCoeff() - exact.V.colwise().minCoeff()).norm();
  double flow_worst = 0, harmonic_worst = 0;
  for (const FairMethod method : {FairMethod::flow, FairMethod::harmonic}) {
    Mesh filled = open;
    const FillReport r = fill_holes(filled, options_for(Continuity::G2, method));
    ASSERT_EQ(r.filled, 1);
    EXPECT_EQ(r.holes.front().supported, Continuity::G2) << r.holes.front().note;
    expect_watertight(open, filled);
    double worst = 0, mean = 0;
    for (int v = open.num_vertices(); v < filled.num_vertices(); ++v) {
      const double d = test::distance_to_mesh(filled.V.row(v).transpose(), exact);
      worst = std::max(worst, d), mean += d;
    }
    mean /= filled.num_vertices() - open.num_vertices();
    std::cout << "blub_open, " << to_string(method) << ": " << filled.num_vertices() - open.num_vertices()
              << " new vertices, distance to blub max " << worst / diagonal << ", mean " << mean / diagonal
              << " (of the bounding-box diagonal)\n";
    EXPECT_LT(worst / diagonal, method == FairMethod::flow ? 0.05 : 0.12);
    (method == FairMethod::flow ? flow_worst : harmonic_worst) = worst;
  }
  EXPECT_LT(flow_worst, harmonic_worst);
}

// The real-hole protocol's cut of blub at (-0.565203, -0.333718, 0.0970017), radius 4 h: a 29-edge
// hole whose 6-ring fairing neighbourhood touches itself on its outer side (a vertex 6 rings out
// had two fans of kept faces), so fair_region rejected it as "1 non-manifold vertex" although the
// mesh and the patch are manifold. The neighbourhood now keeps every face of such a vertex.
TEST(FillBlub, ABallHoleWhoseFairingRingsTouchThemselvesIsFilled) {
  const Mesh holed = test::cut_ball(read_mesh(test::data_path("blub.obj")), Vec3(-0.565203, -0.333718, 0.0970017),
                                    0.153956);
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops.front().size(), 29u);
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, options_for(Continuity::G2, FairMethod::harmonic));
  ASSERT_EQ(r.filled, 1) << r.holes.front().reason;
  EXPECT_EQ(r.holes.front().supported, Continuity::G2);
  expect_watertight(holed, filled);
  EXPECT_FALSE(test::new_faces_cross(holed, filled));
}

// ---------------------------------------------------------------------------------------------
// Selection, joint holes, per-hole failures

TEST(FillSelection, ExplicitHolesMaxEdgesAndSkipLargest) {
  // A cylinder with a hole: loops are the two ends (64 edges) and the hole.
  const Mesh holed = test::cut_hole(test::open_cylinder(64, 24, 1.0, 3.0),
                                    [](const Vec3& p) { return (p - Vec3(1, 0, 1.5)).norm() < 0.4; });
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  ASSERT_EQ(loops.size(), 3u);
  int hole = 0;
  while (loops[hole].size() == 64) ++hole;

  FillOptions o = options_for(Continuity::G0);
  o.holes = {hole};
  Mesh a = holed;
  FillReport r = fill_holes(a, o);
  EXPECT_EQ(r.filled, 1);
  EXPECT_EQ(r.skipped, 2);
  for (const auto& h : r.holes)
    EXPECT_EQ(h.status == HoleStatus::filled, h.index == hole) << h.index;
  EXPECT_EQ(r.holes[(hole + 1) % 3].reason, "not selected");

  o.holes = {};
  o.max_hole_edges = 63;
  Mesh b = holed;
  r = fill_holes(b, o);
  EXPECT_EQ(r.filled, 1);
  EXPECT_EQ(r.holes[(hole + 1) % 3].reason, "64 border edges, more than the maximum 63");

  o.holes = {3};
  Mesh c = holed;
  EXPECT_THROW(
      {
        try {
          fill_holes(c, o);
        } catch (const InvalidArgument& e) {
          EXPECT_STREQ(e.what(), "fill_holes: hole 3 is outside [0, 3) (the mesh has 3 boundary loops)");
          throw;
        }
      },
      InvalidArgument);
}

TEST(FillSelection, SkipLargestLeavesTheOuterBorderOfAGrid) {
  Mesh grid = test::regular_grid(16, 16, 0.1);
  const Mesh holed = test::cut_hole(grid, [](const Vec3& p) { return (p - Vec3(0.8, 0.8, 0)).norm() < 0.25; });
  FillOptions o = options_for(Continuity::G2);
  o.skip_largest = true;
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, o);
  ASSERT_EQ(r.holes.size(), 2u);
  EXPECT_EQ(r.filled, 1);
  EXPECT_EQ(r.skipped, 1);
  for (const auto& h : r.holes)
    if (h.status == HoleStatus::skipped) {
      EXPECT_EQ(h.reason, "the largest border, left open (skip largest)");
    }
  // The patch of a planar hole stays in the plane.
  EXPECT_LT(filled.V.bottomRows(filled.num_vertices() - holed.num_vertices()).col(2).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(FillSelection, AHoleNearAnOpenBorderFallsBackAndSaysSo) {
  // The hole's border is one row from the grid's outer border, which stays open: the open border
  // falls inside the hole's three fixed rings (ring 2 or 3, depending on which border vertices touch
  // a new interior vertex), so the data supports G0 or G1 only.
  const Mesh holed = test::cut_hole(test::regular_grid(16, 16, 0.1), [](const Vec3& p) {
    return p.x() > 0.25 && p.x() < 0.55 && p.y() > 1.25 && p.y() < 1.45;
  });
  FillOptions o = options_for(Continuity::G2);
  o.skip_largest = true;
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, o);
  ASSERT_EQ(r.filled, 1);
  for (const auto& h : r.holes)
    if (h.status == HoleStatus::filled) {  // NOLINT
      EXPECT_EQ(h.requested, Continuity::G2);
      EXPECT_LT(h.supported, Continuity::G2);
      EXPECT_EQ(h.note.rfind("the mesh around the hole has fewer than 3 complete rings: faired with " +
                                 std::string(to_string(h.supported)),
                             0),
                0u)
          << h.note;
    }
}

TEST(FillJoint, HolesWithOverlappingRingsAreFilledTogether) {
  // Two holes three edges apart on a sphere: their three fixed rings overlap.
  const Mesh sphere = test::icosphere(4);
  const Mesh holed = test::cut_hole(sphere, [](const Vec3& p) {
    return (p - Vec3(0.3, 0, 0.954)).norm() < 0.2 || (p - Vec3(-0.3, 0, 0.954)).norm() < 0.2;
  });
  ASSERT_EQ(boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices())).size(), 2u);
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, options_for(Continuity::G2));
  ASSERT_EQ(r.filled, 2);
  EXPECT_EQ(r.holes[0].filled_with, std::vector<int>{1});
  EXPECT_EQ(r.holes[1].filled_with, std::vector<int>{0});
  EXPECT_EQ(r.holes[0].supported, Continuity::G2);
  EXPECT_GT(r.holes[0].vertices_added, 0);
  EXPECT_GT(r.holes[1].vertices_added, 0);
  EXPECT_EQ(r.holes[0].vertices_added + r.holes[1].vertices_added, filled.num_vertices() - holed.num_vertices());
  EXPECT_EQ(r.holes[0].faces_added + r.holes[1].faces_added, filled.num_faces() - holed.num_faces());
  expect_watertight(holed, filled);
  EXPECT_LT(max_new_vertex_deviation(filled, holed.num_vertices(),
                                     [](const Vertices& V) { return test::sphere_distances(V, 1.0); }),
            1e-3);
}

// Two square holes of a grid that touch at the vertex (6, 6) (a pinch with four border edges), and
// a third hole far from both. The faces are removed by their centroids.
Mesh grid_with_pinched_holes() {
  const Mesh grid = test::regular_grid(24, 12, 1.0);
  auto removed = [](const Vec3& c) {
    return (c.x() > 4 && c.x() < 6 && c.y() > 4 && c.y() < 6) || (c.x() > 6 && c.x() < 8 && c.y() > 6 && c.y() < 8) ||
           (c.x() > 16 && c.x() < 18 && c.y() > 4 && c.y() < 6);
  };
  Mesh holed;
  holed.V = grid.V;
  std::vector<int> kept;
  for (int f = 0; f < grid.num_faces(); ++f) {
    const Vec3 c = (grid.V.row(grid.F(f, 0)) + grid.V.row(grid.F(f, 1)) + grid.V.row(grid.F(f, 2))) / 3.0;
    if (!removed(c)) kept.push_back(f);
  }
  holed.F.resize(static_cast<int>(kept.size()), 3);
  for (int i = 0; i < static_cast<int>(kept.size()); ++i) holed.F.row(i) = grid.F.row(kept[i]);
  return holed;
}

// Both holes through the pinch are filled, and the pinch ends as an interior manifold vertex: each
// patch joins one fan of the grid to the other (closing a fan onto itself would leave two cones
// touching at the vertex).
TEST(FillPinches, TwoHolesTouchingAtAVertexAreFilledManifold) {
  const Mesh holed = grid_with_pinched_holes();
  const int pinch = 6 * 25 + 6;
  FillOptions o = options_for(Continuity::G2);
  o.skip_largest = true;
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, o);
  EXPECT_EQ(r.filled, 3);
  for (const auto& h : r.holes)
    if (h.status != HoleStatus::skipped) {
      EXPECT_EQ(h.status, HoleStatus::filled) << h.reason;
    }
  EXPECT_TRUE(filled.F.topRows(holed.num_faces()) == holed.F);
  EXPECT_TRUE(validate(filled).manifold());
  const Topology topo = build_topology(filled.F, filled.num_vertices());
  EXPECT_EQ(boundary_loops(filled.F, topo).size(), 1u);  // the grid's outer border
  EXPECT_FALSE(boundary_vertex_flags(topo)[pinch]);
  // Each hole's own patch is counted for it, though the two touch at the pinch.
  int vertices = 0, faces = 0;
  for (const auto& h : r.holes)
    if (h.status == HoleStatus::filled) {
      EXPECT_GT(h.faces_added, 0) << "hole " << h.index;
      vertices += h.vertices_added, faces += h.faces_added;
    }
  EXPECT_EQ(vertices, filled.num_vertices() - holed.num_vertices());
  EXPECT_EQ(faces, filled.num_faces() - holed.num_faces());
  // The grid stays flat: every new vertex on z = 0.
  EXPECT_LT(filled.V.bottomRows(filled.num_vertices() - holed.num_vertices()).col(2).cwiseAbs().maxCoeff(), 1e-9);
}

// Two holes touching at a corner: each one's patch alone joins the pinch's two fans, so a hole
// selected without the other is filled alone, and the pinch ends a manifold border vertex on the
// other, still open.
TEST(FillPinches, OneHoleOfAPinchIsFilledAloneWhereItsPatchJoinsTheTwoFans) {
  const Mesh holed = grid_with_pinched_holes();
  const int pinch = 6 * 25 + 6;
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  const auto loops = boundary_loops(holed.F, topo);
  std::vector<int> through_pinch, elsewhere;
  for (int i = 0; i < static_cast<int>(loops.size()); ++i) {
    if (loops[i].size() > 20) continue;  // the outer border
    (std::count(loops[i].begin(), loops[i].end(), pinch) ? through_pinch : elsewhere).push_back(i);
  }
  ASSERT_EQ(through_pinch.size(), 2u);
  ASSERT_EQ(elsewhere.size(), 1u);
  FillOptions o = options_for(Continuity::G2);
  o.holes = {through_pinch.front(), elsewhere.front()};
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, o);
  EXPECT_EQ(r.filled, 2);
  EXPECT_EQ(r.holes[elsewhere.front()].status, HoleStatus::filled);
  const HoleReport& alone = r.holes[through_pinch.front()];
  EXPECT_EQ(alone.status, HoleStatus::filled) << alone.reason;
  EXPECT_EQ(alone.pinched_by, -1);
  EXPECT_EQ(r.holes[through_pinch.back()].status, HoleStatus::skipped);
  const ValidationReport v = validate(filled);
  EXPECT_TRUE(v.manifold());
  const Topology after = build_topology(filled.F, filled.num_vertices());
  EXPECT_TRUE(boundary_vertex_flags(after)[pinch]);  // on the hole left open
  EXPECT_EQ(boundary_loops(filled.F, after).size(), 2u);
}

// The loop of grid_with_chained_pinches' hole through grid vertex (x, y), -1 if none.
int hole_through(const std::vector<std::vector<int>>& loops, int x, int y) {
  for (int i = 0; i < static_cast<int>(loops.size()); ++i)
    if (loops[i].size() > 3 && loops[i].size() < 40 && std::count(loops[i].begin(), loops[i].end(), y * 17 + x))
      return i;
  return -1;
}

// A chain of pinches: B cannot be filled where the lone triangle's loop is not (here it is not
// selected, so no patch takes the triangle in, and B's patch would close the fan beside it into a
// cone). A's patch alone joins the fans of its corner, so A is filled though B stays open.
TEST(FillPinches, AHoleTouchingAHoleThatALoneTriangleKeepsOpenIsFilledAlone) {
  const Mesh holed = test::grid_with_chained_pinches();
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  const int a = hole_through(loops, 4, 4), b = hole_through(loops, 10, 10);
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  ASSERT_NE(a, b);
  FillOptions o = options_for(Continuity::G2, FairMethod::harmonic);
  o.holes = {a, b};
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, o);
  const HoleReport& hole_b = r.holes[b];
  ASSERT_EQ(hole_b.status, HoleStatus::failed);
  ASSERT_GE(hole_b.pinched_by, 0);
  EXPECT_TRUE(r.holes[hole_b.pinched_by].around_a_face);
  EXPECT_TRUE(open_at_lone_triangle(r, hole_b));
  EXPECT_EQ(r.holes[a].status, HoleStatus::filled) << r.holes[a].reason;
  // Faired: the lone triangle's corner, a pinch of the border within A's neighbourhood, is a border
  // vertex to A's region (B's open border leaves it two complete rings: G1), not a mesh the
  // fairing refuses (it was, and A was delivered unfaired, C0).
  EXPECT_EQ(r.holes[a].supported, Continuity::G1) << r.holes[a].note;
  EXPECT_EQ(r.filled, 1);
  const ValidationReport v = validate(filled);
  EXPECT_EQ(v.non_manifold_vertices.count, 1);  // the lone triangle's corner, as in the input
  EXPECT_EQ(v.non_manifold_edges.count, 0);
}

// Repair as `fairsurf fill --repair` runs it (RepairOptions::keep_border_pinches) removes the lone
// triangle and leaves the corner where A and B touch joined: fill then closes both holes in one
// group, relinked at the corner. Repair's default splits that corner too, and A and B become one
// loop through both copies of it, which the flat patch runs into: the hole fails.
TEST(FillPinches, RepairKeepingTheBorderPinchesLetsTheChainBeFilled) {
  FillOptions o = options_for(Continuity::G2, FairMethod::harmonic);
  o.skip_largest = true;

  Mesh kept_pinch = test::grid_with_chained_pinches();
  RepairOptions for_fill;
  for_fill.keep_border_pinches = true;
  const RepairReport repaired = repair(kept_pinch, for_fill);
  EXPECT_EQ(repaired.vertices_split, 1);
  EXPECT_EQ(repaired.small_components_removed, 1);
  EXPECT_EQ(validate(kept_pinch).non_manifold_vertices.count, 1);  // the corner (6, 6)
  Mesh again = kept_pinch;
  EXPECT_FALSE(repair(again, for_fill).changed());  // a fixed point, as repair's default is
  const FillReport r = fill_holes(kept_pinch, o);
  EXPECT_EQ(r.filled, 2);
  EXPECT_EQ(r.failed, 0);
  EXPECT_TRUE(validate(kept_pinch).manifold());

  Mesh split = test::grid_with_chained_pinches();
  EXPECT_EQ(repair(split).vertices_split, 2);
  const FillReport after_split = fill_holes(split, o);
  EXPECT_EQ(after_split.failed, 1);
}

// A lone triangle hanging at a vertex of a hole's border (debris a scan or a cut leaves) pinches the
// border there. Filled alone its loop could only be the face again; filled with the hole, in one
// patch relinked at the vertex, the triangle is taken in: both loops filled, the vertex manifold,
// the triangle kept. Where the triangle's loop is not selected, the hole fails at that pinch and
// says which loop pinches it, why that one is not filled and what removes it; after repair (the
// vertex split, the lone triangle removed as a small component) it is filled.
TEST(FillPinches, AHoleWithALoneTriangleHangingAtItsBorderTakesItIn) {
  int pinch = -1;
  Mesh holed = test::sphere_hole_with_lone_triangle(&pinch);
  const auto lone_of = [](const FillReport& r) {
    return std::find_if(r.holes.begin(), r.holes.end(), [](const HoleReport& h) { return h.border_edges == 3; });
  };
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, options_for(Continuity::G2, FairMethod::harmonic));
  ASSERT_EQ(r.holes.size(), 2u);
  const auto lone = lone_of(r);
  ASSERT_NE(lone, r.holes.end());
  const HoleReport& hole = r.holes[lone == r.holes.begin() ? 1 : 0];
  EXPECT_TRUE(lone->around_a_face);
  EXPECT_FALSE(hole.around_a_face);
  EXPECT_EQ(r.filled, 2) << hole.reason << lone->reason;
  EXPECT_EQ(lone->patch_shared_with, hole.index);  // the hole, not the triangle, reports the patch
  EXPECT_EQ(hole.patch_shared_with, -1);
  EXPECT_EQ(hole.vertices_added, filled.num_vertices() - holed.num_vertices());
  EXPECT_EQ(lone->vertices_added, 0);
  EXPECT_TRUE(validate(filled).manifold());
  EXPECT_EQ(boundary_loops(filled.F, build_topology(filled.F, filled.num_vertices())).size(), 0u);
  EXPECT_EQ(filled.F.topRows(holed.num_faces()), holed.F);  // the triangle kept, with every input face

  FillOptions only_the_hole = options_for(Continuity::G2, FairMethod::harmonic);
  only_the_hole.holes = {hole.index};
  Mesh kept = holed;
  const FillReport alone = fill_holes(kept, only_the_hole);
  const auto not_selected = lone_of(alone);
  const HoleReport& failed = alone.holes[static_cast<std::size_t>(hole.index)];
  EXPECT_EQ(failed.status, HoleStatus::failed);
  EXPECT_EQ(failed.reason, "non-manifold border: vertex " + std::to_string(pinch) + " is also on hole " +
                               std::to_string(not_selected->index) + ", which is not filled (" +
                               not_selected->reason + "); repair splits the vertex and removes the lone triangle")
      << failed.reason;
  EXPECT_EQ(failed.pinched_by, not_selected->index);
  EXPECT_TRUE(open_at_lone_triangle(alone, failed));
  EXPECT_EQ(kept.F, holed.F);

  const RepairReport repaired = repair(holed);
  EXPECT_EQ(repaired.small_components_removed, 1);
  const FillReport after = fill_holes(holed, options_for(Continuity::G2, FairMethod::harmonic));
  ASSERT_EQ(after.holes.size(), 1u);
  EXPECT_EQ(after.holes[0].status, HoleStatus::filled) << after.holes[0].reason;
  const ValidationReport v = validate(holed);
  EXPECT_TRUE(v.manifold());
  EXPECT_EQ(boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices())).size(), 0u);
}

// A square annulus cut round an island of a grid, the island still joined to the rest by one
// triangle that touches it at a single vertex (4, 4): the hole's border passes through that vertex
// twice. It must stay one loop there (each pass joining the island's fan to the triangle's):
// splitting it would close the island's own fan into a cone, two disks touching at the vertex.
TEST(FillPinches, AHoleRoundAnIslandJoinedAtOneVertexIsFilledManifold) {
  const Mesh grid = test::regular_grid(12, 12, 1.0);
  Mesh holed;
  holed.V = grid.V;
  std::vector<int> kept;
  for (int f = 0; f < grid.num_faces(); ++f) {
    const Vec3 c = (grid.V.row(grid.F(f, 0)) + grid.V.row(grid.F(f, 1)) + grid.V.row(grid.F(f, 2))) / 3.0;
    const bool annulus = c.x() > 3 && c.x() < 9 && c.y() > 3 && c.y() < 9 && !(c.x() > 4 && c.x() < 8 && c.y() > 4 && c.y() < 8);
    const bool bridge = c.x() < 4 && c.y() < 3.5;  // the triangle (3,3), (4,3), (4,4)
    if (!annulus || bridge) kept.push_back(f);
  }
  holed.F.resize(static_cast<int>(kept.size()), 3);
  for (int i = 0; i < static_cast<int>(kept.size()); ++i) holed.F.row(i) = grid.F.row(kept[i]);
  const int pinch = 4 * 13 + 4;
  ASSERT_FALSE(validate(holed).manifold());  // the pinch

  FillOptions o = options_for(Continuity::G2);
  o.skip_largest = true;
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, o);
  for (const auto& h : r.holes)
    if (h.status != HoleStatus::skipped) {
      EXPECT_EQ(h.status, HoleStatus::filled) << h.reason;
    }
  EXPECT_GE(r.filled, 1);
  EXPECT_TRUE(filled.F.topRows(holed.num_faces()) == holed.F);
  EXPECT_TRUE(validate(filled).manifold());
  const Topology topo = build_topology(filled.F, filled.num_vertices());
  EXPECT_EQ(boundary_loops(filled.F, topo).size(), 1u);  // the grid's outer border
  EXPECT_FALSE(boundary_vertex_flags(topo)[pinch]);
  EXPECT_EQ(connected_components(filled.F, topo).count, 1);
  EXPECT_LT(filled.V.bottomRows(filled.num_vertices() - holed.num_vertices()).col(2).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_FALSE(test::new_faces_cross(holed, filled));
}

// The real-hole protocol's cut of blub at (-0.565203, -0.333718, 0.0970017), radius 8 h: two loops
// (37 and 26 edges) through one pinch vertex with four border edges, both reported "non-manifold
// border" before. Each loop joined a fan of the pinch to itself, so relinking makes them one loop
// through the pinch twice (one patch, counted for one of the holes). Filled, watertight, manifold
// and without crossings.
TEST(FillPinches, BlubBallHoleThroughAPinchIsFilled) {
  const Mesh holed = test::cut_ball(read_mesh(test::data_path("blub.obj")), Vec3(-0.565203, -0.333718, 0.0970017),
                                    0.307912);
  const Topology topo = build_topology(holed.F, holed.num_vertices());
  std::vector<int> border_edges(holed.num_vertices(), 0);
  for (int e = 0; e < topo.edges.rows(); ++e)
    if (topo.is_boundary_edge(e)) ++border_edges[topo.edges(e, 0)], ++border_edges[topo.edges(e, 1)];
  const auto pinches = std::count_if(border_edges.begin(), border_edges.end(), [](int c) { return c > 2; });
  ASSERT_EQ(pinches, 1);
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, options_for(Continuity::G2, FairMethod::harmonic));
  EXPECT_EQ(r.filled, static_cast<int>(r.holes.size()));
  int vertices = 0;
  for (const auto& h : r.holes) {
    EXPECT_EQ(h.status, HoleStatus::filled) << h.reason;
    vertices += h.vertices_added;
  }
  EXPECT_EQ(vertices, filled.num_vertices() - holed.num_vertices());
  expect_watertight(holed, filled);
  EXPECT_FALSE(test::new_faces_cross(holed, filled));
}

// "filled with G2" means a settled G2 flow: one that stops at its step limit is not G2. With the
// linear floor (the default) the hole keeps the ∆³ solution the flow started from, labelled so.
TEST(FillFailures, AFlowWithoutSteadyStateKeepsTheLinearFloorAndSaysSo) {
  const Mesh holed = test::cut_hole(test::icosphere(3), [](const Vec3& p) { return p.z() > 0.5; });
  FillOptions o = options_for(Continuity::G2);
  o.flow.max_steps = 1;
  o.fallback_on_failure = false;
  o.held_out_rings = 0;  // the flow itself, not the held-out choice, meets the floor
  Mesh filled = holed, floor = holed;
  const FillReport r = fill_holes(filled, o);
  ASSERT_EQ(r.filled, 1) << r.holes.front().reason;
  const HoleReport& hole = r.holes.front();
  EXPECT_TRUE(hole.linear);
  EXPECT_EQ(hole.supported, Continuity::G2);
  EXPECT_EQ(hole.steps, 0);
  EXPECT_NE(hole.note.find("the sixth-order flow did not settle (1 steps without a steady state"),
            std::string::npos) << hole.note;
  EXPECT_NE(hole.note.find("kept the linear ∆3 solution it started from"), std::string::npos) << hole.note;
  // Exactly the harmonic method's result.
  o.method = FairMethod::harmonic;
  fill_holes(floor, o);
  EXPECT_TRUE(filled.V == floor.V);
  EXPECT_TRUE(filled.F == floor.F);
}

// A sheet bent into an S with a small hole near its edge (test::s_sheet_with_hole): the two are
// filled jointly, and every patch of the outer border crosses the sheet. The joint group fails; each hole is then filled alone, so the small hole is
// closed and only the outer border fails, both saying why (lagrange_prout.obj's 9 small holes were
// left open with its outer border before).
TEST(FillFailures, AHoleOfAJointGroupThatFailedIsFilledAlone) {
  const Mesh holed = test::s_sheet_with_hole();
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  ASSERT_EQ(loops.size(), 2u);
  const int outer = loops[0].size() > loops[1].size() ? 0 : 1, inner = 1 - outer;
  Mesh filled = holed;
  const FillReport r = fill_holes(filled);
  EXPECT_EQ(r.filled, 1);
  EXPECT_EQ(r.failed, 1);
  const HoleReport& small = r.holes[inner];
  const HoleReport& border = r.holes[outer];
  EXPECT_EQ(small.status, HoleStatus::filled);
  EXPECT_TRUE(small.filled_with.empty());
  EXPECT_NE(small.note.find("the joint fill with hole " + std::to_string(outer) + " failed ("), std::string::npos)
      << small.note;
  EXPECT_NE(small.note.find("); filled alone"), std::string::npos) << small.note;
  EXPECT_GT(small.faces_added, 0);
  EXPECT_EQ(border.status, HoleStatus::failed);
  EXPECT_NE(border.reason.find("crosses the mesh"), std::string::npos) << border.reason;
  // Alone it fails as the joint fill did, and the reason is not repeated.
  EXPECT_NE(border.reason.find("; the joint fill with hole " + std::to_string(inner) + " failed too, for the same reason"),
            std::string::npos)
      << border.reason;
  // Only the outer border is left open, and the patch crosses nothing.
  const auto left = boundary_loops(filled.F, build_topology(filled.F, filled.num_vertices()));
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].size(), loops[outer].size());
  EXPECT_FALSE(test::new_faces_cross(holed, filled));
}

// Without the floor, a flow that stops at its step limit fails the hole and leaves the mesh as it was.
TEST(FillFailures, AFlowWithoutSteadyStateAndWithoutFloorIsNotAFill) {
  const Mesh holed = test::cut_hole(test::icosphere(3), [](const Vec3& p) { return p.z() > 0.5; });
  FillOptions o = options_for(Continuity::G2);
  o.flow.max_steps = 1;
  o.linear_floor = false;
  o.fallback_on_failure = false;
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, o);
  ASSERT_EQ(r.failed, 1);
  // The energy descent is told by its energy, which only falls (unsettled_reason).
  EXPECT_EQ(r.holes.front().reason.rfind("the sixth-order flow did not settle (1 steps without a steady state, E ",
                                         0), 0u) << r.holes.front().reason;
  EXPECT_TRUE(filled.V == holed.V);
  EXPECT_TRUE(filled.F == holed.F);
}

TEST(FillFailures, InvalidMeshIsRejectedWithAPreciseMessage) {
  Mesh prout = read_mesh(test::data_path("lagrange_prout.obj"));
  try {
    fill_holes(prout);
    FAIL() << "no throw";
  } catch (const InvalidMeshError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("fill_holes: mesh has ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("non-manifold edges"), std::string::npos) << e.what();
  }
}

TEST(FillFailures, APatchThatWouldCrossTheMeshIsRejectedAndTheMeshKept) {
  // A sphere with its cap removed and a separate vertical sheet standing in the hole: the patch
  // must cross the sheet.
  const Mesh holed = test::cut_hole(test::icosphere(3), [](const Vec3& p) { return p.z() > 0.5; });
  Mesh sheet = test::regular_grid(8, 8, 0.15);  // in z = 0 over [0, 1.2]^2
  Mesh mesh;
  mesh.V.resize(holed.num_vertices() + sheet.num_vertices(), 3);
  mesh.V.topRows(holed.num_vertices()) = holed.V;
  for (int v = 0; v < sheet.num_vertices(); ++v)  // rotate into the plane x = 0, centred over the hole
    mesh.V.row(holed.num_vertices() + v) << 0.0, sheet.V(v, 0) - 0.6, sheet.V(v, 1) + 0.2;
  mesh.F.resize(holed.num_faces() + sheet.num_faces(), 3);
  mesh.F.topRows(holed.num_faces()) = holed.F;
  mesh.F.bottomRows(sheet.num_faces()) = sheet.F.array() + holed.num_vertices();
  const auto loops = boundary_loops(mesh.F, build_topology(mesh.F, mesh.num_vertices()));
  ASSERT_EQ(loops.size(), 2u);
  const int hole = loops[0].front() < holed.num_vertices() ? 0 : 1;

  FillOptions o = options_for(Continuity::G0);
  o.holes = {hole};
  Mesh filled = mesh;
  const FillReport r = fill_holes(filled, o);
  EXPECT_EQ(r.failed, 1);
  EXPECT_EQ(r.holes[hole].status, HoleStatus::failed);
  EXPECT_NE(r.holes[hole].reason.find("the faired patch crosses the mesh: new face"), std::string::npos)
      << r.holes[hole].reason;
  EXPECT_TRUE(filled.V == mesh.V);
  EXPECT_TRUE(filled.F == mesh.F);

  o.check_intersections = false;  // without the check the crossing patch goes in
  EXPECT_EQ(fill_holes(filled, o).filled, 1);
}

// ---------------------------------------------------------------------------------------------
// The pair test

TEST(FaceIntersection, CrossingTouchingAndDisjointTriangles) {
  const Vec3 a0(0, 0, 0), a1(1, 0, 0), a2(0, 1, 0);
  // A triangle piercing a's interior.
  EXPECT_TRUE(triangles_cross(a0, a1, a2, Vec3(0.2, 0.2, -1), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)));
  // Its edge only touches a's plane at z = 0 (endpoint on the plane): not a crossing.
  EXPECT_FALSE(triangles_cross(a0, a1, a2, Vec3(0.2, 0.2, 0), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)));
  // Passes beside a.
  EXPECT_FALSE(triangles_cross(a0, a1, a2, Vec3(2, 2, -1), Vec3(3, 2, 1), Vec3(2, 3, 1)));
  // A's edge pierces b although no edge of b pierces a.
  EXPECT_TRUE(triangles_cross(a0, a1, a2, Vec3(0.5, -1, -1), Vec3(0.5, 2, -1), Vec3(0.5, 0.2, 3)));
  // Parallel planes.
  EXPECT_FALSE(triangles_cross(a0, a1, a2, Vec3(0, 0, 1e-3), Vec3(1, 0, 1e-3), Vec3(0, 1, 1e-3)));
}

TEST(FaceIntersection, CoplanarTrianglesCrossWhereTheirInteriorsOverlap) {
  const Vec3 a0(0, 0, 0), a1(1, 0, 0), a2(0, 1, 0);
  // In a's plane, edges crossing a's edges.
  EXPECT_TRUE(triangles_cross(a0, a1, a2, Vec3(0.2, -0.5, 0), Vec3(0.4, 0.5, 0), Vec3(-0.5, 0.2, 0)));
  // Inside a, no edge crossing: a corner inside.
  EXPECT_TRUE(triangles_cross(a0, a1, a2, Vec3(0.1, 0.1, 0), Vec3(0.3, 0.1, 0), Vec3(0.1, 0.3, 0)));
  // A copy of a (other vertices, same positions) and a turned over in the same place.
  EXPECT_TRUE(triangles_cross(a0, a1, a2, a0, a1, a2));
  EXPECT_TRUE(triangles_cross(a0, a1, a2, a0, a2, a1));
  // Beside a along its long edge, and touching it only at a corner or along an edge: no overlap.
  EXPECT_FALSE(triangles_cross(a0, a1, a2, Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)));
  EXPECT_FALSE(triangles_cross(a0, a1, a2, Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0)));
  EXPECT_FALSE(triangles_cross(a0, a1, a2, Vec3(2, 2, 0), Vec3(3, 2, 0), Vec3(2, 3, 0)));
  // Parallel planes 1e-9 apart, well above the tolerance: neither crossing nor coplanar.
  EXPECT_FALSE(triangles_cross(a0, a1, a2, Vec3(0.1, 0.1, 1e-9), Vec3(0.3, 0.1, 1e-9), Vec3(0.1, 0.3, 1e-9)));
}

TEST(FaceIntersection, FindsExactlyTheCrossingPairsOfTwoSheets) {
  // Two 4x4 grids crossing at right angles: the query faces of one meet the other along a line.
  const Mesh a = test::regular_grid(4, 4, 0.25);
  Mesh m;
  m.V.resize(2 * a.num_vertices(), 3);
  m.V.topRows(a.num_vertices()) = a.V;
  for (int v = 0; v < a.num_vertices(); ++v) m.V.row(a.num_vertices() + v) << a.V(v, 0) + 0.1, 0.4, a.V(v, 1) - 0.45;
  m.F.resize(2 * a.num_faces(), 3);
  m.F.topRows(a.num_faces()) = a.F;
  m.F.bottomRows(a.num_faces()) = a.F.array() + a.num_vertices();
  std::vector<int> query(a.num_faces());
  for (int f = 0; f < a.num_faces(); ++f) query[f] = f;
  const auto found = find_face_intersections(m.V, m.F, query);
  ASSERT_FALSE(found.empty());
  for (const auto& c : found) {
    EXPECT_LT(c.query_face, a.num_faces());
    EXPECT_GE(c.other_face, a.num_faces());
  }
  // Each query face on the line y = 0.4 crosses some face of the other sheet; none elsewhere.
  std::vector<char> crossed(a.num_faces(), 0);
  for (const auto& c : found) crossed[c.query_face] = 1;
  for (int f = 0; f < a.num_faces(); ++f) {
    double lo = 1e9, hi = -1e9;
    for (int k = 0; k < 3; ++k) lo = std::min(lo, a.V(a.F(f, k), 1)), hi = std::max(hi, a.V(a.F(f, k), 1));
    EXPECT_EQ(crossed[f] != 0, lo < 0.4 && hi > 0.4) << f;
  }
  EXPECT_EQ(find_face_intersections(m.V, m.F, query, 2).size(), 2u);
}

// The faces of one vertex removed: the fill puts a vertex back (patch_refinement.h) and fairs it
// onto the sphere, where the loop's triangulation alone would lie flat, a sagitta below it.
TEST(FillOneRing, AOneRingHoleIsFilledWithAVertexOnTheSurfaceNotFlat) {
  const Mesh sphere = test::jittered_sphere(3, 1.0, 0.02);
  const int centre = 37;
  Mesh holed = sphere;
  std::vector<int> kept;
  for (int f = 0; f < sphere.num_faces(); ++f)
    if (!(sphere.F.row(f).array() == centre).any()) kept.push_back(f);
  holed.F = sphere.F(kept, Eigen::all);
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, FillOptions{});
  ASSERT_EQ(r.filled, 1) << r.holes.front().reason;
  const HoleReport& hole = r.holes.front();
  ASSERT_EQ(hole.vertices_added, 1);
  EXPECT_NE(delivered_label(hole.supported, hole.linear), "C0 (linear)");
  // How far inside the sphere the flat triangulation lies: the depth of its ring's centroid.
  std::set<int> ring;
  for (int f = 0; f < sphere.num_faces(); ++f)
    if ((sphere.F.row(f).array() == centre).any())
      for (int k = 0; k < 3; ++k)
        if (sphere.F(f, k) != centre) ring.insert(sphere.F(f, k));
  Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
  for (const int v : ring) centroid += sphere.V.row(v) / static_cast<double>(ring.size());
  const double sagitta = 1.0 - centroid.norm();
  ASSERT_GT(sagitta, 0.0);
  const double off_sphere = std::abs(filled.V.row(filled.num_vertices() - 1).norm() - 1.0);
  EXPECT_LT(off_sphere, 0.1 * sagitta) << "sagitta " << sagitta;
}

// A loop small enough that its patch has no interior vertex is closed by its triangulation alone:
// nothing is faired, so it is labelled C0 (linear), not the continuity that was asked for.
TEST(FillLabels, APatchWithoutInteriorVertexIsLabelledC0Linear) {
  const Mesh sphere = test::icosphere(2);
  Mesh holed = sphere;
  holed.F = sphere.F.bottomRows(sphere.num_faces() - 1);  // one triangle removed: a 3-edge hole
  Mesh filled = holed;
  const FillReport r = fill_holes(filled, FillOptions{});
  ASSERT_EQ(r.filled, 1) << r.holes.front().reason;
  const HoleReport& hole = r.holes.front();
  EXPECT_EQ(hole.vertices_added, 0);
  EXPECT_EQ(hole.faces_added, 1);
  EXPECT_EQ(delivered_label(hole.supported, hole.linear), "C0 (linear)");
  EXPECT_NE(hole.note.find("the patch has no interior vertex"), std::string::npos) << hole.note;
}
