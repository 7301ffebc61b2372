// Blending (blend.h): the paper's Figs 3-4 scenes and the bundled blobby pieces are joined watertight,
// manifold and, for G2, with a mean curvature continuous across both borders.
#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/scenes.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>
#include <fairsurf/patch/tube.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <numbers>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <vector>

#include "analytic_meshes.h"
#include "hole_meshes.h"
#include "test_support.h"

namespace fairsurf {
namespace {

int loop_count(const Mesh& m) {
  return static_cast<int>(boundary_loops(m.F, build_topology(m.F, m.num_vertices())).size());
}

void print(const char* what, const BlendReport& r) {
  std::printf("[blend] %s: loops %d (%d) + %d (%d), tube %d vertices %d faces, %s, %d steps, max|V| %.3g; "
              "border a: angle %.3g rad, H jump %.3g; border b: angle %.3g rad, H jump %.3g; %.2f s\n",
              what, r.a.index, r.a.length, r.b.index, r.b.length, r.tube_vertices, r.tube_faces,
              std::string(to_string(r.fair.supported)).c_str(), r.fair.flow.accepted_steps,
              r.fair.flow.final_max_velocity, r.a.border.max_normal_angle, r.a.border.max_mean_curvature_jump,
              r.b.border.max_normal_angle, r.b.border.max_mean_curvature_jump, r.seconds);
}

// Crossings of the faces from `first_new_face` on with any face of `m`.
std::vector<FaceIntersection> new_face_crossings(const Mesh& m, int first_new_face) {
  std::vector<int> faces(m.num_faces() - first_new_face);
  for (int i = 0; i < static_cast<int>(faces.size()); ++i) faces[i] = first_new_face + i;
  return find_face_intersections(m.V, m.F, faces, 1);
}

void expect_clean(const Mesh& m) {
  const ValidationReport v = validate(m);
  EXPECT_TRUE(v.manifold());
  EXPECT_EQ(v.degenerate_faces.count, 0);
  EXPECT_EQ(v.near_degenerate_faces.count, 0);
  EXPECT_EQ(v.inconsistent_orientation_edges.count, 0);
}

// Fig 4: two caps of the unit sphere; the G2 blend with f = H must recover the sphere.
TEST(Blend, Fig4CapsOfOneSphereBlendBackToTheSphere) {
  const Scene s = make_scene("fig4", {0.15});
  Mesh m = s.mesh;
  const BlendReport r = blend_loops(m);
  print("fig4", r);
  EXPECT_TRUE(r.automatic);
  EXPECT_EQ(loop_count(m), 0);  // closed: watertight
  expect_clean(m);
  EXPECT_EQ(r.fair.supported, Continuity::G2);
  EXPECT_EQ(r.fair.flow.stop_reason, FlowStopReason::steady);
  double worst = 0;
  for (int v = s.mesh.num_vertices(); v < m.num_vertices(); ++v) worst = std::max(worst, std::abs(m.V.row(v).norm() - 1));
  std::printf("[blend] fig4: max|r - 1| on the tube %.3g\n", worst);
  EXPECT_LT(worst, 5e-3);
  for (const BlendLoop* loop : {&r.a, &r.b}) {
    EXPECT_GT(loop->border.border_vertices, 0);
    EXPECT_LT(loop->border.max_normal_angle, 0.02);
    EXPECT_LT(loop->border.max_mean_curvature_jump, 0.02);
  }
}

// A time-stepped flow that ends unsettled (here cut short at 20 of the 47 steps it needs, as real meshes' flows end at
// their step limit or throw) is continued by the energy descent, which reaches a steady state from
// its last state: E falls at every accepted descent step, and the tube still lies on the sphere.
TEST(Blend, AnUnsettledFlowIsContinuedByTheEnergyDescent) {
  const Scene s = make_scene("fig4", {0.15});
  for (const bool fallback : {false, true}) {
    Mesh m = s.mesh;
    BlendOptions o;
    o.flow.max_steps = 20;
    o.descent_fallback = fallback;
    std::vector<double> energies;
    const BlendReport r = blend_loops(m, o, [&](const StepRecord& step) {
      if (step.accepted) energies.push_back(step.energy);
    });
    print(fallback ? "fig4, 20 steps + descent" : "fig4, 20 steps", r);
    EXPECT_EQ(r.fair.supported, Continuity::G2);
    EXPECT_FALSE(r.fair.linear);
    if (!fallback) {
      EXPECT_EQ(r.fair.flow.stop_reason, FlowStopReason::max_steps);
      EXPECT_TRUE(r.fair.note.empty()) << r.fair.note;
      continue;
    }
    EXPECT_EQ(r.fair.flow.stop_reason, FlowStopReason::steady);
    EXPECT_NE(r.fair.note.find("the energy descent continued from "), std::string::npos) << r.fair.note;
    ASSERT_GT(r.fair.flow.accepted_steps, 0);
    ASSERT_GE(energies.size(), 2u + r.fair.flow.accepted_steps);
    const auto descent = energies.end() - r.fair.flow.accepted_steps;
    EXPECT_LT(r.fair.flow.final_energy, r.fair.flow.initial_energy);
    EXPECT_TRUE(std::is_sorted(descent, energies.end(), std::greater<>()));
    double worst = 0;
    for (int v = s.mesh.num_vertices(); v < m.num_vertices(); ++v) worst = std::max(worst, std::abs(m.V.row(v).norm() - 1));
    EXPECT_LT(worst, 5e-3);
    for (const BlendLoop* loop : {&r.a, &r.b}) EXPECT_LT(loop->border.max_normal_angle, 0.02);
  }
}

// Fig 3: a cap above a disk with a hole; the tube joins the hole and the cap's rim (not the disk's
// outer loop), the result keeps one loop, and the G2 tube leaves the disk tangentially where the
// membrane kinks (0.031 against 0.53 rad).
TEST(Blend, Fig3CapAboveADiskWithAHole) {
  const Scene s = make_scene("fig3", {0.15});
  Mesh m = s.mesh;
  BlendOptions g2;
  g2.flow.steady_relative_tolerance = 1e-12;
  const BlendReport r = blend_loops(m, g2);
  print("fig3", r);
  const auto loops = boundary_loops(s.mesh.F, build_topology(s.mesh.F, s.mesh.num_vertices()));
  EXPECT_EQ(loops[r.a.index], s.blend_loops[0]);
  EXPECT_EQ(loops[r.b.index], s.blend_loops[1]);
  EXPECT_EQ(loop_count(m), 1);
  expect_clean(m);
  EXPECT_TRUE(r.relaxed);

  Mesh membrane = s.mesh;
  BlendOptions g0;
  g0.method = FairMethod::harmonic;
  g0.continuity = Continuity::G0;
  const BlendReport m0 = blend_loops(membrane, g0);
  print("fig3 membrane (harmonic G0)", m0);
  EXPECT_LT(r.a.border.max_normal_angle, 0.1);
  EXPECT_LT(r.b.border.max_normal_angle, 0.1);
  EXPECT_LT(r.a.border.max_normal_angle, 0.5 * m0.a.border.max_normal_angle);
  // The H jump at the disk is not a measurement floor: the same fits read exactly 0 on the flat
  // disk. It is the discrete solution's: its H rises from 0 to 0.9 within 0.2 of the hole, and the
  // jump falls like 2.4 h^(1/2) under refinement (0.88, 0.78, 0.67, 0.54 at h = 0.15, 0.1, 0.075,
  // 0.05; docs/blend.md), which puts it at 0.93 here.
  EXPECT_EQ(r.a.reference.max_mean_curvature_jump, 0.0);
  EXPECT_LT(r.a.border.max_mean_curvature_jump, 1.0);
  EXPECT_LT(r.b.border.max_mean_curvature_jump, 1.0);
}

// Fig 3 reaches G2 only in the limit: halving h lowers the mean H jump at the disk by 1.31
// (h^0.39) and at the cap by 3.2 (h^1.7), and the normal angles with them.
TEST(Blend, Fig3JumpsFallUnderRefinement) {
  BlendReport coarse, fine;
  for (auto [h, report] : {std::pair{0.15, &coarse}, std::pair{0.075, &fine}}) {
    Mesh m = make_scene("fig3", {h}).mesh;
    *report = blend_loops(m);
    print(h == 0.15 ? "fig3 h = 0.15" : "fig3 h = 0.075", *report);
    EXPECT_EQ(report->fair.flow.stop_reason, FlowStopReason::steady);
  }
  const double disk = coarse.a.border.mean_mean_curvature_jump / fine.a.border.mean_mean_curvature_jump;
  const double cap = coarse.b.border.mean_mean_curvature_jump / fine.b.border.mean_mean_curvature_jump;
  std::printf("[blend] fig3: mean H jump ratio h = 0.15 / 0.075: disk %.3g, cap %.3g\n", disk, cap);
  EXPECT_GT(disk, 1.15);
  EXPECT_GT(cap, 2.0);
  EXPECT_LT(fine.a.border.max_normal_angle, 0.6 * coarse.a.border.max_normal_angle);
  EXPECT_LT(fine.b.border.max_normal_angle, 0.6 * coarse.b.border.max_normal_angle);
}

// Real data: the three blobby pieces, joined where their borders face each other (both pairs).
// Their mesh is coarse for its curvature (edge × curvature up to 0.4), so one-sided fits read up to
// 15° and an H jump of 25 on the untouched input 3 rings from each loop; the blend's borders read
// the same (mean angle within 1.5 times the input's), a G0 blend 3 to 6 times more.
TEST(Blend, BlobbyPiecesJoinIntoOneClosedSurface) {
  Mesh m = read_mesh(test::data_path("cgal_blobby_3cc.off"));
  EXPECT_EQ(loop_count(m), 4);
  const BlendReport first = blend_loops(m);
  print("blobby pair 1", first);
  EXPECT_EQ(loop_count(m), 2);
  const BlendReport second = blend_loops(m);
  print("blobby pair 2", second);
  EXPECT_EQ(loop_count(m), 0);
  expect_clean(m);
  const Topology topo = build_topology(m.F, m.num_vertices());
  EXPECT_EQ(connected_components(m.F, topo).count, 1);
  for (const BlendReport* r : {&first, &second}) {
    EXPECT_EQ(r->fair.flow.stop_reason, FlowStopReason::steady);
    for (const BlendLoop* loop : {&r->a, &r->b}) {
      std::printf("[blend] blobby loop %d: mean normal angle %.3g (input %.3g), max %.3g (input %.3g)\n",
                  loop->index, loop->border.mean_normal_angle, loop->reference.mean_normal_angle,
                  loop->border.max_normal_angle, loop->reference.max_normal_angle);
      EXPECT_LE(loop->border.border_vertices, loop->length);  // its own loop only (both before)
      EXPECT_GE(loop->border.border_vertices, loop->length - 2);
      EXPECT_GT(loop->reference.border_vertices, 0);
      EXPECT_LT(loop->border.mean_normal_angle, 1.5 * loop->reference.mean_normal_angle);
      EXPECT_LT(loop->border.max_normal_angle, 1.5 * loop->reference.max_normal_angle);
    }
  }
  Mesh membrane = read_mesh(test::data_path("cgal_blobby_3cc.off"));
  BlendOptions g0;
  g0.continuity = Continuity::G0;
  const BlendReport m0 = blend_loops(membrane, g0);
  EXPECT_GT(m0.a.border.mean_normal_angle, 2.0 * m0.a.reference.mean_normal_angle);
}

// blend_all_loops joins the blobby's two gaps in one call, exactly as two blend_loops calls do, and
// refuses a named pair (it chooses each pair itself).
TEST(Blend, AllLoopsAreJoinedPairByPairAsSuccessiveBlendsJoinThem) {
  const Mesh input = read_mesh(test::data_path("cgal_blobby_3cc.off"));
  Mesh one_by_one = input;
  blend_loops(one_by_one);
  blend_loops(one_by_one);
  Mesh all = input;
  const BlendAllReport report = blend_all_loops(all);
  ASSERT_EQ(report.blends.size(), 2u);
  EXPECT_EQ(report.blends[0].loops_found, 4);
  EXPECT_EQ(report.blends[1].loops_found, 2);
  EXPECT_TRUE(report.blends[0].automatic);
  EXPECT_GT(report.blends[0].loop_distance, 0.0);
  EXPECT_TRUE(report.unjoined.empty());
  EXPECT_EQ(report.loops_left, 0);
  EXPECT_EQ(loop_count(all), 0);
  EXPECT_TRUE(all.V == one_by_one.V);
  EXPECT_TRUE(all.F == one_by_one.F);
  BlendOptions named;
  named.loop_a = 0;
  named.loop_b = 3;
  Mesh refused = input;
  EXPECT_THROW(blend_all_loops(refused, named), InvalidArgument);
  EXPECT_TRUE(refused.V == input.V);
}

// Two capsules, each cut across by a slab; a thin closed disk lies in the narrower gap
// (test::capsules_one_gap_blocked), so that pair, the closest, cannot be joined: every tube through it crosses the disk. blend_all_loops
// leaves that pair as it was, joins the other, and pairs neither loop of the first with a loop of
// the second capsule, far away.
TEST(Blend, AllLoopsLeavesAPairThatCannotBeJoinedOpenAndJoinsTheOthers) {
  const Mesh input = test::capsules_one_gap_blocked();
  ASSERT_EQ(loop_count(input), 4);

  Mesh all = input;
  const BlendAllReport report = blend_all_loops(all);
  ASSERT_EQ(report.unjoined.size(), 1u);
  ASSERT_EQ(report.blends.size(), 1u);
  EXPECT_EQ(report.loops_left, 2);
  const UnjoinedLoops& unjoined = report.unjoined.front();
  EXPECT_NE(unjoined.why.find("crosses the mesh"), std::string::npos) << unjoined.why;
  EXPECT_FALSE(unjoined.repairable);
  const std::vector<std::vector<int>> left = boundary_loops(all.F, build_topology(all.F, all.num_vertices()));
  ASSERT_EQ(left.size(), 2u);
  for (int index : {unjoined.loop_a, unjoined.loop_b})
    for (int v : left[index]) EXPECT_GT(all.V(v, 0), 3.0);  // both on the blocked capsule
  EXPECT_EQ(unjoined.length_a, static_cast<int>(left[unjoined.loop_a].size()));

  // The mesh is the input with the open capsule's pair joined, as blend_loops joins it alone.
  const BlendReport& joined = report.blends.front();
  EXPECT_TRUE(joined.automatic);
  BlendOptions that_pair;
  that_pair.loop_a = joined.a.index;
  that_pair.loop_b = joined.b.index;
  Mesh alone = input;
  blend_loops(alone, that_pair);
  EXPECT_TRUE(all.V == alone.V);
  EXPECT_TRUE(all.F == alone.F);
  EXPECT_TRUE(all.V.topRows(input.num_vertices()) == input.V);
  EXPECT_TRUE(new_face_crossings(all, input.num_faces()).empty());
  expect_clean(all);

  Mesh closed = test::ellipsoid(2, 1, 1, 1);
  EXPECT_THROW(blend_all_loops(closed), InvalidMeshError);
}

// Two holes of a sphere that touch at a vertex (test::sphere_with_two_holes_touching): no tube starts
// from both. blend_all_loops leaves them open, says repair mends them, and changes nothing.
TEST(Blend, AllLoopsLeavesLoopsThatTouchOpenAndSaysRepairSplitsThem) {
  const Mesh input = test::sphere_with_two_holes_touching();
  ASSERT_EQ(loop_count(input), 2);
  Mesh all = input;
  const BlendAllReport report = blend_all_loops(all);
  EXPECT_TRUE(report.blends.empty());
  ASSERT_EQ(report.unjoined.size(), 1u);
  EXPECT_TRUE(report.unjoined.front().repairable);
  EXPECT_NE(report.unjoined.front().why.find("share vertex"), std::string::npos) << report.unjoined.front().why;
  EXPECT_EQ(report.loops_left, 2);
  EXPECT_TRUE(all.V == input.V);
  EXPECT_TRUE(all.F == input.F);
}

// Real data: two adjacent ends of fairing_cross.off face away from each other, so the tube turns
// by 3π/2 (a handle around the corner). The Hermite tube follows concentric arcs about the corner
// instead of folding flat, the membrane (no minimal surface spans ends 3.5 apart of radius 0.68)
// pinches off and is discarded, and the flow starts from the Hermite tube. f = H has no steady
// state on so long a handle (it beads into spheres of radius 1/|H| joined by thinning necks), so
// this runs 15 steps.
TEST(Blend, FairingCrossAdjacentEndsJoinByAHandle) {
  Mesh m = read_mesh(test::data_path("fairing_cross.off"));
  BlendOptions o;
  o.flow.max_steps = 15;
  o.descent_fallback = false;  // the time-stepped flow's 15th state, not a steady one
  const BlendReport r = blend_loops(m, o);
  print("fairing_cross", r);
  std::printf("[blend] fairing_cross: tube quality %.3g, membrane %.3g; energy %.4g -> %.4g\n", r.hermite_quality,
              r.membrane_quality, r.fair.flow.initial_energy, r.fair.flow.final_energy);
  EXPECT_EQ(r.a.index, 0);
  EXPECT_EQ(r.b.index, 1);
  EXPECT_FALSE(r.relaxed);
  EXPECT_LT(r.membrane_quality, 1e-6);
  EXPECT_GT(r.hermite_quality, 0.25);
  EXPECT_EQ(r.fair.flow.accepted_steps, 15);
  EXPECT_LT(r.fair.flow.final_energy, 0.05 * r.fair.flow.initial_energy);
  EXPECT_EQ(loop_count(m), 2);  // the two other ends
  expect_clean(m);
  EXPECT_EQ(connected_components(m.F, build_topology(m.F, m.num_vertices())).count, 1);
  for (const BlendLoop* loop : {&r.a, &r.b}) {
    EXPECT_LE(loop->border.border_vertices, loop->length);
    EXPECT_LT(loop->border.max_normal_angle, 0.1);
    EXPECT_LT(loop->border.max_mean_curvature_jump, 0.5);
  }
}

// With the defaults, the time-stepped flow on that handle diverges towards its beads (200 steps,
// max|V| 1.9e11); the energy descent from the Hermite tube it started from settles in a few steps at
// a lower energy than the descent from the beads, and keeps the handle round: every tube vertex lies
// within 1.4 of the centre circle of the 3π/2 arc (radius 2.5 about (−1, −1, 0); the ends' radius is
// 0.68), where the beads reach 2.2 from it.
TEST(Blend, FairingCrossDefaultsKeepTheHandleRound) {
  const Mesh cross = read_mesh(test::data_path("fairing_cross.off"));
  Mesh m = cross;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("fairing_cross, defaults", r);
  EXPECT_FALSE(r.fair.linear);
  EXPECT_EQ(r.fair.flow.stop_reason, FlowStopReason::steady);
  EXPECT_NE(r.fair.note.find("the energy descent continued from the tube it started from"), std::string::npos)
      << r.fair.note;
  double farthest = 0;
  for (int v = cross.num_vertices(); v < m.num_vertices(); ++v) {
    const Eigen::Vector3d p = m.V.row(v).transpose() - Eigen::Vector3d(-1, -1, 0);
    farthest = std::max(farthest, std::hypot(std::hypot(p.x(), p.y()) - 2.5, p.z()));
  }
  std::printf("[blend] fairing_cross, defaults: farthest tube vertex %.3f from the arc's centre circle\n", farthest);
  EXPECT_LT(farthest, 1.4);
  expect_clean(m);
  EXPECT_TRUE(new_face_crossings(m, cross.num_faces()).empty());
}

// The Hermite tube between the cross's ends 0 and 1 is a handle around the corner, not a fold: every
// ring keeps the ends' width (the per-point chord tangents used before flattened the middle rings
// to a sheet) and stays about the circle of radius 2.5 about (−1, −1, 0), the centre line of the
// 3π/2 arc (the cubic strays up to 27% from it at its quarter points).
TEST(Blend, HermiteTubeAroundACornerKeepsItsWidth) {
  const Mesh m = read_mesh(test::data_path("fairing_cross.off"));
  const Topology topo = build_topology(m.F, m.num_vertices());
  const auto loops = boundary_loops(m.F, topo);
  const Tube tube = build_tube(m.V, m.F, topo, loops[0], loops[1]);
  ASSERT_EQ(loops[0].size(), loops[1].size());
  const int per_ring = static_cast<int>(loops[0].size());
  ASSERT_EQ(static_cast<int>(tube.ring_vertices.size()), tube.rings * per_ring);
  double low = 1e9, high = -1e9;
  for (int v : loops[0]) low = std::min(low, m.V(v, 1)), high = std::max(high, m.V(v, 1));
  const double end_width = high - low;  // loop 0 lies in the plane x = −1, across y
  double narrowest = 1e9, worst_centre = 0;
  for (int r = 0; r < tube.rings; ++r) {
    double inner = 1e9, outer = -1e9, mean = 0;
    for (int k = 0; k < per_ring; ++k) {
      const int v = tube.ring_vertices[r * per_ring + k];
      const double rho = std::hypot(tube.V(v, 0) + 1, tube.V(v, 1) + 1);
      inner = std::min(inner, rho), outer = std::max(outer, rho), mean += rho / per_ring;
    }
    narrowest = std::min(narrowest, (outer - inner) / end_width);
    worst_centre = std::max(worst_centre, std::abs(mean / 2.5 - 1));
  }
  std::printf("[blend] cross tube: %d rings, narrowest ring %.3g of the end's width, centre off the arc by %.3g\n",
              tube.rings, narrowest, worst_centre);
  EXPECT_GT(narrowest, 0.9);
  EXPECT_LT(worst_centre, 0.3);
}

TEST(Blend, ConcatenationKeepsTheFirstMeshFirst) {
  const Mesh a = icosphere(0), b = icosphere(1, 2.0);
  const Mesh c = concatenate_meshes(a, b);
  EXPECT_EQ(c.V.topRows(12), a.V);
  EXPECT_EQ(c.V.bottomRows(42), b.V);
  EXPECT_EQ(c.F.topRows(20), a.F);
  EXPECT_EQ(Faces(c.F.bottomRows(80).array() - 12), b.F);
}

TEST(Blend, ContinuityAtAVertexOutOfRangeIsRefused) {
  const Mesh sphere = icosphere(1);
  const std::vector<int> free{0}, at{42};
  try {
    measure_continuity(sphere.V, sphere.F, free, at);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "measure_continuity: vertex 42 is out of range");
  }
}

// blend_loops refuses `mesh` with RepairableMeshError(`message`) and leaves it as it was.
void expect_refused_for_repair(Mesh mesh, const char* message) {
  const Mesh given = mesh;
  try {
    blend_loops(mesh);
    FAIL() << "no throw";
  } catch (const RepairableMeshError& e) {
    EXPECT_STREQ(e.what(), message);
  }
  EXPECT_EQ(mesh.V, given.V);
  EXPECT_EQ(mesh.F, given.F);
}

TEST(Blend, ClearErrors) {
  Mesh closed = icosphere(1);
  try {
    blend_loops(closed);
    FAIL();
  } catch (const InvalidMeshError& e) {
    EXPECT_STREQ(e.what(), "blend_loops: the mesh has 0 boundary loops; blending needs two");
  }
  Mesh fig4 = make_scene("fig4", {0.3}).mesh;
  BlendOptions o;
  o.loop_a = 0;
  o.loop_b = 5;
  try {
    blend_loops(fig4, o);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "blend_loops: loop 5 is out of range; the mesh has 2 boundary loops: 0 (18 vertices), "
                           "1 (18 vertices)");
  }
  o.loop_b = 0;
  EXPECT_THROW(blend_loops(fig4, o), InvalidArgument);
  BlendOptions relaxed;
  relaxed.crossing_retry_relaxation = 1.5;
  const Mesh untouched = fig4;
  try {
    blend_loops(fig4, relaxed);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "blend_loops: crossing_retry_relaxation must lie in [0, 1], got 1.500000");
  }
  EXPECT_EQ(fig4.V, untouched.V);

  // data/lagrange_prout.obj's closest loops pass through one vertex: a non-manifold vertex, which
  // repair splits (before, build_tube's InvalidArgument, exit 1 in the CLI, with no hint).
  expect_refused_for_repair(read_mesh(test::data_path("lagrange_prout.obj")),
                            "blend_loops: loops 5 and 12 share vertex 883, a non-manifold vertex where the two "
                            "borders touch; no tube starts from both");

  // A band across spot through vertex 182 (bench_stress --section blend --seed 4242's third slab)
  // leaves two pieces that touch at one vertex, and the 74-edge loop passes through it twice: a tube
  // from that loop used its border edges there twice (before, refine_patch's "patch edge ... is used
  // twice in the same direction", exit 3 with no hint).
  const Mesh spot = read_mesh(test::data_path("spot.obj"));
  expect_refused_for_repair(test::cut_slab(spot, spot.V.row(182).transpose(),
                                           Eigen::Vector3d(0.659, 0.733, -0.170).normalized(),
                                           2 * test::mean_edge_length(spot)),
                            "blend_loops: loop 0 passes through vertex 2183 twice, a non-manifold vertex where "
                            "its border pinches; no tube starts from it");
}

