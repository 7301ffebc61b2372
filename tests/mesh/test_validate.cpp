#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_summary.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>

#include "hole_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

Mesh with_vertex_rows(const Mesh& m, std::initializer_list<Eigen::RowVector3d> rows) {
  Mesh out = m;
  out.V.conservativeResize(m.V.rows() + static_cast<int>(rows.size()), 3);
  int i = static_cast<int>(m.V.rows());
  for (const auto& r : rows) out.V.row(i++) = r;
  return out;
}

Mesh with_face_rows(const Mesh& m, std::initializer_list<Eigen::RowVector3i> rows) {
  Mesh out = m;
  out.F.conservativeResize(m.F.rows() + static_cast<int>(rows.size()), 3);
  int i = static_cast<int>(m.F.rows());
  for (const auto& r : rows) out.F.row(i++) = r;
  return out;
}

// A closed torus: an n by m grid of quads wrapped in both directions, each split in two.
Mesh torus(int n, int m) {
  Mesh t;
  t.V.resize(n * m, 3);
  t.F.resize(2 * n * m, 3);
  const double two_pi = 2 * std::numbers::pi;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = two_pi * i / n, v = two_pi * j / m;
      t.V.row(i * m + j) << (2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u),
          std::sin(v);
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = i * m + (j + 1) % m,
                d = ((i + 1) % n) * m + (j + 1) % m;
      t.F.row(2 * a) << a, b, d;
      t.F.row(2 * a + 1) << a, d, c;
    }
  return t;
}

// A Moebius strip of n quads (2n triangles): top vertices t_i = i, bottom b_i = n + i. Quad i joins
// rung (t_i, b_i) to rung (t_{i+1}, b_{i+1}); the last quad joins rung n-1 to rung 0 swapped
// (b_0, t_0), which is the half twist. All quads are oriented alike, so the only edge traversed
// twice in the same direction is the closing rung t_0-b_0.
Mesh moebius(int n) {
  Mesh m;
  m.V.resize(2 * n, 3);
  m.F.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double u = 2 * std::numbers::pi * i / n, w = 0.3;
    for (int side = 0; side < 2; ++side) {
      const double s = side == 0 ? w : -w;
      const double r = 1 + s * std::cos(u / 2);
      m.V.row(side * n + i) << r * std::cos(u), r * std::sin(u), s * std::sin(u / 2);
    }
    const int a = i, b = n + i;
    const int c = i + 1 < n ? i + 1 : n, d = i + 1 < n ? n + i + 1 : 0;
    m.F.row(2 * i) << a, b, d;
    m.F.row(2 * i + 1) << a, d, c;
  }
  return m;
}

// Three triangles sharing the edge 0-1 (a fin), consistently oriented two by two where possible.
Mesh fin() {
  Mesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
  m.F.resize(3, 3);
  m.F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  return m;
}

// Two triangles touching only at vertex 0 (a bowtie).
Mesh bowtie() {
  Mesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 3, 4;
  return m;
}

std::vector<int> edge(int a, int b) { return {a, b}; }

int total_count(const ValidationReport& r) {
  int total = 0;
  for (const auto& named : named_findings(r)) total += named.finding->count;
  return total;
}

}  // namespace

TEST(Validate, CleanTetrahedronHasNoFinding) {
  const ValidationReport r = validate(test::tetrahedron());
  EXPECT_EQ(total_count(r), 0);
  EXPECT_EQ(r.num_edges, 6);
  EXPECT_FALSE(r.no_faces);
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.orientable());
  EXPECT_TRUE(r.is_valid());
  EXPECT_NO_THROW(require_valid(test::tetrahedron(), {}, "test"));
}

TEST(Validate, NanAndInfiniteCoordinates) {
  Mesh m = test::tetrahedron();
  m.V(2, 1) = std::numeric_limits<double>::quiet_NaN();
  m.V(3, 0) = -std::numeric_limits<double>::infinity();
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.nan_vertices.count, 2);
  EXPECT_EQ(r.nan_vertices.examples, (std::vector<int>{2, 3}));
  // Faces with a non-finite corner have no shape to judge.
  EXPECT_EQ(r.degenerate_faces.count, 0);
  EXPECT_FALSE(r.is_valid());
  EXPECT_THROW(require_valid(m, {}, "test"), InvalidMeshError);
}

