// relax_tangentially (tangential_relaxation.h), hold_back_turned_faces (orientation_guard.h) and
// the figures of mesh_quality.h.
#include <fairsurf/flow/flow.h>
#include <fairsurf/flow/orientation_guard.h>
#include <fairsurf/flow/tangential_relaxation.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_quality.h>
#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "analytic_meshes.h"
#include "hole_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

// Smallest angle of any face, in degrees.
double min_angle(const Vertices& V, const Faces& F) {
  double worst = 180;
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = V.row(F(f, k)), q = V.row(F(f, (k + 1) % 3)), r = V.row(F(f, (k + 2) % 3));
      const double c = (q - p).normalized().dot((r - p).normalized());
      worst = std::min(worst, std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi);
    }
  return worst;
}

std::vector<int> all_vertices(int n) {
  std::vector<int> v(n);
  for (int i = 0; i < n; ++i) v[i] = i;
  return v;
}

}  // namespace

// A flat grid with its interior vertices jittered in the plane (needles down to a few degrees):
// relaxation must keep the plane exactly, leave the border alone and open up the needles.
TEST(TangentialRelaxation, OpensNeedlesWithinTheTangentPlane) {
  const int n = 12;
  Mesh m = test::regular_grid(n, n, 1.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45);
  std::vector<int> interior;
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) {
      const int v = j * (n + 1) + i;
      m.V(v, 0) += jitter(rng), m.V(v, 1) += jitter(rng);
      interior.push_back(v);
    }
  const Topology topo = build_topology(m.F, m.num_vertices());
  Vertices normals = Vertices::Zero(m.num_vertices(), 3);
  normals.col(2).setOnes();
  const Vertices input = m.V;
  const double before = min_angle(m.V, m.F);
  for (int sweep = 0; sweep < 10; ++sweep) relax_tangentially(m.V, topo, interior, normals, 0.5);
  const double after = min_angle(m.V, m.F);
  std::printf("[relax] jittered grid: min angle %.2f -> %.2f degrees\n", before, after);
  EXPECT_LT(before, 10.0);
  EXPECT_GT(after, 2 * before);
  EXPECT_EQ(m.V.col(2).cwiseAbs().maxCoeff(), 0.0);
  for (int v = 0; v < m.num_vertices(); ++v)
    if (std::find(interior.begin(), interior.end(), v) == interior.end()) {
      EXPECT_EQ(m.V.row(v), input.row(v));
    }
}

// On a sphere a tangential move δ leaves the surface by |δ|²/(2R) to first order: relaxation
// changes the shape only to second order in the move.
TEST(TangentialRelaxation, LeavesASphereOnlyToSecondOrder) {
  const Mesh m = test::jittered_sphere(3, 1.0, 0.3);
  const Topology topo = build_topology(m.F, m.num_vertices());
  const Vertices normals = m.V.rowwise().normalized();
  Vertices V = m.V;
  relax_tangentially(V, topo, all_vertices(m.num_vertices()), normals, 1.0);
  double worst_ratio = 0, largest_move = 0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const double move = (V.row(v) - m.V.row(v)).norm();
    largest_move = std::max(largest_move, move);
    if (move > 0) worst_ratio = std::max(worst_ratio, std::abs(V.row(v).norm() - 1.0) / (move * move));
  }
  std::printf("[relax] jittered sphere: largest move %.3g, max |r - 1| / |move|^2 = %.3f\n", largest_move,
              worst_ratio);
  EXPECT_GT(largest_move, 0.01);
  EXPECT_LE(worst_ratio, 0.5 + 1e-6);
}

TEST(TangentialRelaxation, RejectsBadArguments) {
  Mesh m = test::regular_grid(2, 2, 1.0);
  const Topology topo = build_topology(m.F, m.num_vertices());
  const Vertices normals = Vertices::Zero(m.num_vertices(), 3);
  try {
    relax_tangentially(m.V, topo, all_vertices(m.num_vertices()), normals, 1.5);
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "relax_tangentially: weight 1.500000 is outside [0, 1]");
  }
  EXPECT_THROW(relax_tangentially(m.V, topo, {}, Vertices::Zero(2, 3), 0.5), InvalidArgument);
}

// Two triangles sharing the edge 1–2 and a third reaching far out to vertex 4; pushing vertex 3
// across the edge 1–2 turns face 1 over. The guard halves that move (twice) until face 1 keeps its
// orientation; vertex 4, whose faces stay as they were, keeps its full move.
TEST(OrientationGuard, HalvesOnlyTheMovesThatTurnFacesOver) {
  Vertices from(5, 3);
  from << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 5, 5, 0;
  Faces F(3, 3);
  F << 0, 1, 2, 1, 3, 2, 3, 4, 1;  // face 2 reaches vertex 4 far away
  Vertices to = from;
  to.row(3) << -0.5, -0.5, 0;  // across the edge 1–2: face 1 turns over
  to.row(4) << 5, 6, 0.5;
  const std::vector<int> faces{0, 1, 2};
  const Eigen::MatrixX3d before = face_directions(from, F, faces);
  const Eigen::MatrixX3d* const references[] = {&before};
  ASSERT_EQ(count_inverted_faces(from, to, F), 1);
  const int held = hold_back_turned_faces(from, to, F, faces, references);
  EXPECT_EQ(count_inverted_faces(from, to, F), 0);
  const Eigen::MatrixX3d after = face_directions(to, F, faces);
  for (int k = 0; k < 3; ++k) EXPECT_GT(after.row(k).dot(before.row(k)), 0) << k;
  EXPECT_EQ(held, 1);  // vertex 3: vertices 1 and 2 of face 1 did not move
  EXPECT_EQ(to.row(4), Eigen::RowVector3d(5, 6, 0.5));
  EXPECT_EQ(to.row(0), from.row(0));
  // The halved move still goes the same way, only shorter.
  EXPECT_EQ(to.row(3), Eigen::RowVector3d(0.625, 0.625, 0));
}