// Mean distance of the tube's vertices (from `first_tube_vertex` on) to the uncut mesh, in h.
double tube_distance(const Mesh& m, int first_tube_vertex, const Mesh& uncut, double h) {
  double sum = 0;
  for (int v = first_tube_vertex; v < m.num_vertices(); ++v) sum += test::distance_to_mesh(m.V.row(v).transpose(), uncut);
  return sum / (m.num_vertices() - first_tube_vertex) / h;
}

// data/`file` and that mesh with a band 4 h wide cut across it (h: its mean edge length), centred on
// the plane through `point` normal to `axis` (test::cut_slab), as bench_real_holes' slabs.
struct Band {
  Mesh uncut;
  double h = 0;
  Mesh cut;
};

Band band_across(const char* file, const Eigen::Vector3d& point, const Eigen::Vector3d& axis) {
  Band b{read_mesh(test::data_path(file)), 0, {}};
  b.h = test::mean_edge_length(b.uncut);
  b.cut = test::cut_slab(b.uncut, point, axis, 2 * b.h);
  return b;
}

// Band `b` blended into `out` from the G0 membrane only (rebuild_without_membrane off).
BlendReport blend_from_membrane_only(const Band& b, Mesh& out) {
  BlendOptions once;
  once.rebuild_without_membrane = false;
  out = b.cut;
  return blend_loops(out, once);
}

