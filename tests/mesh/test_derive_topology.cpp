// derive_topology and extend_topology (topology.h): the connectivity of a part of a mesh, derived
// from the whole mesh's, and of a mesh grown by added faces, extended from the smaller mesh's, must
// equal build_topology of their faces field by field, since every later stage reads them as if they
// had been built (an order that differed would change results, not only counts).
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/submesh.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/patch.h>

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "analytic_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

// Whether two topologies hold the same values in every field.
bool same_topology(const Topology& a, const Topology& b) {
  const auto same_csr = [](const Csr& x, const Csr& y) { return x.offsets == y.offsets && x.indices == y.indices; };
  return a.num_vertices == b.num_vertices && a.num_faces == b.num_faces &&
         same_csr(a.vertex_vertices, b.vertex_vertices) && same_csr(a.vertex_faces, b.vertex_faces) &&
         a.edges.rows() == b.edges.rows() && a.edges == b.edges && same_csr(a.edge_faces, b.edge_faces) &&
         a.face_edges == b.face_edges;
}

// The faces `faces` of F with their vertices compacted in ascending order (as a submesh keeps them),
// or over all of the parent's vertices (as the continuity measure keeps one side's faces).
struct Part {
  Faces F;
  std::vector<int> to_parent;
};

Part part_of(const Faces& F, int num_vertices, const std::vector<int>& faces, bool compact) {
  std::vector<int> local(num_vertices, -1);
  for (int f : faces)
    for (int k = 0; k < 3; ++k) local[F(f, k)] = 0;
  Part part;
  for (int v = 0; v < num_vertices; ++v)
    if (!compact || local[v] == 0) local[v] = static_cast<int>(part.to_parent.size()), part.to_parent.push_back(v);
  part.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) part.F(static_cast<Eigen::Index>(i), k) = local[F(faces[i], k)];
  return part;
}

// Derives the part's topology from the parent's and compares it with the part's own build.
void expect_derived_equals_built(const Topology& parent, const Part& part) {
  const std::uint64_t before = topology_builds();
  const Topology derived = derive_topology(parent, part.F, part.to_parent);
  EXPECT_EQ(topology_builds(), before) << "deriving is not a build";
  const Topology built = build_topology(part.F, static_cast<int>(part.to_parent.size()));
  EXPECT_TRUE(same_topology(derived, built)) << part.F.rows() << " faces over " << part.to_parent.size()
                                             << " vertices";
}

// Seven faces over vertices 0-8 (build_topology's for 10 leaves vertex 9 without a face): an edge
// with three faces, a face given twice, two fans at a vertex.
Faces non_manifold_faces() {
  Faces F(7, 3);
  F << 0, 1, 2,  //
      1, 0, 3,   // the edge 0-1 has three faces
      0, 1, 4,   //
      0, 1, 2,   // the first face again
      2, 1, 5,   //
      4, 6, 7,   // a second fan at vertex 4
      7, 6, 8;
  return F;
}

// Extends the connectivity of F's first `base_faces` rows over `base_vertices` vertices to all of F
// over `num_vertices`, and compares it with F's own build.
void expect_extended_equals_built(const Faces& F, int base_faces, int base_vertices, int num_vertices) {
  const Topology base = build_topology(F.topRows(base_faces), base_vertices);
  const std::uint64_t before = topology_builds();
  const Topology extended = extend_topology(base, F, num_vertices);
  EXPECT_EQ(topology_builds(), before) << "extending is not a build";
  EXPECT_TRUE(same_topology(extended, build_topology(F, num_vertices)))
      << base_faces << " of " << F.rows() << " faces, " << base_vertices << " of " << num_vertices << " vertices";
}

}  // namespace

// A hole's patch added to a scan, as hole_patch adds it (refined, so with new vertices): the
// patched mesh's connectivity is extended from the scan's.
TEST(ExtendTopology, APatchedScanEqualsItsBuild) {
  const Mesh mesh = read_mesh(test::data_path("stanford_bunny_zipper.obj"));
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const std::vector<std::vector<int>> loops = boundary_loops(mesh.F, topo);
  ASSERT_GE(loops.size(), 2u);
  const InitialPatch patch = hole_patch(mesh, topo, {loops[0], loops[1]});
  ASSERT_GT(patch.mesh.num_vertices(), mesh.num_vertices());
  EXPECT_TRUE(same_topology(patch.topology, build_topology(patch.mesh.F, patch.mesh.num_vertices())));
  expect_extended_equals_built(patch.mesh.F, mesh.num_faces(), mesh.num_vertices(), patch.mesh.num_vertices());
}

// Faces added in every split of a closed mesh, a grid with a border and a thin torus: the added
// faces take base edges, new edges before, between and after the base's, and vertices that only
// they use; none added, or all.
TEST(ExtendTopology, EverySplitOfAMeshEqualsItsBuild) {
  for (const Mesh& mesh : {test::icosphere(1), test::regular_grid(5, 4), test::torus_grid(12, 4, 1.0, 0.1).mesh}) {
    const int n = mesh.num_faces();
    for (int base_faces : {0, 1, n / 3, n / 2, n - 1, n}) {
      int base_vertices = 0;  // the vertices the base faces use, as if the later ones were added
      for (int f = 0; f < base_faces; ++f)
        for (int k = 0; k < 3; ++k) base_vertices = std::max(base_vertices, mesh.F(f, k) + 1);
      expect_extended_equals_built(mesh.F, base_faces, base_vertices, mesh.num_vertices());
      expect_extended_equals_built(mesh.F, base_faces, mesh.num_vertices(), mesh.num_vertices() + 2);
    }
  }
}