TEST(Validate, OutOfRangeIndicesAreReportedAndTheRestIsStillAnalysed) {
  // build_topology would throw on this mesh; validate skips the two bad faces.
  const Mesh m = with_face_rows(test::tetrahedron(), {{0, 1, 7}, {-1, 2, 3}});
  ValidationReport r;
  ASSERT_NO_THROW(r = validate(m));
  EXPECT_EQ(r.out_of_range_indices.count, 2);
  EXPECT_EQ(r.out_of_range_indices.examples, (std::vector<int>{4, 5}));
  EXPECT_EQ(r.num_edges, 6);
  EXPECT_EQ(r.non_manifold_edges.count, 0);
  EXPECT_FALSE(r.manifold());
}

TEST(Validate, FacesRepeatingAVertex) {
  const Mesh m = with_face_rows(test::tetrahedron(), {{1, 1, 2}, {3, 0, 3}});
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.repeated_vertex_faces.count, 2);
  EXPECT_EQ(r.repeated_vertex_faces.examples, (std::vector<int>{4, 5}));
  EXPECT_EQ(r.degenerate_faces.count, 0);  // not counted twice
  EXPECT_EQ(r.out_of_range_indices.count, 0);
}

TEST(Validate, NoFaces) {
  Mesh m;
  m.V = test::tetrahedron().V;
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.no_faces);
  EXPECT_EQ(r.unreferenced_vertices.count, 4);
  EXPECT_FALSE(r.is_valid());
  try {
    require_valid(m, {}, "smooth");
    FAIL() << "no exception";
  } catch (const InvalidMeshError& e) {
    EXPECT_STREQ(e.what(), "smooth: mesh has no faces");
  }
}

TEST(Validate, ZeroAreaAndNeedleTriangles) {
  Mesh m;
  m.V.resize(7, 3);
  m.V << 0, 0, 0, 1, 0, 0, 2, 0, 0,  // collinear
      0, 0, 1, 1, 0, 1, 0.5, 1e-14, 1,   // a needle: height 1e-14 over a unit edge
      5, 5, 5;                           // coincides with nothing; used by a face twice below
  m.F.resize(4, 3);
  m.F << 0, 1, 2, 3, 4, 5, 0, 1, 3, 6, 6, 6;
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.degenerate_faces.count, 1);
  EXPECT_EQ(r.degenerate_faces.examples, (std::vector<int>{0}));
  EXPECT_EQ(r.near_degenerate_faces.count, 1);
  EXPECT_EQ(r.near_degenerate_faces.examples, (std::vector<int>{1}));
  EXPECT_EQ(r.repeated_vertex_faces.count, 1);

  ValidationOptions strict_zero;
  strict_zero.near_degenerate_tolerance = 0;
  EXPECT_EQ(validate(m, strict_zero).near_degenerate_faces.count, 0);
}

TEST(Validate, DuplicateFacesMatchVertexSetsInAnyOrder) {
  // Face 1 again in both orientations: two duplicates, and its three edges now carry three faces.
  const Mesh m = with_face_rows(test::tetrahedron(), {{1, 3, 0}, {3, 1, 0}});
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.duplicate_faces.count, 2);
  EXPECT_EQ(r.duplicate_faces.examples, (std::vector<int>{4, 5}));
  EXPECT_EQ(r.non_manifold_edges.count, 3);
  EXPECT_EQ(r.non_manifold_edges.examples, (std::vector<int>{0, 1, 0, 3, 1, 3}));
}

TEST(Validate, UnreferencedVerticesKeepOnlyTheFirstExamples) {
  Mesh m = test::tetrahedron();
  m.V.conservativeResize(14, 3);
  for (int v = 4; v < 14; ++v) m.V.row(v) << v, 0, 0;
  ValidationOptions options;
  options.max_examples = 3;
  const ValidationReport r = validate(m, options);
  EXPECT_EQ(r.unreferenced_vertices.count, 10);
  EXPECT_EQ(r.unreferenced_vertices.examples, (std::vector<int>{4, 5, 6}));
  EXPECT_EQ(format_examples(r.unreferenced_vertices, 2), "4, 5");
}