// The blend `m` of band `b` closes the cut: its tube crosses nothing, the mesh is clean (expect_clean)
// and no loop is left.
void expect_band_closed(const Mesh& m, const Band& b) {
  EXPECT_TRUE(new_face_crossings(m, b.cut.num_faces()).empty());
  expect_clean(m);
  EXPECT_EQ(loop_count(m), 0);
}

// A G2 blend delivered as a linear tube of a lower continuity, for a crossing (crossing_fallback).
void expect_lower_linear_tube(const BlendReport& r) {
  EXPECT_TRUE(r.fair.linear);
  EXPECT_TRUE(r.fair.crossing_fallback);
  EXPECT_EQ(r.fair.requested, Continuity::G2);
  EXPECT_LT(r.fair.supported, Continuity::G2);
}

// A band of width 4h cut across blub (bench_real_holes' blub 517 y), started from the G0 membrane
// only: the time-stepped flow diverges, and the energy descent from its last state settles into a
// tube that passes through itself (49 crossings); from the linear ∆³ tube, with the trials that
// would cross rejected, it settles at a lower energy than from the tube as built, without crossing.
// That G2 tube turns the normal across the loops by 99.6° where the linear tube turns it by 86.3°:
// no gain in smoothness there, and it lies a little farther from blub's surface (0.0388 h against
// 0.0378 h), so the linear tube is delivered, with both reasons in the note.
TEST(BlendReal, AnUnsettledFlowDescendsFromTheLinearTubeWithoutCrossing) {
  const Band b = band_across("blub.obj", {0.280928, -0.0196544, 0.897816}, Eigen::Vector3d::UnitY());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m;
  const BlendReport r = blend_from_membrane_only(b, m);
  print("blub band", r);
  EXPECT_TRUE(r.fair.flow_folded_back);
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "C2 (linear)");
  EXPECT_NE(r.fair.note.find("the energy descent continued from the linear ∆3 tube"), std::string::npos)
      << r.fair.note;
  EXPECT_NE(r.fair.note.find("the sixth-order flow's tube turns the normal across the loops by "), std::string::npos)
      << r.fair.note;
  EXPECT_NE(r.fair.note.find("kept the linear ∆3 tube"), std::string::npos) << r.fair.note;
  expect_band_closed(m, b);

  BlendOptions linear_options;
  linear_options.method = FairMethod::harmonic;
  Mesh linear = b.cut;
  const BlendReport l = blend_loops(linear, linear_options);
  EXPECT_EQ(m.V, linear.V);  // the linear tube itself
  EXPECT_EQ(r.fair.continuity.max_normal_angle, l.fair.continuity.max_normal_angle);
}

