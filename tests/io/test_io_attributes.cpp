// Texture coordinates, normals and polygons through the readers and writers (issue #16): what each
// format keeps, and what it says it cannot.
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "scratch_dir.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

// Two quads sharing the edge 2-3, and a triangle; vertex 2 has two texture coordinates (a seam:
// vt 3 on the first quad, vt 5 on the second) and the triangle has normals, the quads none.
const char* const kSeamObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nv 3 0 0\n"
    "vt 0 0\nvt 0.5 0\nvt 0.5 1\nvt 0 1\nvt 0.6 1\nvt 1 0\nvt 1 1\n"
    "vn 0 0 1\nvn 0 0.6 0.8\n"
    "f 1/1 2/2 3/3 4/4\n"
    "f 2/2 5/6 6/7 3/5\n"
    "f 5//1 7//2 6//1\n";

class IoAttributes : public test::ScratchDirTest {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(file(name), std::ios::binary) << text;
    return file(name);
  }
  static std::string face_lines(const std::string& text) {
    std::string faces;
    for (std::size_t at = text.find("\nf "); at != std::string::npos; at = text.find("\nf ", at + 1))
      faces += text.substr(at + 1, text.find('\n', at + 1) - at);
    return faces;
  }
};

}  // namespace

TEST_F(IoAttributes, ObjKeepsPolygonsSeamsAndNormalsThroughARoundTrip) {
  const Mesh m = read_mesh(write("in.obj", kSeamObj));
  ASSERT_EQ(m.num_faces(), 5);
  EXPECT_EQ(m.TC.rows(), 7);
  EXPECT_EQ(m.N.rows(), 2);
  EXPECT_EQ(m.FTC.row(2), Eigen::RowVector3i(1, 5, 6));  // second quad's first fan triangle
  EXPECT_EQ(m.FTC.row(4), Eigen::RowVector3i(-1, -1, -1));
  EXPECT_EQ(m.FN.row(4), Eigen::RowVector3i(0, 1, 0));
  EXPECT_EQ(m.face_polygon, (Eigen::VectorXi(5) << 0, 0, 1, 1, 2).finished());

  write_mesh(file("out.obj"), m);
  const std::string out = test::read_bytes(file("out.obj"));
  EXPECT_EQ(face_lines(out), face_lines(kSeamObj));
  const Mesh back = read_mesh(file("out.obj"));
  EXPECT_EQ(back.F, m.F);
  EXPECT_EQ(back.TC, m.TC);
  EXPECT_EQ(back.FTC, m.FTC);
  EXPECT_EQ(back.N, m.N);
  EXPECT_EQ(back.FN, m.FN);
  EXPECT_EQ(back.face_polygon, m.face_polygon);
}

TEST_F(IoAttributes, AnIncompleteOrReorderedPolygonIsWrittenAsWhatRemains) {
  Mesh m = read_mesh(write("in.obj", kSeamObj));
  // Reversed as orienting reverses faces (corners 1 and 2 swapped): still one polygon, reversed.
  for (int f = 0; f < 2; ++f) {
    std::swap(m.F(f, 1), m.F(f, 2));
    std::swap(m.FTC(f, 1), m.FTC(f, 2));
  }
  // The second quad loses its second triangle: the first is written as a triangle.
  m.F.row(3) = m.F.row(4);
  m.FTC.row(3) = m.FTC.row(4);
  m.FN.row(3) = m.FN.row(4);
  m.F.conservativeResize(4, 3);
  m.FTC.conservativeResize(4, 3);
  m.FN.conservativeResize(4, 3);
  m.face_polygon = (Eigen::VectorXi(4) << 0, 0, 1, 2).finished();
  write_mesh(file("out.obj"), m);
  EXPECT_EQ(face_lines(test::read_bytes(file("out.obj"))),
            "f 1/1 4/4 3/3 2/2\nf 2/2 5/6 6/7\nf 5//1 7//2 6//1\n");
}

