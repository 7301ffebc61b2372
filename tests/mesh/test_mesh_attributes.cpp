// The operations that change faces or move vertices keep texture coordinates, normals and polygons
// consistent (mesh_attributes.h): repair, concatenate_meshes, and the normals of moved vertices.
#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/repair.h>
#include <fairsurf/mesh/mesh_attributes.h>

#include <gtest/gtest.h>

using namespace fairsurf;

namespace {

// Two unit quads side by side, fanned, each with its own texture coordinates; the second quad's
// copy of the shared edge is a second pair of vertices at the same positions (as an exporter that
// splits at a UV seam writes it).
Mesh split_quads() {
  Mesh m;
  m.V.resize(8, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,  //
      1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0;
  m.F.resize(4, 3);
  m.F << 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7;
  m.TC.resize(8, 2);
  for (int v = 0; v < 8; ++v) m.TC.row(v) << m.V(v, 0) / 2 + (v >= 4 ? 0.01 : 0), m.V(v, 1);
  m.FTC = m.F;
  m.face_polygon = (Eigen::VectorXi(4) << 0, 0, 1, 1).finished();
  return m;
}

}  // namespace

TEST(MeshAttributes, RepairMergingASeamKeepsEachCornersTextureCoordinateAndThePolygons) {
  const Mesh input = split_quads();
  Mesh m = input;
  const RepairReport report = repair(m);
  ASSERT_EQ(report.vertices_merged, 2);
  ASSERT_EQ(m.num_vertices(), 6);
  ASSERT_EQ(m.FTC.rows(), 4);
  EXPECT_EQ(m.TC, input.TC);
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(m.V.row(m.F(f, k)), input.V.row(input.FTC(f, k)));  // each corner's UV is its own position's
      EXPECT_EQ(m.FTC(f, k), input.FTC(f, k));
    }
  EXPECT_EQ(m.face_polygon, input.face_polygon);
}

TEST(MeshAttributes, RepairRemovingATriangleOfAPolygonLeavesTheRestAsTriangles) {
  Mesh m = split_quads();
  m.F.conservativeResize(5, 3);
  m.F.row(4) << 4, 5, 6;  // a duplicate of face 2, which repair removes
  m.FTC.conservativeResize(5, 3);
  m.FTC.row(4) << 4, 5, 6;
  m.face_polygon.conservativeResize(5);
  m.face_polygon[4] = 1;  // polygon 1 now claims three triangles, one of which goes
  repair(m);
  ASSERT_EQ(m.num_faces(), 4);
  EXPECT_EQ(m.face_polygon, (Eigen::VectorXi(4) << 0, 0, -1, -1).finished());
  EXPECT_EQ(m.FTC.minCoeff(), 0);  // every surviving face still has its texture coordinates
}

TEST(MeshAttributes, ConcatenationShiftsTheSecondMeshsIndicesAndPadsWhatOneLacks) {
  const Mesh a = split_quads();
  Mesh b = split_quads();
  b.FTC.resize(0, 3);
  b.TC.resize(0, 2);
  b.FN = Faces::Zero(4, 3);
  b.N = Vertices::Zero(1, 3);
  b.N(0, 2) = 1;
  const Mesh c = concatenate_meshes(a, b);
  ASSERT_EQ(c.FTC.rows(), 8);
  EXPECT_EQ(c.FTC.topRows(4), a.FTC);
  EXPECT_EQ(c.FTC.bottomRows(4).maxCoeff(), -1);
  ASSERT_EQ(c.FN.rows(), 8);
  EXPECT_EQ(c.FN.topRows(4).maxCoeff(), -1);
  EXPECT_EQ(c.FN.bottomRows(4).minCoeff(), 0);
  EXPECT_EQ(c.face_polygon, (Eigen::VectorXi(8) << 0, 0, 1, 1, 2, 2, 3, 3).finished());
}

TEST(MeshAttributes, RefreshingNormalsKeepsACreaseAndTouchesOnlyMovedVertices) {
  // A roof: two quads meeting at the ridge x = 1, one normal per side (a crease), and a third
  // normal used by a triangle far away whose vertices do not move.
  Mesh m;
  m.V.resize(9, 3);
  m.V << 0, 0, 0, 1, 0, 1, 1, 1, 1, 0, 1, 0, 2, 0, 0, 2, 1, 0, 5, 5, 5, 6, 5, 5, 5, 6, 5;
  m.F.resize(5, 3);
  m.F << 0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2, 6, 7, 8;
  m.N.resize(3, 3);
  m.N << 0, 0, 1, 0, 0, 1, 0, 0, 1;  // stale on purpose
  m.FN.resize(5, 3);
  m.FN << 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 2, 2, 2;
  const Vertices before = m.V;
  m.V(1, 2) = 0.5;  // lower the ridge
  m.V(2, 2) = 0.5;
  EXPECT_EQ(refresh_moved_normals(m, before), 2);
  const double s = 1 / std::sqrt(1.25);
  EXPECT_NEAR((m.N.row(0) - Eigen::RowVector3d(-0.5 * s, 0, s)).norm(), 0, 1e-12);
  EXPECT_NEAR((m.N.row(1) - Eigen::RowVector3d(0.5 * s, 0, s)).norm(), 0, 1e-12);
  EXPECT_EQ(m.N.row(2), Eigen::RowVector3d(0, 0, 1));  // nothing of it moved
}

TEST(MeshAttributes, PaddingGivesAppendedFacesNone) {
  Mesh m = split_quads();
  m.F.conservativeResize(6, 3);
  m.F.bottomRows(2) << 0, 1, 4, 1, 5, 4;
  EXPECT_EQ(pad_face_attributes(m), 2);
  ASSERT_EQ(m.FTC.rows(), 6);
  EXPECT_EQ(m.FTC.bottomRows(2).maxCoeff(), -1);
  EXPECT_EQ(m.face_polygon, (Eigen::VectorXi(6) << 0, 0, 1, 1, -1, -1).finished());
}