// The same band with the defaults: the linear tube kept in place of the G2 tube that folds back
// comes from the same membrane and turns the normal across the loops by 86.3°, where the input
// reads 32°. So the blend runs again from the Hermite tube (rebuild_without_membrane), as where the
// delivered tube folds back itself: its linear tube turns it by 29.5° and lies 0.028 h from blub,
// against the membrane's 0.038 h. (Its G2 tube turns it by 33.5°, more than the linear one, so the
// linear tube is kept there too.)
TEST(BlendReal, ALinearTubeKeptInPlaceOfAFlowThatFoldsBackIsBuiltAgainFromTheHermiteTube) {
  const Band b = band_across("blub.obj", {0.280928, -0.0196544, 0.897816}, Eigen::Vector3d::UnitY());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh from_membrane;
  const BlendReport f = blend_from_membrane_only(b, from_membrane);
  ASSERT_TRUE(f.relaxed);
  ASSERT_TRUE(f.fair.flow_folded_back);
  ASSERT_FALSE(folds_back(f.a) || folds_back(f.b));  // the old rule alone would not build again

  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("blub band, built again", r);
  EXPECT_TRUE(r.rebuilt_without_membrane);
  EXPECT_FALSE(r.relaxed);
  EXPECT_EQ(r.fair.note.rfind("the flow's tube from the G0 membrane folds back (the linear tube kept in its "
                              "place turns the normal across the loops by 86.3 deg); built again from the Hermite "
                              "tube, which turns it by ",
                              0),
            0u)
      << r.fair.note;
  const auto largest = [](const BlendReport& x) {
    return std::max(x.a.border.max_normal_angle, x.b.border.max_normal_angle);
  };
  const auto reference = [](const BlendReport& x) {
    return std::max(x.a.reference.max_normal_angle, x.b.reference.max_normal_angle);
  };
  EXPECT_GT(largest(f), 1.5 * reference(f));  // folded by bench_real_holes' rule
  EXPECT_LT(largest(r), 1.5 * reference(r));  // not any more
  expect_band_closed(m, b);
  const double rebuilt = tube_distance(m, b.cut.num_vertices(), b.uncut, b.h);
  const double membrane = tube_distance(from_membrane, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] blub band: %.4f h from blub built again, %.4f h from the membrane\n", rebuilt, membrane);
  EXPECT_LT(rebuilt, 0.9 * membrane);
}

