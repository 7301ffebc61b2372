// End-to-end tests of what the commands keep (issue #16, "data kept"): texture coordinates, normals
// and polygon faces of an OBJ through convert, smooth, fair, curvature, fill, blend, repair and info.
#include <fairsurf/io/io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scratch_dir.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

constexpr int kCells = 12;  // quads per side of the grid

// A bumpy quad grid with one texture coordinate per vertex and one normal per corner row
// (vn j: all corners of row j of quads share it), optionally with a 2 by 2 hole in the middle.
std::string quad_grid_obj(bool hole) {
  std::ostringstream out;
  out.precision(17);
  const auto id = [](int i, int j) { return j * (kCells + 1) + i + 1; };
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      const double x = double(i) / kCells, y = double(j) / kCells;
      out << "v " << x << ' ' << y << ' ' << 0.3 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)) + 0.01 * std::sin(7 * i + 3 * j) << '\n';
    }
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) out << "vt " << double(i) / kCells << ' ' << double(j) / kCells << '\n';
  for (int j = 0; j < kCells; ++j) out << "vn 0 0 1\n";
  const int c = kCells / 2;
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      if (hole && i >= c - 1 && i <= c && j >= c - 1 && j <= c) continue;
      out << 'f';
      for (const int v : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) out << ' ' << v << '/' << v << '/' << j + 1;
      out << '\n';
    }
  return out.str();
}

std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) lines.push_back(line);
  return lines;
}

class CliAttributes : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    grid_ = quad_grid_obj(false);
    std::ofstream(file("grid.obj")) << grid_;
    std::ofstream(file("holed.obj")) << quad_grid_obj(true);
  }
  test::CliRun run(const std::string& arguments) const { return test::run_cli(arguments); }
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string q(const std::string& name) const { return std::string("'").append(file(name)).append("'"); }

  std::string grid_;
};

}  // namespace

TEST_F(CliAttributes, ConvertKeepsQuadsTextureCoordinatesAndNormals) {
  const test::CliRun c = run("convert " + q("grid.obj") + " -o " + q("out.obj"));
  ASSERT_EQ(c.exit_code, 0) << c.out;
  const std::string out = test::read_bytes(file("out.obj"));
  EXPECT_EQ(lines_starting(out, "f "), lines_starting(grid_, "f "));  // 144 quads, v/vt/vn each corner
  EXPECT_EQ(lines_starting(out, "vt ").size(), 169u);
  EXPECT_EQ(lines_starting(out, "vn ").size(), 12u);
}

TEST_F(CliAttributes, SmoothKeepsFacesAndUvsAndRecomputesTheNormalsOfMovedVertices) {
  const test::CliRun s = run("smooth " + q("grid.obj") + " -o " + q("out.obj") + " --fixed-rings 1 --quiet");
  ASSERT_EQ(s.exit_code, 0) << s.out;
  EXPECT_NE(s.out.find("out.obj: recomputed 12 of 12 normals from the faces around them: their vertices moved"),
            std::string::npos) << s.out;
  const std::string out = test::read_bytes(file("out.obj"));
  EXPECT_EQ(lines_starting(out, "f "), lines_starting(grid_, "f "));
  EXPECT_EQ(lines_starting(out, "vt "), lines_starting(grid_, "vt "));
  const Mesh in = read_mesh(file("grid.obj")), smoothed = read_mesh(file("out.obj"));
  EXPECT_GT((smoothed.V - in.V).cwiseAbs().maxCoeff(), 1e-4);  // the vertices moved
  ASSERT_EQ(smoothed.N.rows(), 12);
  for (int r = 0; r < 12; ++r) {
    EXPECT_NEAR(smoothed.N.row(r).norm(), 1.0, 1e-12);
    EXPECT_GT(std::abs(smoothed.N(r, 0)) + std::abs(smoothed.N(r, 1)), 1e-3) << "row " << r << " still (0, 0, 1)";
  }
}

TEST_F(CliAttributes, FairKeepsFacesAndUvs) {
  const test::CliRun f = run("fair " + q("grid.obj") + " -o " + q("out.obj") + " --region-sphere 0.5,0.5,0,0.2 --quiet");
  ASSERT_EQ(f.exit_code, 0) << f.out;
  const std::string out = test::read_bytes(file("out.obj"));
  EXPECT_EQ(lines_starting(out, "f "), lines_starting(grid_, "f "));
  EXPECT_EQ(lines_starting(out, "vt "), lines_starting(grid_, "vt "));
}