// build_topology represents non-manifold meshes; so does the extension, whichever faces are added.
TEST(ExtendTopology, ANonManifoldMeshEqualsItsBuild) {
  const Faces F = non_manifold_faces();
  for (int base_faces = 0; base_faces <= F.rows(); ++base_faces) expect_extended_equals_built(F, base_faces, 9, 10);
}

TEST(ExtendTopology, RejectsAddedFacesBuildWouldRejectAndAShrunkMesh) {
  const Mesh grid = test::regular_grid(2, 2);
  const Topology topo = build_topology(grid.F, grid.num_vertices());
  Faces grown(grid.num_faces() + 1, 3);
  grown.topRows(grid.num_faces()) = grid.F;
  grown.bottomRows(1) << 0, 9, 4;  // vertex 9 is outside the 9 vertices
  EXPECT_THROW(extend_topology(topo, grown, grid.num_vertices()), InvalidArgument);
  grown.bottomRows(1) << 0, 4, 4;
  EXPECT_THROW(extend_topology(topo, grown, grid.num_vertices()), InvalidArgument);
  EXPECT_THROW(extend_topology(topo, grid.F.topRows(2), grid.num_vertices()), InvalidArgument);
  EXPECT_THROW(extend_topology(topo, grid.F, grid.num_vertices() - 1), InvalidArgument);
}

// Neighbourhoods as fill and fair_region cut them (0 rings: the membrane's; 6: the fairing's) around
// a border of a real scan, and the whole scan as its own part.
TEST(DeriveTopology, SubmeshesOfARealScanEqualTheirBuild) {
  const Mesh mesh = read_mesh(test::data_path("stanford_bunny_zipper.obj"));
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const std::vector<std::vector<int>> loops = boundary_loops(mesh.F, topo);
  ASSERT_GE(loops.size(), 2u);
  for (int rings : {0, 2, 6}) {
    const Submesh sub = extract_neighbourhood(mesh.V, mesh.F, topo, loops[1], rings);
    ASSERT_LT(sub.mesh.num_faces(), mesh.num_faces());
    expect_derived_equals_built(topo, Part{sub.mesh.F, sub.to_global});
  }
  std::vector<int> all(mesh.num_faces());
  std::iota(all.begin(), all.end(), 0);
  expect_derived_equals_built(topo, part_of(mesh.F, mesh.num_vertices(), all, true));
}

// One side of a region's border over all of the parent's vertices (the continuity measure's face
// sets), on a grid with a border: the other side's vertices stay, without faces.
TEST(DeriveTopology, OneSideOfARegionOnAMeshWithBorder) {
  const Mesh grid = test::regular_grid(8, 6);
  const Topology topo = build_topology(grid.F, grid.num_vertices());
  std::vector<int> inside, outside;
  for (int f = 0; f < grid.num_faces(); ++f) (grid.V(grid.F(f, 0), 0) < 3.5 ? inside : outside).push_back(f);
  expect_derived_equals_built(topo, part_of(grid.F, grid.num_vertices(), inside, false));
  expect_derived_equals_built(topo, part_of(grid.F, grid.num_vertices(), outside, false));
  // Every other face: a part whose vertices join fans that touch at a corner only.
  std::vector<int> checkerboard;
  for (int f = 0; f < grid.num_faces(); f += 2) checkerboard.push_back(f);
  expect_derived_equals_built(topo, part_of(grid.F, grid.num_vertices(), checkerboard, true));
}

// Rings around a vertex of a thin torus wrap around its tube and touch themselves on the far side.
TEST(DeriveTopology, NeighbourhoodWhoseRingsTouchThemselves) {
  const Mesh torus = test::torus_grid(24, 5, 1.0, 0.1).mesh;
  const Topology topo = build_topology(torus.F, torus.num_vertices());
  for (int rings : {1, 2, 3}) {
    const std::vector<int> seed{0};
    const Submesh sub = extract_neighbourhood(torus.V, torus.F, topo, seed, rings);
    ASSERT_LT(sub.mesh.num_faces(), torus.num_faces());
    expect_derived_equals_built(topo, Part{sub.mesh.F, sub.to_global});
  }
}

// build_topology represents a non-manifold parent (an edge with three faces, a face given twice, two
// fans at a vertex); every part of it derives what it builds.
TEST(DeriveTopology, EveryPartOfANonManifoldParent) {
  const Faces F = non_manifold_faces();
  const Topology topo = build_topology(F, 10);  // vertex 9 has no face
  for (int subset = 1; subset < (1 << F.rows()); ++subset) {
    std::vector<int> faces;
    for (int f = 0; f < F.rows(); ++f)
      if (subset & (1 << f)) faces.push_back(f);
    expect_derived_equals_built(topo, part_of(F, 10, faces, true));
    expect_derived_equals_built(topo, part_of(F, 10, faces, false));
  }
}

TEST(DeriveTopology, RejectsWhatIsNotAPartOfTheParent) {
  const Mesh grid = test::regular_grid(2, 2);
  const Topology topo = build_topology(grid.F, grid.num_vertices());
  const std::vector<int> all = [&] {
    std::vector<int> v(grid.num_vertices());
    std::iota(v.begin(), v.end(), 0);
    return v;
  }();
  Faces across(1, 3);
  across << 0, 8, 4;  // 0-8 is no edge of the grid
  try {
    derive_topology(topo, across, all);
    FAIL() << "a face across the grid was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "derive_topology: face 0 has an edge the parent does not");
  }
  const std::vector<int> descending{2, 1, 0};
  Faces first(1, 3);
  first << 0, 1, 2;
  EXPECT_THROW(derive_topology(topo, first, descending), InvalidArgument);
  const std::vector<int> two{0, 1};
  EXPECT_THROW(derive_topology(topo, first, two), InvalidArgument);  // vertex 2 of 2
}
