// Tests that an operation builds each mesh's connectivity once and passes it down (docs/architecture.md:
// "connectivity is built once"), read from the diagnostic counter topology_builds() (topology.h).
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/smooth.h>
#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <vector>

#include "analytic_meshes.h"
#include "hole_meshes.h"

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
// group, one per distinct mesh: the patched mesh (the membrane, the fairing's cut and the next
// group read it), the membrane's region, the fairing's neighbourhood (its validation, ∆³ solves,
// flow and held-out trials read it); and the two one-sided face sets measure_continuity fits.
// Before the connectivity was passed down: 33 and 63 (3 per operation, 30 per group).
TEST(TopologyBuilds, FillBuildsEachMeshsConnectivityOnce) {
  using Vec3 = Eigen::Vector3d;
  const Mesh sphere = test::icosphere(3);
  const Mesh one = test::cut_hole(sphere, [](const Vec3& p) { return p.z() > 0.5; });
  const Mesh two = test::cut_hole(sphere, [](const Vec3& p) { return std::abs(p.z()) > 0.6; });
  const std::uint64_t single = fill_builds(one, 1), pair = fill_builds(two, 2);
  std::cout << "topologies built: " << single << " for one hole, " << pair << " for two separate holes\n";
  EXPECT_EQ(pair - single, 5u);  // per group
  EXPECT_EQ(single, 1u + 5u);
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

// fair_region (`fairsurf fair`'s defaults): the mesh's (its validation's), the neighbourhood's (the
// ∆³ solve, the flow and the held-out trials read it) and the continuity measure's two face sets.
TEST(TopologyBuilds, FairRegionBuildsTheMeshAndItsNeighbourhoodOnce) {
  Mesh mesh = test::icosphere(4);
  std::vector<int> free;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (mesh.V(v, 2) > 0.8) free.push_back(v);
  const std::uint64_t before = topology_builds();
  fair_region(mesh, free, FairRegionOptions::harmonic_started());
  const std::uint64_t builds = topology_builds() - before;
  std::cout << "topologies built by fair_region: " << builds << "\n";
  EXPECT_EQ(builds, 4u);
}