TEST(MeshQuality, InvertedFacesAndNoiseIndex) {
  const Mesh grid = test::regular_grid(4, 3, 1.0);
  Vertices mirrored = grid.V;
  mirrored.col(1) *= -1;  // the plane seen from below: every face points down
  EXPECT_EQ(count_inverted_faces(grid.V, grid.V, grid.F), 0);
  EXPECT_EQ(count_inverted_faces(grid.V, mirrored, grid.F), grid.num_faces());
  mirrored.row(0) = mirrored.row(1);  // and face 0 (0, 1, …) degenerate
  EXPECT_EQ(count_inverted_faces(grid.V, mirrored, grid.F), grid.num_faces());
  EXPECT_THROW(count_inverted_faces(grid.V, grid.V.topRows(3), grid.F), InvalidArgument);

  const Mesh sphere = test::icosphere(3);

  const Topology topo = build_topology(sphere.F, sphere.num_vertices());
  EXPECT_EQ(noise_index(sphere.V, sphere.F, topo), 0.0);  // every umbrella points inwards
  // Alternating bumps on the sphere: most edges join a raised and a lowered vertex.
  Vertices noisy = sphere.V;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (int v = 0; v < noisy.rows(); ++v) noisy.row(v) *= 1 + noise(rng);
  const double index = noise_index(noisy, sphere.F, topo);
  std::printf("[quality] icosphere level 3 with 5%% radial noise: noise index %.3f\n", index);
  EXPECT_GT(index, 0.2);
  std::vector<char> none(sphere.num_vertices(), 0);
  EXPECT_EQ(noise_index(noisy, sphere.F, topo, none), 0.0);
}

// roughness: how far a vertex lies from the quadratic its 2-ring predicts, in edges. Curvature
// alone reads close to 0, normal noise of σ edges about 0.8 σ, and a vertex on a knife edge, whose
// 2-ring is no height function over its tangent plane, is left out: no quadratic is fitted across it.
TEST(MeshQuality, RoughnessReadsNoiseAtTheScaleOfAnEdgeNotCurvature) {
  const test::ParametricMesh torus = test::torus_grid(60, 30, 1.0, 0.4);
  const Topology topo = build_topology(torus.mesh.F, torus.mesh.num_vertices());
  std::vector<int> every(torus.mesh.num_vertices());
  std::iota(every.begin(), every.end(), 0);
  const double h = test::mean_edge_length(torus.mesh);
  const double smooth = roughness(torus.mesh.V, torus.mesh.F, topo, every);
  double noisy[2];
  for (int k = 0; k < 2; ++k) {
    Mesh copy = torus.mesh;
    test::add_normal_noise(copy, (k == 0 ? 0.03 : 0.1) * h, 11);
    noisy[k] = roughness(copy.V, copy.F, topo, every);
  }
  std::printf("[quality] torus 60 x 30: roughness %.4f; with 0.03 and 0.1 edges of normal noise %.4f, %.4f\n", smooth,
              noisy[0], noisy[1]);
  EXPECT_LT(smooth, 0.01);
  EXPECT_GT(noisy[0], 2 * smooth);
  EXPECT_GT(noisy[1], 2 * noisy[0]);
  EXPECT_GT(noisy[1], 0.06);
  EXPECT_LT(noisy[1], 0.11);
  EXPECT_EQ(roughness(torus.mesh.V, torus.mesh.F, topo, {}), 0.0);
  const int outside[] = {torus.mesh.num_vertices()};
  EXPECT_THROW(roughness(torus.mesh.V, torus.mesh.F, topo, outside), InvalidArgument);

  // A sphere pressed into a disk 0.04 thick: at its rim the 2-ring wraps round a knife edge.
  Mesh disk = test::icosphere(3);
  disk.V.col(2) *= 0.02;
  const Topology disk_topo = build_topology(disk.F, disk.num_vertices());
  std::vector<int> rim;
  for (int v = 0; v < disk.num_vertices(); ++v)
    if (std::abs(disk.V(v, 2)) < 1e-12) rim.push_back(v);
  ASSERT_FALSE(rim.empty());
  EXPECT_EQ(roughness(disk.V, disk.F, disk_topo, rim), 0.0) << "a rim vertex was read";
}

TEST(TangentialRelaxation, RunFlowRejectsAWeightOutsideTheUnitInterval) {
  const Mesh m = test::icosphere(1);
  Vertices V = m.V;
  FlowOptions o;
  o.tangential_relaxation = -0.1;
  try {
    run_flow(V, m.F, o);
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "run_flow: tangential_relaxation must lie in [0, 1]");
  }
  EXPECT_EQ(V, m.V);
}
