// Tests that an operation builds each mesh's connectivity once and passes it down (docs/architecture.md:
// "connectivity is built once"), read from the diagnostic counter topology_builds() (topology.h).
#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/smooth.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <vector>

#include "analytic_meshes.h"
#include "hole_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

// Topologies built by one fill_holes of `holed` with the default options; every hole must fill.
std::uint64_t fill_builds(const Mesh& holed, int holes) {
  Mesh filled = holed;
  const std::uint64_t before = topology_builds();
  const FillReport report = fill_holes(filled, FillOptions{});
  const std::uint64_t builds = topology_builds() - before;
  EXPECT_EQ(report.filled, holes);
  return builds;
}

}  // namespace

TEST(TopologyBuilds, CountsEveryBuild) {
  const Mesh sphere = test::icosphere(1);
  const std::uint64_t before = topology_builds();
  build_topology(sphere.F, sphere.num_vertices());
  build_topology(sphere.F, sphere.num_vertices());
  EXPECT_EQ(topology_builds() - before, 2u);
}

// The default fill (G2 flow from the re-evaluated ∆³ start, with the held-out check) of one hole,
// and of two holes far apart (two groups). Once per operation: the input (its validation's). Per
// group none: the patched mesh's connectivity extends the mesh's (extend_topology), and the
// membrane's region, the fairing's neighbourhood (its validation, ∆³ solves, flow and held-out
// trials) and the two one-sided face sets measure_continuity fits are parts of it, whose
// connectivity derives from it (derive_topology). Before the connectivity was passed down: 33 and
// 63 (3 per operation, 30 per group); before the parts derived theirs: 6 and 11 (1, and 5 per
// group); before the patched mesh's was extended: 2 and 3.
TEST(TopologyBuilds, FillBuildsEachMeshsConnectivityOnce) {
  using Vec3 = Eigen::Vector3d;
  const Mesh sphere = test::icosphere(3);
  const Mesh one = test::cut_hole(sphere, [](const Vec3& p) { return p.z() > 0.5; });
  const Mesh two = test::cut_hole(sphere, [](const Vec3& p) { return std::abs(p.z()) > 0.6; });
  const std::uint64_t single = fill_builds(one, 1), pair = fill_builds(two, 2);
  std::cout << "topologies built: " << single << " for one hole, " << pair << " for two separate holes\n";
  EXPECT_EQ(pair, single);  // none per group
  EXPECT_EQ(single, 1u);
}

// smooth validates the mesh, takes the default time and flows on one connectivity (before: 5).
TEST(TopologyBuilds, SmoothBuildsTheMeshsConnectivityOnce) {
  Mesh mesh = test::jittered_sphere(2, 1.0, 0.02);
  SmoothOptions options;
  options.flow.kind = FlowKind::mean_curvature;
  options.flow.max_steps = 2;
  const std::uint64_t before = topology_builds();
  smooth(mesh, options);
  EXPECT_EQ(topology_builds() - before, 1u);
}

// fair_region (`fairsurf fair`'s defaults) builds the mesh's connectivity (its validation's); the
// neighbourhood's (the ∆³ solve, the flow and the held-out trials read it) and the continuity
// measure's two face sets derive theirs from it (before: 4 builds). Given the connectivity, it
// builds none, and neither does measure_continuity.
TEST(TopologyBuilds, FairRegionBuildsTheMeshsConnectivityOnce) {
  const Mesh sphere = test::icosphere(4);
  std::vector<int> free;
  for (int v = 0; v < sphere.num_vertices(); ++v)
    if (sphere.V(v, 2) > 0.8) free.push_back(v);
  Mesh mesh = sphere;
  std::uint64_t before = topology_builds();
  const FairRegionReport report = fair_region(mesh, free, FairRegionOptions::harmonic_started());
  const std::uint64_t builds = topology_builds() - before;
  std::cout << "topologies built by fair_region: " << builds << "\n";
  EXPECT_EQ(builds, 1u);
  EXPECT_GT(report.continuity.border_vertices, 0);  // the measure ran, on derived connectivity

  mesh = sphere;
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  before = topology_builds();
  fair_region(mesh, topo, free, FairRegionOptions::harmonic_started());
  measure_continuity(mesh.V, mesh.F, topo, free);
  EXPECT_EQ(topology_builds() - before, 0u);
}

// blend_loops builds the input's connectivity (its loops, the reference measures, the tube); the
// tubed mesh's (the membrane, the fairing, the border measures) extends it, and the measured parts
// derive theirs (before: 22 on this mesh; before the tubed mesh's was extended: 2).
TEST(TopologyBuilds, BlendBuildsTheInputsAndTheTubedMeshsConnectivity) {
  Mesh mesh = read_mesh(test::data_path("cgal_blobby_3cc.off"));
  const std::uint64_t before = topology_builds();
  const BlendReport report = blend_loops(mesh);
  EXPECT_EQ(topology_builds() - before, 1u);
  EXPECT_GT(report.a.reference.border_vertices, 0);  // the reference measures ran
  EXPECT_GT(report.b.border.border_vertices, 0);
}