TEST_F(CliAttributes, CurvatureWritesQuadsAndPerVertexUvsAndNormalsToPly) {
  const test::CliRun c = run("curvature " + q("grid.obj") + " -o " + q("out.ply"));
  ASSERT_EQ(c.exit_code, 0) << c.out;
  // Each vertex has one texture coordinate and one normal value (the rows' normals are all (0, 0, 1),
  // and curvature moves nothing), so PLY holds both as vertex properties.
  EXPECT_EQ(c.out.find("not written"), std::string::npos) << c.out;
  const Mesh back = read_mesh(file("out.ply"));
  const Mesh in = read_mesh(file("grid.obj"));
  ASSERT_EQ(back.TC.rows(), 169);
  for (int f = 0; f < in.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(back.TC.row(back.FTC(f, k)), in.TC.row(in.FTC(f, k)));
  ASSERT_EQ(back.N.rows(), 169);
  EXPECT_EQ(back.N.col(2).minCoeff(), 1.0);
  EXPECT_EQ(back.face_polygon.size(), 288);  // 144 quads, fanned again on reading
  EXPECT_EQ(back.vertex_scalars.count("H"), 1u);
}

TEST_F(CliAttributes, FillKeepsTheOldFacesAttributesAndSaysWhatTheNewOnesLack) {
  const test::CliRun f = run("fill " + q("holed.obj") + " -o " + q("out.obj") + " --skip-largest --quiet");
  ASSERT_EQ(f.exit_code, 0) << f.out;
  const std::vector<std::string> in_faces = lines_starting(quad_grid_obj(true), "f ");
  const std::vector<std::string> out_faces = lines_starting(test::read_bytes(file("out.obj")), "f ");
  ASSERT_GT(out_faces.size(), in_faces.size());
  const std::string added = std::to_string(out_faces.size() - in_faces.size());
  EXPECT_NE(f.out.find("holed.obj: the " + added + " faces fill added have no texture coordinates or normals; "
                       "the input's faces keep theirs"), std::string::npos) << f.out;
  EXPECT_EQ(std::vector<std::string>(out_faces.begin(), out_faces.begin() + in_faces.size()), in_faces);
  for (std::size_t i = in_faces.size(); i < out_faces.size(); ++i)
    EXPECT_EQ(out_faces[i].find('/'), std::string::npos) << out_faces[i];
}

TEST_F(CliAttributes, RepairKeepsThemAndInfoSaysWhatTheFileHolds) {
  const test::CliRun r = run("repair " + q("grid.obj") + " -o " + q("out.obj"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(lines_starting(test::read_bytes(file("out.obj")), "f "), lines_starting(grid_, "f "));
  const test::CliRun i = run("info " + q("out.obj"));
  ASSERT_EQ(i.exit_code, 0) << i.out;
  EXPECT_NE(i.out.find("\ntexture coordinates: 169 (on 288 of 288 triangles)\nnormals: 12 (on 288 of 288 triangles)\n"
                       "polygons of 4 or more corners: 144\n"), std::string::npos) << i.out;
}

TEST_F(CliAttributes, BlendKeepsTheInputFacesTextureCoordinatesAndSaysWhatTheTubeLacks) {
  ASSERT_EQ(run("scene fig4 -o " + q("caps.obj")).exit_code, 0);
  // The two caps with one texture coordinate per vertex: its x and y.
  std::ostringstream textured, texture_lines, faces;
  std::istringstream in(test::read_bytes(file("caps.obj")));
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line.substr(2));
    if (line.rfind("v ", 0) == 0) {
      std::string x, y;
      fields >> x >> y;
      textured << line << '\n';
      texture_lines << "vt " << x << ' ' << y << '\n';
    } else if (line.rfind("f ", 0) == 0) {
      faces << 'f';
      for (std::string v; fields >> v;) faces << ' ' << v << '/' << v;
      faces << '\n';
    }
  }
  textured << texture_lines.str() << faces.str();
  std::ofstream(file("textured.obj")) << textured.str();

  const test::CliRun b = run("blend " + q("textured.obj") + " -o " + q("out.obj") + " --quiet");
  ASSERT_EQ(b.exit_code, 0) << b.out;
  const std::vector<std::string> in_faces = lines_starting(faces.str(), "f ");
  const std::vector<std::string> out_faces = lines_starting(test::read_bytes(file("out.obj")), "f ");
  ASSERT_GT(out_faces.size(), in_faces.size());
  const std::string added = std::to_string(out_faces.size() - in_faces.size());
  EXPECT_NE(b.out.find("textured.obj: the " + added + " faces blend added have no texture coordinates; the "
                       "input's faces keep theirs"), std::string::npos) << b.out;
  EXPECT_EQ(std::vector<std::string>(out_faces.begin(), out_faces.begin() + in_faces.size()), in_faces);
  for (std::size_t i = in_faces.size(); i < out_faces.size(); ++i)
    EXPECT_EQ(out_faces[i].find('/'), std::string::npos) << out_faces[i];
}