// A band across blub's tail fin (bench_real_holes --all-slabs' blub 1097 z): the G0 membrane lies
// against one side of the fin, and the tube from it folds back at a loop (103° across it where the
// untouched input reads 6°), 0.21 h from blub. Built again from the Hermite tube (what
// rebuild_without_membrane does) it turns the normal by 65° and lies 0.053 h from blub.
TEST(BlendReal, ATubeFromTheMembraneThatFoldsBackIsBuiltAgainFromTheHermiteTube) {
  const Mesh blub = read_mesh(test::data_path("blub.obj"));
  const Band b = band_across("blub.obj", blub.V.row(1097).transpose(), Eigen::Vector3d::UnitZ());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh folded;
  const BlendReport f = blend_from_membrane_only(b, folded);
  ASSERT_TRUE(f.relaxed);
  ASSERT_TRUE(folds_back(f.a) || folds_back(f.b));

  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("blub fin band", r);
  EXPECT_TRUE(r.rebuilt_without_membrane);
  EXPECT_FALSE(r.relaxed);
  EXPECT_FALSE(folds_back(r.a) || folds_back(r.b));
  const auto largest = [](const BlendReport& x) {
    return std::max(x.a.border.max_normal_angle, x.b.border.max_normal_angle);
  };
  EXPECT_LT(largest(r), largest(f));
  EXPECT_EQ(r.fair.note.rfind("the tube from the G0 membrane folds back", 0), 0u) << r.fair.note;
  expect_band_closed(m, b);
  const double rebuilt = tube_distance(m, b.cut.num_vertices(), b.uncut, b.h);
  const double membrane = tube_distance(folded, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] blub fin band: %.3f h from blub rebuilt, %.3f h from the membrane\n", rebuilt, membrane);
  EXPECT_LT(rebuilt, 0.5 * membrane);
}

