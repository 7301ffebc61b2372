// derive_topology (topology.h): the connectivity of a part of a mesh, derived from the whole mesh's,
// must equal build_topology of the part's faces field by field, since every later stage reads it as
// if it had been built (an order that differed would change results, not only counts).
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/submesh.h>
#include <fairsurf/mesh/topology.h>

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

}  // namespace

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
  Faces F(7, 3);
  F << 0, 1, 2,  //
      1, 0, 3,   // the edge 0-1 has three faces
      0, 1, 4,   //
      0, 1, 2,   // the first face again
      2, 1, 5,   //
      4, 6, 7,   // a second fan at vertex 4
      7, 6, 8;
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
