#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region_selection.h>
#include <fairsurf/mesh/submesh.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_support.h"

using namespace fairsurf;

namespace {

std::filesystem::path write_text(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(RegionSelection, ReadsIndicesWithCommentsSortedAndUnique) {
  const auto path = write_text("fairsurf_region_ok.txt", "# free region\n5 3\n\t3 12 # again\n0\n");
  EXPECT_EQ(read_vertex_indices(path, 13), (std::vector<int>{0, 3, 5, 12}));
}

TEST(RegionSelection, RejectsBadIndicesWithLineAndToken) {
  const auto path = write_text("fairsurf_region_bad.txt", "1 2\n3 x7\n");
  try {
    read_vertex_indices(path, 10);
    FAIL() << "no exception";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "read_vertex_indices: " + path.string() +
                                         ":2: 'x7' is not a vertex index in [0, 10)");
  }
  const auto range = write_text("fairsurf_region_range.txt", "10\n");
  EXPECT_THROW(read_vertex_indices(range, 10), ParseError);
  EXPECT_THROW(read_vertex_indices("/nonexistent/region.txt", 10), IoError);
}

TEST(RegionSelection, BallAndProperty) {
  Mesh m = test::regular_grid(4, 4);
  EXPECT_EQ(vertices_in_ball(m.V, Eigen::Vector3d(2, 2, 0), 1.01),
            (std::vector<int>{7, 11, 12, 13, 17}));
  EXPECT_THROW(vertices_in_ball(m.V, Eigen::Vector3d::Zero(), -1), InvalidArgument);
  m.vertex_scalars["mask"] = Eigen::VectorXd::Zero(m.num_vertices());
  m.vertex_scalars["mask"][4] = 1;
  m.vertex_scalars["mask"][9] = 0.5;
  EXPECT_EQ(vertices_with_property(m, "mask"), (std::vector<int>{4, 9}));
  try {
    vertices_with_property(m, "region");
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(),
                 "vertices_with_property: the mesh has no vertex property 'region' (it has: mask)");
  }
}

TEST(Submesh, KeepsTheRingsAroundTheRegionAndWritesBack) {
  const int n = 30;
  Mesh m = test::regular_grid(n, n);
  const Topology topo = build_topology(m.F, m.num_vertices());
  const int centre = 15 * (n + 1) + 15;
  const int seeds[] = {centre};
  const Submesh sub = extract_neighbourhood(m.V, m.F, topo, seeds, 3);
  // Faces touching the 3-ring hexagon: its vertices plus one more ring, a hexagon of radius 4.
  EXPECT_EQ(sub.to_global.size(), static_cast<std::size_t>(1 + 3 * 4 * 5));
  ASSERT_EQ(sub.free_local.size(), 1u);
  EXPECT_EQ(sub.to_global[sub.free_local[0]], centre);
  // Every interior vertex of the submesh within 3 rings keeps its full star (valence 6).
  const Topology local = build_topology(sub.mesh.F, sub.mesh.num_vertices());
  EXPECT_EQ(local.vertex_vertices.size(sub.free_local[0]), 6);
  EXPECT_TRUE(std::is_sorted(sub.to_global.begin(), sub.to_global.end()));

  Submesh moved = sub;
  moved.mesh.V.row(moved.free_local[0]) << 1, 2, 3;
  write_back_free(moved, m.V);
  EXPECT_EQ(m.V.row(centre), Eigen::RowVector3d(1, 2, 3));
}