TEST(Validate, DuplicateVertexPositionsOfAnUnweldedSoup) {
  // Two triangles of a square, each with its own copy of the shared diagonal's corners.
  Mesh m;
  m.V.resize(6, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 3, 4, 5;
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.duplicate_vertex_positions.count, 2);
  EXPECT_EQ(r.duplicate_vertex_positions.examples, (std::vector<int>{3, 4}));
  const MeshSummary s = summarize(m, r);
  EXPECT_EQ(s.components, 2);
  EXPECT_EQ(s.boundary_loop_lengths, (std::vector<int>{3, 3}));
  EXPECT_EQ(s.lone_triangles, 2);  // each triangle's three edges are on the border
}

// A ball hole in a sphere with a triangle hanging at one vertex of its border: that triangle is the
// one lone triangle; the hole's own border faces each keep an edge inside the mesh.
TEST(MeshSummary, ALoneTriangleHangingAtAHoleIsCountedAndNoOtherFace) {
  const Mesh m = test::sphere_hole_with_lone_triangle();
  const MeshSummary s = summarize(m, validate(m));
  EXPECT_EQ(s.lone_triangles, 1);
  EXPECT_EQ(s.boundary_loop_lengths.size(), 2u);
}

TEST(Validate, FinHasOneNonManifoldEdgeButNoNonManifoldVertex) {
  const ValidationReport r = validate(fin());
  EXPECT_EQ(r.non_manifold_edges.count, 1);
  EXPECT_EQ(r.non_manifold_edges.examples, edge(0, 1));
  // The three faces around vertex 0 are joined through edge 0-1: one fan.
  EXPECT_EQ(r.non_manifold_vertices.count, 0);
  // Only two-face edges can be inconsistently oriented.
  EXPECT_EQ(r.inconsistent_orientation_edges.count, 0);
  EXPECT_FALSE(r.manifold());
  try {
    require_valid(fin(), {}, "fill");
    FAIL() << "no exception";
  } catch (const InvalidMeshError& e) {
    EXPECT_STREQ(e.what(), "fill: mesh has 1 non-manifold edge (first: 0-1)");
  }
  Requirements lenient;
  lenient.manifold = false;
  EXPECT_NO_THROW(require_valid(fin(), lenient, "fill"));
}

TEST(Validate, BowtieVertexIsNonManifold) {
  const ValidationReport r = validate(bowtie());
  EXPECT_EQ(r.non_manifold_vertices.count, 1);
  EXPECT_EQ(r.non_manifold_vertices.examples, (std::vector<int>{0}));
  EXPECT_EQ(r.non_manifold_edges.count, 0);
  EXPECT_FALSE(r.manifold());
  EXPECT_FALSE(summarize(bowtie(), r).genus.has_value());
}

TEST(Validate, FlippedFaceGivesInconsistentEdgesButStaysOrientable) {
  Mesh m = test::tetrahedron();
  m.F.row(3) << 1, 3, 2;  // reversed
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.inconsistent_orientation_edges.count, 3);
  EXPECT_EQ(r.inconsistent_orientation_edges.examples, (std::vector<int>{1, 2, 1, 3, 2, 3}));
  EXPECT_TRUE(r.orientable());
  EXPECT_TRUE(r.manifold());
  try {
    require_valid(m, {}, "smooth");
    FAIL() << "no exception";
  } catch (const InvalidMeshError& e) {
    EXPECT_STREQ(e.what(), "smooth: mesh has 3 inconsistently oriented edges (first: 1-2)");
  }
}

TEST(Validate, MoebiusStripIsNonOrientable) {
  const Mesh m = moebius(5);
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.manifold());
  EXPECT_EQ(r.inconsistent_orientation_edges.count, 1);
  EXPECT_EQ(r.inconsistent_orientation_edges.examples, edge(0, 5));
  EXPECT_EQ(r.non_orientable_components.count, 1);
  EXPECT_FALSE(r.orientable());
  const MeshSummary s = summarize(m, r);
  EXPECT_EQ(s.euler_characteristic, 0);
  EXPECT_EQ(s.boundary_loop_lengths, (std::vector<int>{10}));
  EXPECT_FALSE(s.genus.has_value());
}