// A band across spot's body (bench_real_holes' spot 2099 y): the time-stepped flow does not settle
// (it diverged before the flow limited the term of unresolved curvature; now its max|V| falls over
// its 200 steps). The energy descent that continues from it turns the normal across the loops by
// 11–12° where the linear tube turns it by 8.8°: it folds against the linear tube, which lies
// closer to spot (0.032 h), and the linear tube is delivered. (Which of the descent's starts wins,
// the flow's last state or the tube it started from, and so the angle, depends on the machine: the
// unsettled flow's last state carries its rounding, amplified over 200 steps.)
TEST(BlendReal, ADescentThatFoldsAgainstTheLinearTubeIsNotKept) {
  const Band b = band_across("spot.obj", {-0.293232, 0.0711038, 0.460405}, Eigen::Vector3d::UnitY());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  std::printf("[blend] spot band: %s\n", r.fair.note.c_str());
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "C2 (linear)");
  EXPECT_TRUE(r.fair.checks_chose_linear);  // the angle rule, which keep_settled_flow switches off
  EXPECT_NE(r.fair.note.find("the energy descent continued from"), std::string::npos) << r.fair.note;
  const std::string rule = "the sixth-order flow's tube turns the normal across the loops by ";
  const std::size_t at = r.fair.note.find(rule);
  ASSERT_NE(at, std::string::npos) << r.fair.note;
  const double angle = std::stod(r.fair.note.substr(at + rule.size()));
  EXPECT_GT(angle, 1.05 * 8.84) << r.fair.note;
  EXPECT_NE(r.fair.note.find("°, more than the linear tube (8.84°)", at), std::string::npos) << r.fair.note;
  EXPECT_TRUE(new_face_crossings(m, b.cut.num_faces()).empty());
  const double delivered = tube_distance(m, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] spot band: tube %.4f h from the uncut mesh\n", delivered);
  EXPECT_LT(delivered, 0.04);
}

// The same band with keep_settled_flow: the descent's settled G2 tube is delivered though it turns
// the normal across the loops more than the linear tube; it stays clear of the mesh, and lies
// farther from spot than the linear tube (the trade docs/blend.md describes).
TEST(BlendReal, KeepingTheSettledFlowDeliversTheG2TubeTheAngleRuleRefuses) {
  const Band b = band_across("spot.obj", {-0.293232, 0.0711038, 0.460405}, Eigen::Vector3d::UnitY());
  Mesh m = b.cut;
  BlendOptions o;
  keep_settled_flow(o);
  EXPECT_FALSE(o.weigh_against_linear_tube);
  const BlendReport r = blend_loops(m, o);
  std::printf("[blend] spot band, flow kept: %s\n", r.fair.note.c_str());
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "G2");
  EXPECT_EQ(r.fair.flow.stop_reason, FlowStopReason::steady);
  EXPECT_EQ(r.fair.note.find("kept the linear"), std::string::npos) << r.fair.note;
  EXPECT_FALSE(r.fair.checks_chose_linear);
  EXPECT_GT(r.fair.continuity.max_normal_angle, 1.05 * 8.84 * std::numbers::pi / 180);
  EXPECT_TRUE(new_face_crossings(m, b.cut.num_faces()).empty());
  const double kept = tube_distance(m, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] spot band, flow kept: tube %.4f h from the uncut mesh\n", kept);
  EXPECT_GT(kept, 0.04);
  EXPECT_LT(kept, 0.5);
}

// The same band without the descent: the time-stepped flow's diverged tube passes through the mesh,
// and the linear ∆³ tube from the same start, which does not, is delivered, labelled linear, with
// the reason.
TEST(BlendReal, AG2TubeThatCrossesTheMeshGivesWayToTheLinearTube) {
  const Band b = band_across("blub.obj", {0.280928, -0.0196544, 0.897816}, Eigen::Vector3d::UnitY());
  Mesh m = b.cut;
  BlendOptions o;
  o.descent_fallback = false;
  const BlendReport r = blend_loops(m, o);
  print("blub band, no descent", r);
  EXPECT_TRUE(r.fair.linear);
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "C2 (linear)");
  EXPECT_NE(r.fair.note.find("the sixth-order flow's tube crosses the mesh"), std::string::npos) << r.fair.note;
  EXPECT_NE(r.fair.note.find("kept the linear ∆3 tube"), std::string::npos) << r.fair.note;
  EXPECT_TRUE(new_face_crossings(m, b.cut.num_faces()).empty());
  expect_clean(m);
}

// Edges with a face from `first_new_face` on whose two faces' normals are more than 90° apart.
int creased_edges(const Mesh& m, int first_new_face) {
  const Topology topo = build_topology(m.F, m.num_vertices());
  const auto normal = [&](int f) -> Eigen::Vector3d {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)).transpose();
    return (m.V.row(m.F(f, 1)).transpose() - a).cross(m.V.row(m.F(f, 2)).transpose() - a);
  };
  int creases = 0;
  for (int e = 0; e < topo.edges.rows(); ++e) {
    const auto faces = topo.edge_faces.row(e);
    if (faces.size() == 2 && std::max(faces[0], faces[1]) >= first_new_face)
      creases += normal(faces[0]).dot(normal(faces[1])) < 0;
  }
  return creases;
}

// A band across spot's neck (bench_real_holes --all-slabs' spot 1519 z): the tube from straight
// rings settles G2 after its descent, but with a fin standing out of the neck, 68 of its edges
// folded beyond a right angle where the linear ∆³ tube has 16, 0.63 h from the uncut mesh on
// average against the linear tube's 0.25 h. Its border angles do not show it (135°, the linear
// tube's 147°). The linear tube is delivered, labelled linear, with the reason.
TEST(BlendReal, AG2TubeThatCreasesGivesWayToTheLinearTube) {
  const Band b = band_across("spot.obj", {0.135327, 0.828572, -0.217894}, Eigen::Vector3d::UnitZ());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("spot neck band", r);
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "C2 (linear)");
  EXPECT_NE(r.fair.note.find("the sixth-order flow's tube creases ("), std::string::npos) << r.fair.note;
  EXPECT_NE(r.fair.note.find("kept the linear ∆3 tube"), std::string::npos) << r.fair.note;
  const int creases = creased_edges(m, b.cut.num_faces());
  const double distance = tube_distance(m, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] spot neck band: %d creased edges, tube %.3f h from the uncut mesh\n", creases, distance);
  EXPECT_LE(creases, 20);
  EXPECT_LT(distance, 0.3);
  EXPECT_TRUE(new_face_crossings(m, b.cut.num_faces()).empty());
  expect_clean(m);
}

