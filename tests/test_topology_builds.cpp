// Tests that an operation builds each mesh's connectivity once and passes it down (docs/architecture.md:
// "connectivity is built once"), read from the diagnostic counter topology_builds() (topology.h).
#include <fairsurf/topology.h>

#include <gtest/gtest.h>

#include <cstdint>

#include "analytic_meshes.h"

using namespace fairsurf;

TEST(TopologyBuilds, CountsEveryBuild) {
  const Mesh sphere = test::icosphere(1);
  const std::uint64_t before = topology_builds();
  build_topology(sphere.F, sphere.num_vertices());
  build_topology(sphere.F, sphere.num_vertices());
  EXPECT_EQ(topology_builds() - before, 2u);
}