TEST(Validate, SeveralDefectsAtOnceNeverThrowAndAllAppearInOneMessage) {
  Mesh m = with_face_rows(fin(), {{0, 1, 9}, {2, 2, 4}, {1, 2, 0}});
  m.V(4, 2) = std::numeric_limits<double>::quiet_NaN();
  ValidationReport r;
  ASSERT_NO_THROW(r = validate(m));
  EXPECT_EQ(r.nan_vertices.count, 1);
  EXPECT_EQ(r.out_of_range_indices.count, 1);
  EXPECT_EQ(r.repeated_vertex_faces.count, 1);
  EXPECT_EQ(r.duplicate_faces.count, 1);
  try {
    require_valid(r, {}, "blend");
    FAIL() << "no exception";
  } catch (const InvalidMeshError& e) {
    EXPECT_STREQ(e.what(),
                 "blend: mesh has 1 vertex with a NaN or infinite coordinate (first: 4), "
                 "1 face with an out-of-range vertex index (first: 3), "
                 "1 face repeating a vertex (first: 4), "
                 "1 non-manifold edge (first: 0-1), "
                 "2 inconsistently oriented edges (first: 0-2), "
                 "1 duplicate face (first: 5)");
  }
}

TEST(Validate, WellFormedFacesKeepsOrderAndReportsKeptRows) {
  Faces F(4, 3);
  F << 0, 1, 2, 0, 0, 1, 1, 2, 5, 2, 1, 0;
  std::vector<int> kept;
  const Faces good = well_formed_faces(F, 3, &kept);
  EXPECT_EQ(kept, (std::vector<int>{0, 3}));
  ASSERT_EQ(good.rows(), 2);
  EXPECT_EQ(good.row(1), F.row(3));
}