TEST_F(IoAttributes, PlyAndOffKeepPolygonsAndPlyKeepsPerVertexValuesOnly) {
  const Mesh m = read_mesh(write("in.obj", kSeamObj));
  WriteReport report;
  write_mesh(file("out.ply"), m, {.binary = false}, &report);
  EXPECT_EQ(report.notes, (std::vector<std::string>{
                              "normals not written: PLY holds one per vertex, and some vertex has none or several "
                              "(OBJ keeps them per corner)",
                              "texture coordinates not written: PLY holds one per vertex, and some vertex has none "
                              "or several, as at a seam (OBJ keeps them per corner)"}));
  const std::string ply = test::read_bytes(file("out.ply"));
  EXPECT_NE(ply.find("element face 3\n"), std::string::npos);
  EXPECT_NE(ply.find("\n4 0 1 2 3\n4 1 4 5 2\n3 4 6 5\n"), std::string::npos) << ply;

  WriteReport off_report;
  write_mesh(file("out.off"), m, {}, &off_report);
  EXPECT_EQ(off_report.notes.size(), 2u);  // texture coordinates, normals
  const Mesh off = read_mesh(file("out.off"));
  EXPECT_EQ(off.F, m.F);
  EXPECT_EQ(off.face_polygon, m.face_polygon);
}

TEST_F(IoAttributes, PlyVertexNormalsAndTextureCoordinatesRoundTrip) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n"
      "property float quality\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0 1 0 0 7\n1 0 0 0 0 1 1 0 7\n1 1 0 0 0 1 1 1 7\n0 1 0 0 0 1 0 1 7\n4 0 1 2 3\n";
  const Mesh m = read_mesh(write("in.ply", text));
  ASSERT_EQ(m.TC.rows(), 4);
  EXPECT_EQ(m.TC.row(2), Eigen::RowVector2d(1, 1));
  EXPECT_EQ(m.FTC, m.F);  // per-vertex values: each corner uses its vertex's row
  EXPECT_EQ(m.FN, m.F);
  EXPECT_EQ(m.vertex_scalars.size(), 1u);  // quality; nx..nz and s, t are attributes now
  WriteReport report;
  write_mesh(file("out.ply"), m, {}, &report);
  EXPECT_TRUE(report.notes.empty());
  const Mesh back = read_mesh(file("out.ply"));
  EXPECT_EQ(back.TC, m.TC);
  EXPECT_EQ(back.N, m.N);
  EXPECT_EQ(back.F, m.F);
  EXPECT_EQ(back.face_polygon, m.face_polygon);
  EXPECT_EQ(back.vertex_scalars.at("quality"), m.vertex_scalars.at("quality"));
}

TEST_F(IoAttributes, CornerIndicesOutsideTheirTableReadAsNoneWithANote) {
  ReadReport report;
  const Mesh m = read_mesh(write("in.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n"), &report);
  EXPECT_EQ(m.FTC.row(0), Eigen::RowVector3i(0, -1, 0));
  EXPECT_EQ(report.notes, std::vector<std::string>{"1 texture indices of 'f' corners outside the 1 'vt' lines: read as none"});
}

TEST_F(IoAttributes, MismatchedAttributesAreRefusedBeforeWriting) {
  Mesh m = read_mesh(write("in.obj", kSeamObj));
  m.FTC.conservativeResize(4, 3);
  EXPECT_THROW(write_mesh(file("a.obj"), m), InvalidArgument);
  m = read_mesh(file("in.obj"));
  m.FN(4, 1) = 2;  // N has 2 rows
  EXPECT_THROW(write_mesh(file("a.obj"), m), InvalidArgument);
  m = read_mesh(file("in.obj"));
  m.face_polygon.resize(2);
  EXPECT_THROW(write_mesh(file("a.obj"), m), InvalidArgument);
  EXPECT_FALSE(std::filesystem::exists(file("a.obj")));
}