// A band across airplane.obj's fuselage just behind the wings (bench_real_holes' airplane 2997 y):
// loops of 174 and 37 vertices, whose Hermite tube already passes through itself and stays tangled
// under the flow and under the linear ∆³ solve. The tube is built again with straight rings, which
// do not twist, and that one settles into a G2 tube clear of the mesh.
TEST(BlendReal, AHermiteTubeThatCrossesTheMeshIsBuiltAgainWithStraightRings) {
  const Band b = band_across("airplane.obj", {-0.658108, -0.895837, 1.04441}, Eigen::Vector3d::UnitY());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("airplane band", r);
  EXPECT_TRUE(r.straight_rings);
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "G2");
  EXPECT_EQ(r.fair.flow.stop_reason, FlowStopReason::steady);
  EXPECT_NE(r.fair.note.find("the tube from Hermite rings crossed the mesh (blend_loops: the faired tube crosses "
                             "the mesh (tube face"),
            std::string::npos)
      << r.fair.note;
  EXPECT_NE(r.fair.note.find("); built again with straight rings"), std::string::npos) << r.fair.note;
  expect_band_closed(m, b);
}

// A slab 4 h wide across the hammer scan's handle, 15° off square: two facing loops, ragged as the
// scan is. Every tube at G2 crosses the mesh near a notch of one loop, from Hermite rings and from
// straight ones, flowed or linear (the Hermite tube's ∆³ crosses an input face, the straight
// rings' their own tube); ∆² does too. The linear ∆ tube does not, and is delivered, "C0 (linear)", with
// the reason. Before, the blend was an error.
TEST(BlendReal, WhereEveryG2TubeCrossesTheFirstLowerLinearTubeThatDoesNotIsKept) {
  const Band b = band_across("hammer_rawscan.obj", {-0.469669, 0.083133, 0.071897},
                             Eigen::Vector3d(0.003, -0.256, 0.967).normalized());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("hammer handle, oblique", r);
  expect_lower_linear_tube(r);
  EXPECT_NE(r.fair.note.find("built again with straight rings"), std::string::npos) << r.fair.note;
  EXPECT_NE(r.fair.note.find("tube, the first that does not cross"), std::string::npos) << r.fair.note;
  expect_band_closed(m, b);
}

// A band 4 h wide across the raw hammer scan (bench_real_holes' hammer 14000 z): every G2 tube from
// Hermite rings crosses the mesh, and so does the flow's tube from straight rings, a few of its
// triangles sheared over next to a notch of a loop. Flowed once more with its trial states relaxed
// tangentially (crossing_retry_relaxation, as fill's retry) it settles clear of the mesh, and
// --keep-flow delivers that G2 tube (0.015 h from the scan, the linear ∆³ tube 0.012 h); without the
// retry the linear tube takes its place.
TEST(BlendReal, AFlowWhoseTubeCrossesTheMeshIsRelaxedAndTriedAgain) {
  const Band b = band_across("hammer_rawscan.obj", {0.160535, -0.177527, 1.188496}, Eigen::Vector3d::UnitZ());
  ASSERT_EQ(loop_count(b.cut), 2);
  BlendOptions options;
  keep_settled_flow(options);
  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, options);
  print("hammer band, kept flow", r);
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "G2") << r.fair.note;
  EXPECT_EQ(r.fair.flow.stop_reason, FlowStopReason::steady);
  EXPECT_NE(r.fair.note.find("tube crossed the mesh; flowed again with its trial states relaxed tangentially (0.5)"),
            std::string::npos)
      << r.fair.note;
  expect_band_closed(m, b);

  options.crossing_retry_relaxation = 0;
  Mesh unrelaxed = b.cut;
  const BlendReport u = blend_loops(unrelaxed, options);
  EXPECT_TRUE(u.fair.linear);
  EXPECT_NE(u.fair.note.find("flow's tube crosses the mesh; kept the linear ∆3 tube"), std::string::npos)
      << u.fair.note;
  expect_band_closed(unrelaxed, b);
  std::printf("[blend] hammer band: G2 tube %.4f h, linear tube %.4f h from the scan\n",
              tube_distance(m, b.cut.num_vertices(), b.uncut, b.h),
              tube_distance(unrelaxed, b.cut.num_vertices(), b.uncut, b.h));
}

// An oblique slab across the remeshed bunny (bench_stress's blend draws): the time-stepped flow
// does not settle, and the energy descent from its last state and from the linear ∆³ tube both end
// at their step limit without a steady state. The linear tube is delivered, steady, "C2
// (linear)", with the reason; before, the unsettled descent was, labelled G2 and NOT steady.
TEST(BlendReal, WhereNoDescentSettlesTheLinearTubeIsKept) {
  const Band b = band_across(
      "stanford_bunny_remesh_closed.obj", {-0.666721, 0.341074, 0.065914},
      Eigen::Vector3d(0.71289063388071217, -0.32721991021677854, -0.62025323415753331).normalized());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("bunny, oblique", r);
  EXPECT_EQ(delivered_label(r.fair.supported, r.fair.linear), "C2 (linear)") << r.fair.note;
  EXPECT_NE(r.fair.note.find("did not settle"), std::string::npos) << r.fair.note;
  EXPECT_NE(r.fair.note.find("kept the linear ∆3 tube"), std::string::npos) << r.fair.note;
  expect_band_closed(m, b);

  // The time-stepped flow alone (no descent fallback) failed at its first step before the flow
  // limited the term of unresolved curvature (FlowOptions::curvature_resolution); it now runs to its
  // step limit, its tube crosses the mesh, and the linear tube is delivered.
  Mesh asked = b.cut;
  BlendOptions no_descent;
  no_descent.descent_fallback = false;
  const BlendReport alone = blend_loops(asked, no_descent);
  EXPECT_EQ(delivered_label(alone.fair.supported, alone.fair.linear), "C2 (linear)") << alone.fair.note;
  EXPECT_NE(alone.fair.note.find("the sixth-order flow's tube crosses the mesh"), std::string::npos) << alone.fair.note;
  expect_band_closed(asked, b);
}