TEST(MeshSummary, TetrahedronAndTwoCopiesHaveGenusZero) {
  const Mesh tet = test::tetrahedron();
  const MeshSummary s = summarize(tet, validate(tet));
  EXPECT_EQ(s.vertices, 4);
  EXPECT_EQ(s.faces, 4);
  EXPECT_EQ(s.edges, 6);
  EXPECT_EQ(s.euler_characteristic, 2);
  EXPECT_EQ(s.genus, 0);
  EXPECT_TRUE(s.boundary_loop_lengths.empty());

  Mesh two = with_vertex_rows(tet, {{5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}});
  two.F.conservativeResize(8, 3);
  two.F.bottomRows(4) = tet.F.array() + 4;
  const MeshSummary s2 = summarize(two, validate(two));
  EXPECT_EQ(s2.components, 2);
  EXPECT_EQ(s2.euler_characteristic, 4);
  EXPECT_EQ(s2.genus, 0);
  EXPECT_EQ(s2.bounding_box.min(), Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(s2.bounding_box.max(), Eigen::Vector3d(6, 1, 1));
}

TEST(MeshSummary, TorusHasGenusOne) {
  const Mesh t = torus(12, 8);
  const MeshSummary s = summarize(t, validate(t));
  EXPECT_EQ(s.edges, 3 * 12 * 8);
  EXPECT_EQ(s.euler_characteristic, 0);
  EXPECT_EQ(s.genus, 1);
  EXPECT_EQ(s.components, 1);
}

TEST(MeshSummary, GridDiskBoundaryAndMeanEdgeLength) {
  const double h = 0.5;
  const Mesh grid = test::regular_grid(2, 1, h);
  const MeshSummary s = summarize(grid, validate(grid));
  EXPECT_EQ(s.boundary_loop_lengths, (std::vector<int>{6}));
  EXPECT_EQ(s.boundary_edges, 6);
  EXPECT_EQ(s.euler_characteristic, 1);
  EXPECT_EQ(s.genus, 0);
  // 7 axis-aligned edges of length h and 2 diagonals of length h*sqrt(2).
  EXPECT_NEAR(s.mean_edge_length, (7 * h + 2 * h * std::sqrt(2.0)) / 9, 1e-15);
}

TEST(MeshSummary, ReferencedVerticesAndNonFiniteVerticesInTheBox) {
  Mesh m = with_vertex_rows(test::tetrahedron(), {{9, 9, 9}, {std::nan(""), 0, 0}});
  const MeshSummary s = summarize(m, validate(m));
  EXPECT_EQ(s.vertices, 6);
  EXPECT_EQ(s.referenced_vertices, 4);
  EXPECT_EQ(s.euler_characteristic, 2);  // unreferenced vertices do not count
  EXPECT_EQ(s.bounding_box.max(), Eigen::Vector3d(9, 9, 9));
}

// ---- Bundled meshes (data/README.md): documented defects and topology figures ----

namespace {

struct Loaded {
  Mesh mesh;
  ValidationReport report;
  MeshSummary summary;
};

Loaded load(const std::string& name) {
  Loaded l;
  l.mesh = read_mesh(test::data_path(name));
  l.report = validate(l.mesh);
  l.summary = summarize(l.mesh, l.report);
  return l;
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST(ValidateData, StanfordBunnyZipperRes2) {
  const Loaded l = load("stanford_bunny_zipper_res2.ply");
  EXPECT_EQ(l.summary.vertices, 8171);
  EXPECT_EQ(l.summary.faces, 16301);
  EXPECT_EQ(l.report.non_manifold_edges.count, 150);
  EXPECT_EQ(l.report.duplicate_faces.count, 87);
  EXPECT_EQ(l.report.unreferenced_vertices.count, 25);
  EXPECT_EQ(l.report.non_manifold_vertices.count, 0);
  EXPECT_FALSE(l.report.manifold());
  EXPECT_FALSE(l.summary.genus.has_value());
}

TEST(ValidateData, LagrangeProut) {
  const Loaded l = load("lagrange_prout.obj");
  EXPECT_EQ(l.summary.vertices, 1023);
  EXPECT_EQ(l.summary.faces, 1937);
  EXPECT_EQ(l.report.non_manifold_edges.count, 20);
  EXPECT_EQ(l.report.non_manifold_vertices.count, 4);
  EXPECT_EQ(l.report.duplicate_faces.count, 5);
  EXPECT_EQ(l.report.inconsistent_orientation_edges.count, 18);
}

TEST(ValidateData, HourglassIcoHasOneNonManifoldVertex) {
  const Loaded l = load("hourglass_ico.obj");
  EXPECT_EQ(l.summary.vertices, 23);
  EXPECT_EQ(l.summary.faces, 40);
  EXPECT_EQ(l.report.non_manifold_vertices.count, 1);
  EXPECT_EQ(l.report.non_manifold_edges.count, 0);
  EXPECT_TRUE(l.summary.boundary_loop_lengths.empty());
  // Every other finding is absent: the one defect is the shared vertex.
  int others = 0;
  for (const auto& named : named_findings(l.report))
    if (named.finding != &l.report.non_manifold_vertices) others += named.finding->count;
  EXPECT_EQ(others, 0);
}

TEST(ValidateData, TripleVierbeinHasTwentyNonManifoldEdges) {
  const Loaded l = load("triple_vierbein.obj");
  EXPECT_EQ(l.summary.vertices, 75);
  EXPECT_EQ(l.summary.faces, 108);
  EXPECT_EQ(l.report.non_manifold_edges.count, 20);
}

TEST(ValidateData, CgalDegtriSlidingHasFourZeroAreaTriangles) {
  const Loaded l = load("cgal_degtri_sliding.off");
  EXPECT_EQ(l.summary.vertices, 8);
  EXPECT_EQ(l.summary.faces, 8);
  EXPECT_EQ(l.report.degenerate_faces.count, 4);
  EXPECT_EQ(l.summary.boundary_loop_lengths.size(), 1u);
}

TEST(ValidateData, CubeSoupIsSixComponentsWithSixteenDuplicatePositions) {
  const Loaded l = load("cube_soup.obj");
  EXPECT_EQ(l.summary.vertices, 24);
  EXPECT_EQ(l.summary.faces, 12);
  EXPECT_EQ(l.summary.components, 6);
  EXPECT_EQ(l.report.duplicate_vertex_positions.count, 16);
  EXPECT_EQ(l.summary.boundary_loop_lengths.size(), 6u);
}

TEST(ValidateData, MoebiusIsManifoldButNonOrientable) {
  const Loaded l = load("moebius_160_10.ply");
  EXPECT_EQ(l.summary.vertices, 1600);
  EXPECT_EQ(l.summary.faces, 2880);
  EXPECT_TRUE(l.report.manifold());
  EXPECT_FALSE(l.report.orientable());
  EXPECT_EQ(l.report.non_orientable_components.count, 1);
  EXPECT_EQ(l.report.inconsistent_orientation_edges.count, 9);
  EXPECT_EQ(l.summary.boundary_loop_lengths, (std::vector<int>{320}));
  EXPECT_EQ(l.summary.euler_characteristic, 0);
}

// The manifold meshes of data/README.md's table: #V, #F, boundary loops (with their lengths where
// the README gives them), components; all clean, orientable, and genus as documented.
struct ManifoldCase {
  const char* file;
  int vertices, faces;
  int loops;
  std::vector<int> loop_lengths;  // sorted; empty when the README does not give them
  int components;
  int genus;
  int unreferenced;
};

class ValidateManifoldData : public ::testing::TestWithParam<ManifoldCase> {};

TEST_P(ValidateManifoldData, MatchesTheDataReadme) {
  const ManifoldCase& c = GetParam();
  const Loaded l = load(c.file);
  EXPECT_EQ(l.summary.vertices, c.vertices);
  EXPECT_EQ(l.summary.faces, c.faces);
  EXPECT_EQ(static_cast<int>(l.summary.boundary_loop_lengths.size()), c.loops);
  if (!c.loop_lengths.empty()) {
    EXPECT_EQ(sorted(l.summary.boundary_loop_lengths), c.loop_lengths);
  }
  EXPECT_EQ(l.summary.components, c.components);
  EXPECT_TRUE(l.report.manifold());
  EXPECT_TRUE(l.report.orientable());
  EXPECT_EQ(l.report.inconsistent_orientation_edges.count, 0);
  EXPECT_EQ(l.report.unreferenced_vertices.count, c.unreferenced);
  EXPECT_EQ(l.summary.genus, c.genus);
}

INSTANTIATE_TEST_SUITE_P(
    Readme, ValidateManifoldData,
    ::testing::Values(
        ManifoldCase{"stanford_bunny_zipper.obj", 35947, 69451, 5, {}, 1, 0, 1113},
        ManifoldCase{"cgal_mech_holes_shark.off", 5246, 10192, 4, {48, 80, 80, 96}, 1, 0, 0},
        ManifoldCase{"demosthenes_scan_lowres.obj", 8394, 16719, 1, {67}, 1, 0, 0},
        ManifoldCase{"airplane_holes.obj", 8519, 16747, 27, {}, 1, 0, 0},
        ManifoldCase{"airplane.obj", 8730, 17456, 0, {}, 1, 0, 0},
        ManifoldCase{"blub_open.obj", 5857, 11648, 1, {64}, 1, 0, 0},
        ManifoldCase{"blub.obj", 7106, 14208, 0, {}, 1, 0, 0},
        ManifoldCase{"spot.obj", 2930, 5856, 0, {}, 1, 0, 0},
        ManifoldCase{"torus.obj", 2304, 4608, 0, {}, 1, 1, 0},
        ManifoldCase{"sphere_16k.off", 16070, 32136, 0, {}, 1, 0, 0},
        ManifoldCase{"hammer_rawscan.obj", 30082, 60160, 0, {}, 1, 0, 0},
        ManifoldCase{"fairing_cross.off", 4983, 9762, 4, {52, 52, 52, 52}, 1, 0, 0},
        ManifoldCase{"hemisphere.off", 1861, 3600, 1, {120}, 1, 0, 0},
        ManifoldCase{"hand_lowres.obj", 810, 1602, 1, {16}, 1, 0, 0},
        ManifoldCase{"cgal_blobby_3cc.off", 1820, 3417, 4, {}, 3, 0, 0}),
    [](const auto& info) {
      std::string name = info.param.file;
      std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(ch); }, '_');
      return name;
    });

TEST(ValidateData, BlobbyLoopsSplitTwoCapsAndOneBand) {
  // Two end caps with one loop each and a middle band with two (data/README.md).
  const Loaded l = load("cgal_blobby_3cc.off");
  const Faces F = l.mesh.F;
  const Topology topo = build_topology(F, l.mesh.num_vertices());
  const Components comps = connected_components(F, topo);
  std::vector<int> loops_per_component(comps.count, 0);
  for (const auto& loop : boundary_loops(F, topo)) ++loops_per_component[comps.vertex_component[loop[0]]];
  EXPECT_EQ(sorted(loops_per_component), (std::vector<int>{1, 1, 2}));
}
