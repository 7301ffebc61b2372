#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region.h>

#include <gtest/gtest.h>

#include "analytic_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

// A 21x21 grid; the free set is the 3x3 block of vertices around the centre (index (i, j)).
struct GridRegion {
  Mesh mesh = test::regular_grid(20, 20);
  Topology topo = build_topology(mesh.F, mesh.num_vertices());
  std::vector<int> block(int ci, int cj) const {
    std::vector<int> out;
    for (int j = cj - 1; j <= cj + 1; ++j)
      for (int i = ci - 1; i <= ci + 1; ++i) out.push_back(j * 21 + i);
    return out;
  }
};

}  // namespace

TEST(Region, ThreeCompleteRingsAwayFromTheBorder) {
  GridRegion g;
  const Region r = make_region(g.topo, g.block(10, 10), Continuity::G2);
  EXPECT_EQ(r.num_free(), 9);
  EXPECT_EQ(r.complete_rings, 3);
  EXPECT_EQ(r.supported, Continuity::G2);
  // Free vertices are indexed in ascending order; ring numbers are graph distances.
  for (int k = 0; k < r.num_free(); ++k) EXPECT_EQ(r.free_index[r.free_vertices[k]], k);
  EXPECT_EQ(r.ring[10 * 21 + 10], 0);
  EXPECT_EQ(r.ring[10 * 21 + 12], 1);
  EXPECT_EQ(r.ring[10 * 21 + 14], 3);
  EXPECT_EQ(r.ring[10 * 21 + 15], -1);
  EXPECT_FALSE(r.is_free(10 * 21 + 12));
}

TEST(Region, ContinuityFallsBackNearTheBorder) {
  GridRegion g;
  // The block's outermost vertices sit 2, 1 and 0 vertices away from column 0.
  const struct {
    int ci, rings;
    Continuity supported;
  } cases[] = {{4, 3, Continuity::G2}, {3, 2, Continuity::G1}, {2, 1, Continuity::G0},
               {1, 0, Continuity::G0}};
  for (const auto& c : cases) {
    const Region r = make_region(g.topo, g.block(c.ci, 10), Continuity::G2);
    EXPECT_EQ(r.complete_rings, c.rings) << c.ci;
    EXPECT_EQ(r.supported, c.supported) << c.ci;
  }
  // A lower request is never raised.
  EXPECT_EQ(make_region(g.topo, g.block(10, 10), Continuity::G1).supported, Continuity::G1);
}

// On a closed mesh: a cap leaves three rings; a region that takes all but three vertices far apart
// leaves them all next to it, with no second ring, so only positions (G0) are given; the sphere
// smoothed whole has no fixed vertex and needs no data.
TEST(Region, AnEmptyRingBoundsTheRingsOfData) {
  const Mesh sphere = test::icosphere(3);
  const Topology topo = build_topology(sphere.F, sphere.num_vertices());
  std::vector<int> cap, all_but_three, all;
  Eigen::Index far[3];
  for (int axis = 0; axis < 3; ++axis) sphere.V.col(axis).maxCoeff(&far[axis]);
  for (int v = 0; v < sphere.num_vertices(); ++v) {
    if (sphere.V(v, 2) > 0.5) cap.push_back(v);
    if (v != far[0] && v != far[1] && v != far[2]) all_but_three.push_back(v);
    all.push_back(v);
  }
  EXPECT_EQ(make_region(topo, cap).complete_rings, 3);
  const Region most = make_region(topo, all_but_three);
  EXPECT_EQ(most.num_free(), sphere.num_vertices() - 3);
  EXPECT_EQ(most.complete_rings, 1);
  EXPECT_EQ(most.supported, Continuity::G0);
  const Region whole = make_region(topo, all);
  EXPECT_EQ(whole.complete_rings, 3);
  EXPECT_EQ(whole.supported, Continuity::G2);
}

TEST(Region, InteriorVerticesLeaveFixedRingsAlongTheBorder) {
  GridRegion g;
  const auto interior = interior_vertices(g.topo, 3);
  // Rows and columns 0-2 and 18-20 are fixed: 15 x 15 interior vertices remain.
  EXPECT_EQ(interior.size(), 15u * 15u);
  EXPECT_EQ(interior.front(), 3 * 21 + 3);
  const Region r = make_region(g.topo, interior, Continuity::G2);
  EXPECT_EQ(r.complete_rings, 3);
  EXPECT_EQ(interior_vertices(g.topo, 0).size(), 21u * 21u);
}

TEST(Region, ParsesContinuityAndRejectsBadInput) {
  EXPECT_EQ(parse_continuity("g1"), Continuity::G1);
  EXPECT_EQ(rings_needed(Continuity::G2), 3);
  EXPECT_STREQ(to_string(Continuity::G0), "G0");
  try {
    parse_continuity("C2");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "parse_continuity: 'C2' is not a continuity (expected G0, G1 or G2)");
  }
  GridRegion g;
  EXPECT_THROW(make_region(g.topo, std::vector<int>{}), InvalidArgument);
  EXPECT_THROW(make_region(g.topo, std::vector<int>{5000}), InvalidArgument);
}

TEST(Region, RegionFacesAreTheFacesWithAFreeVertexAscending) {
  Faces F(4, 3);
  F << 0, 1, 2,  //
      2, 3, 4,   //
      5, 6, 7,   //
      4, 8, 2;
  EXPECT_EQ(region_faces(F, 9, std::vector<int>{4}), (std::vector<int>{1, 3}));
  EXPECT_EQ(region_faces(F, 9, std::vector<int>{2, 2, 7}), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(region_faces(F, 9, std::vector<int>{-1, 9, 3}), (std::vector<int>{1}));  // out of range ignored
  EXPECT_TRUE(region_faces(F, 9, std::vector<int>{}).empty());
}