// bench_real_holes' blub 954 z (--all-slabs): the G2 tube settles clear of the mesh but turned the
// normal across a loop by 38° where the input reads 13° (it now creases: 24 of its edges turn by
// more than 90°, 7 of the linear ∆² tube's), and its linear ∆³ tube crosses the mesh, so there was
// no linear tube to weigh it against and it was delivered, 0.19 h from the uncut mesh. It is weighed
// against the first lower linear tube that does not cross (the floor a crossing ∆³ gives way to):
// that one is no worse, and was delivered, 0.08 h from the uncut mesh. That tube, C1 (linear), is
// below the continuity asked for, so the blend now runs again from the Hermite tube
// (rebuild_without_membrane), whose G2 tube settles clear of the mesh 0.019 h from it.
TEST(BlendReal, AG2TubeIsWeighedAgainstALowerLinearTubeWhereTheLinearOneCrosses) {
  const Band b = band_across("blub.obj", {0.0599292, -0.275701, -1.33125}, Eigen::Vector3d::UnitZ());
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m;
  const BlendReport r = blend_from_membrane_only(b, m);
  print("blub 954 z", r);
  expect_lower_linear_tube(r);
  // It loses to that tube by the crease rule or the angle rule, whichever the machine's rounding of
  // the unsettled time-stepped flow it descended from leads to (24 creased edges; or 38.3° against
  // 26.4°).
  EXPECT_TRUE(r.fair.note.find("the sixth-order flow's tube creases") != std::string::npos ||
              r.fair.note.find("the sixth-order flow's tube turns the normal across the loops by") != std::string::npos)
      << r.fair.note;
  EXPECT_NE(r.fair.note.find("(the linear ∆3 tube crosses the mesh)"), std::string::npos) << r.fair.note;
  EXPECT_TRUE(new_face_crossings(m, b.cut.num_faces()).empty());
  expect_clean(m);
  const double distance = tube_distance(m, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] blub 954 z: %s, %.3f h from the uncut mesh\n",
              delivered_label(r.fair.supported, r.fair.linear).c_str(), distance);
  EXPECT_LT(distance, 0.12);

  Mesh rebuilt = b.cut;
  const BlendReport g2 = blend_loops(rebuilt, BlendOptions{});
  EXPECT_EQ(delivered_label(g2.fair.supported, g2.fair.linear), "G2") << g2.fair.note;
  EXPECT_TRUE(g2.rebuilt_without_membrane);
  EXPECT_EQ(g2.fair.note.rfind("from the G0 membrane the tube fell to C1 (linear), the first lower linear tube "
                               "that does not cross the mesh; built again from the Hermite tube, which gives G2",
                               0),
            0u)
      << g2.fair.note;
  expect_band_closed(rebuilt, b);
  const double closer = tube_distance(rebuilt, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] blub 954 z from the Hermite tube: %.3f h from the uncut mesh\n", closer);
  EXPECT_LT(closer, 0.5 * distance);
}

// An oblique slab 4 h wide across spot's head, through the base of its horns (bench_stress's blend
// draws, spot vertex 643). Every tube from Hermite rings or straight ones crosses the mesh, flowed
// or linear, at G2 and below; the G0 membrane spans the loops without crossing but was dropped,
// since it pinches off (worst face quality 0.0046 against the Hermite tube's 0.13). It is the last
// start: the energy descent from it settles clear of the mesh, 0.28 h from the uncut head. The
// loops do not face each other (the slab grazes the horns), so the tube folds back at both, as every
// tube there does; before, the blend was an error.
TEST(BlendReal, WhereEveryTubeCrossesTheMeshThePinchedMembraneIsTheLastStart) {
  const Band b = band_across("spot.obj", {-0.0838463, 0.11062, -0.238883},
                             Eigen::Vector3d(-0.19198793547419313, -0.055301074517244538, 0.97983795792446993));
  ASSERT_EQ(loop_count(b.cut), 2);
  Mesh m = b.cut;
  const BlendReport r = blend_loops(m, BlendOptions{});
  print("spot head, oblique", r);
  EXPECT_TRUE(r.relaxed);
  EXPECT_LT(r.membrane_quality, BlendOptions{}.pinch_quality_ratio * r.hermite_quality);
  EXPECT_NE(r.fair.note.find("which pinches off, crosses the mesh"), std::string::npos) << r.fair.note;
  EXPECT_NE(r.fair.note.find("); started from the membrane"), std::string::npos) << r.fair.note;
  expect_band_closed(m, b);
  const double distance = tube_distance(m, b.cut.num_vertices(), b.uncut, b.h);
  std::printf("[blend] spot head, oblique: %s, %.3f h from the uncut mesh\n",
              delivered_label(r.fair.supported, r.fair.linear).c_str(), distance);
  EXPECT_LT(distance, 0.4);

  // Without the membrane every tube crosses: the error that was.
  Mesh hermite = b.cut;
  BlendOptions no_membrane;
  no_membrane.patch.relax = false;
  EXPECT_THROW(blend_loops(hermite, no_membrane), NumericalError);
}

// Two open cylinders end to end with a plate between their facing ends: every tube between those
// ends passes through the plate, from Hermite rings or straight ones, flowed or linear. No tube is
// delivered as a success: NumericalError names the first crossing of both tubes, and the mesh
// holds the straight one.
TEST(BlendCrossings, ATubeThroughAnotherSheetIsAnErrorEvenWithStraightRings) {
  const Mesh lower = test::open_cylinder(24, 8, 0.5, 1.0);
  Mesh m = lower;
  const auto append = [&m](const Mesh& part, const Eigen::RowVector3d& shift) {
    const int nv = m.num_vertices(), nf = m.num_faces();
    m.V.conservativeResize(nv + part.num_vertices(), 3);
    m.V.bottomRows(part.num_vertices()) = part.V.rowwise() + shift;
    m.F.conservativeResize(nf + part.num_faces(), 3);
    m.F.bottomRows(part.num_faces()) = part.F.array() + nv;
  };
  append(lower, {0, 0, 2.0});                                  // the upper cylinder, z in [2, 3]
  append(test::regular_grid(8, 8, 0.25), {-1.0, -1.0, 1.5});  // the plate, 2 by 2, in z = 1.5
  const Topology topo = build_topology(m.F, m.num_vertices());
  const std::vector<std::vector<int>> loops = boundary_loops(m.F, topo);
  BlendOptions o;
  for (int i = 0; i < static_cast<int>(loops.size()); ++i) {
    const double z = m.V(loops[i].front(), 2);
    if (std::abs(z - 1.0) < 1e-9) o.loop_a = i;
    if (std::abs(z - 2.0) < 1e-9) o.loop_b = i;
  }
  ASSERT_GE(o.loop_a, 0);
  ASSERT_GE(o.loop_b, 0);
  const int input_faces = m.num_faces();
  try {
    blend_loops(m, o);
    ADD_FAILURE() << "a tube through the plate was delivered";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("blend_loops: the faired tube crosses the mesh (tube face", 0), 0u) << what;
    EXPECT_NE(what.find("; built again with straight rings: blend_loops: the faired tube crosses the mesh (tube "
                        "face"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("crosses input face"), std::string::npos) << what;  // the plate
    EXPECT_FALSE(new_face_crossings(m, input_faces).empty());
  }
}

}  // namespace
}  // namespace fairsurf
