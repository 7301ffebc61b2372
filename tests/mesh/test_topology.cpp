#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include "test_support.h"

using namespace fairsurf;

namespace {

}  // namespace

TEST(Topology, ClosedTetrahedronCounts) {
  const Mesh m = test::tetrahedron();
  const Topology t = build_topology(m.F, m.num_vertices());
  EXPECT_EQ(t.edges.rows(), 6);
  for (int e = 0; e < 6; ++e) EXPECT_EQ(t.edge_faces.size(e), 2);
  for (int v = 0; v < 4; ++v) {
    EXPECT_EQ(t.vertex_vertices.size(v), 3);
    EXPECT_EQ(t.vertex_faces.size(v), 3);
  }
  EXPECT_TRUE(boundary_loops(m.F, t).empty());
  EXPECT_EQ(connected_components(m.F, t).count, 1);
}

TEST(Topology, EdgesAreSortedAndFaceEdgesConsistent) {
  const Mesh m = test::regular_grid(5, 4);
  const Topology t = build_topology(m.F, m.num_vertices());
  // A disk has Euler characteristic 1.
  EXPECT_EQ(m.num_vertices() - t.edges.rows() + m.num_faces(), 1);
  for (int e = 1; e < t.edges.rows(); ++e) {
    EXPECT_LT(t.edges(e, 0), t.edges(e, 1));
    EXPECT_TRUE(t.edges(e - 1, 0) < t.edges(e, 0) ||
                (t.edges(e - 1, 0) == t.edges(e, 0) && t.edges(e - 1, 1) < t.edges(e, 1)));
  }
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int e = t.face_edges[3 * f + k];
      const int a = std::min(m.F(f, k), m.F(f, (k + 1) % 3));
      const int b = std::max(m.F(f, k), m.F(f, (k + 1) % 3));
      EXPECT_EQ(t.edges(e, 0), a);
      EXPECT_EQ(t.edges(e, 1), b);
    }
}

TEST(Topology, GridBoundaryLoopIsOrderedWithSurfaceOnTheLeft) {
  const int nx = 6, ny = 3;
  const Mesh m = test::regular_grid(nx, ny);
  const Topology t = build_topology(m.F, m.num_vertices());
  const auto loops = boundary_loops(m.F, t);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), static_cast<std::size_t>(2 * (nx + ny)));
  // Consecutive loop vertices share a border edge, and the signed area of the loop polygon is
  // positive: counter-clockwise seen from +z, the side the grid's normals point to.
  double twice_area = 0;
  const auto& loop = loops[0];
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    twice_area += m.V(a, 0) * m.V(b, 1) - m.V(b, 0) * m.V(a, 1);
    const auto row = t.vertex_vertices.row(a);
    EXPECT_NE(std::find(row.begin(), row.end(), b), row.end());
  }
  EXPECT_NEAR(twice_area, 2.0 * nx * ny, 1e-12);
}

TEST(Topology, KRingSizesOnRegularGrid) {
  const int n = 12;
  const Mesh m = test::regular_grid(n, n);
  const Topology t = build_topology(m.F, m.num_vertices());
  const int center = (n / 2) * (n + 1) + n / 2;
  const int seeds[] = {center};
  // On a valence-6 grid the k-ring is a hexagon with 1 + 3k(k+1) vertices.
  for (int k = 0; k <= 4; ++k)
    EXPECT_EQ(k_ring(t, seeds, k).size(), static_cast<std::size_t>(1 + 3 * k * (k + 1))) << k;
  const auto dist = ring_distances(t, seeds, 2);
  EXPECT_EQ(dist[center], 0);
  EXPECT_EQ(dist[center + 1], 1);
  EXPECT_EQ(dist[center + 2], 2);
  EXPECT_EQ(dist[center + 3], -1);
}

TEST(Topology, ThreeRingsAroundARegion) {
  // The three fixed rings of method.md §6 around a free row of the grid.
  const int n = 10;
  const Mesh m = test::regular_grid(n, n);
  const Topology t = build_topology(m.F, m.num_vertices());
  std::vector<int> row;
  for (int i = 0; i <= n; ++i) row.push_back(5 * (n + 1) + i);
  const auto dist = ring_distances(t, row, 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int expected = std::abs(j - 5) <= 3 ? std::abs(j - 5) : -1;
      EXPECT_EQ(dist[j * (n + 1) + i], expected);
    }
}

TEST(Topology, ComponentsAndUnreferencedVertices) {
  Mesh a = test::tetrahedron();
  Mesh m;
  m.V.resize(9, 3);
  m.V.topRows(4) = a.V;
  m.V.middleRows(4, 4) = a.V.array() + 5.0;
  m.V.row(8) << 9, 9, 9;  // unreferenced
  m.F.resize(8, 3);
  m.F.topRows(4) = a.F;
  m.F.bottomRows(4) = a.F.array() + 4;
  const Topology t = build_topology(m.F, m.num_vertices());
  const Components c = connected_components(m.F, t);
  EXPECT_EQ(c.count, 2);
  EXPECT_EQ(c.vertex_component[0], 0);
  EXPECT_EQ(c.vertex_component[4], 1);
  EXPECT_EQ(c.vertex_component[8], -1);
  EXPECT_EQ(c.face_component[7], 1);
}

TEST(Topology, RejectsOutOfRangeIndexWithMessage) {
  Mesh m = test::tetrahedron();
  m.F(2, 1) = 7;
  try {
    build_topology(m.F, m.num_vertices());
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "build_topology: face 2 has vertex index 7 outside [0, 4)");
  }
}

TEST(Topology, AreasAndNormals) {
  const Mesh m = test::regular_grid(3, 2, 0.5);
  const Eigen::VectorXd A = vertex_areas(m.V, m.F);
  EXPECT_NEAR(A.sum(), 3 * 0.5 * 2 * 0.5, 1e-14);
  Eigen::MatrixX3d N;
  Eigen::VectorXd FA;
  face_normals_and_areas(m.V, m.F, N, FA);
  for (int f = 0; f < m.num_faces(); ++f) {
    EXPECT_NEAR(N(f, 2), 1.0, 1e-15);
    EXPECT_NEAR(FA[f], 0.125, 1e-15);
  }
}
