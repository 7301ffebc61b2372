// The sixth-order flow on a real raw scan (data/hammer_rawscan.obj: irregular scan triangulation,
// edge-length CV 0.48, needle triangles down to 0.24°, noise one edge length high). A patch of the
// scan keeps the test to seconds: its free vertices see exactly what they see in the whole mesh
// (submesh.h).
#include <fairsurf/flow.h>
#include <fairsurf/io.h>
#include <fairsurf/region.h>
#include <fairsurf/submesh.h>
#include <fairsurf/topology.h>

#include <gtest/gtest.h>

#include "test_support.h"

using namespace fairsurf;

namespace {

// The data README's noise index over the edges between free vertices: the fraction whose endpoints
// have opposite signs of the umbrella operator's component along the area-weighted vertex normal.
double noise_index(const Vertices& V, const Faces& F, const Topology& topo, const Region& region) {
  Eigen::MatrixX3d face_normal;
  Eigen::VectorXd face_area;
  face_normals_and_areas(V, F, face_normal, face_area);
  Eigen::VectorXd umbrella(V.rows());
  for (int v = 0; v < V.rows(); ++v) {
    Eigen::RowVector3d normal = Eigen::RowVector3d::Zero(), centre = Eigen::RowVector3d::Zero();
    for (int f : topo.vertex_faces.row(v)) normal += face_area[f] * face_normal.row(f);
    for (int u : topo.vertex_vertices.row(v)) centre += V.row(u);
    centre /= static_cast<double>(topo.vertex_vertices.size(v));
    umbrella[v] = (centre - V.row(v)).dot(normal);
  }
  int edges = 0, flips = 0;
  for (int e = 0; e < topo.edges.rows(); ++e) {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    if (!region.is_free(a) || !region.is_free(b)) continue;
    ++edges;
    flips += umbrella[a] * umbrella[b] < 0;
  }
  return static_cast<double>(flips) / edges;
}

}  // namespace

TEST(FlowRealScan, HammerPatchStaysFiniteAndLosesEnergy) {
  const Mesh hammer = read_mesh(test::data_path("hammer_rawscan.obj"));
  const Topology full = build_topology(hammer.F, hammer.num_vertices());
  // About 1300 free vertices around vertex 19813, where the whole-mesh step failed first.
  const std::vector<int> seed{19813};
  const Submesh patch =
      extract_neighbourhood(hammer.V, hammer.F, full, k_ring(full, seed, 20), 6);
  const Topology topo = build_topology(patch.mesh.F, patch.mesh.num_vertices());
  const Region region = make_region(topo, patch.free_local, Continuity::G2);
  ASSERT_GT(region.num_free(), 1000);

  FlowOptions o;
  o.normalize = false;  // the whole scan's unit-diagonal units, as `fairsurf smooth` uses
  Vertices V = (patch.mesh.V.rowwise() - 0.5 * (hammer.V.colwise().maxCoeff() +
                                                  hammer.V.colwise().minCoeff())) /
               (hammer.V.colwise().maxCoeff() - hammer.V.colwise().minCoeff()).norm();
  const Vertices input = V;
  o.tau = 1e-21;
  o.max_steps = 12;
  o.step_control.limit_displacement = true;
  o.step_control.jacobian_dominance = 0.3;
  o.step_control.max_consecutive_rejections = 20;
  const FlowReport report = run_flow(V, patch.mesh.F, region, o);

  EXPECT_EQ(report.accepted_steps, 12);
  ASSERT_TRUE(V.allFinite());
  EXPECT_LT(report.final_energy, 0.5 * report.initial_energy);
  // Every step guards against faces turning by more than 90° within the step; over the run a few
  // needle triangles still flip (the scan has angles down to 0.24°): count them against the input.
  Eigen::MatrixX3d before, after;
  Eigen::VectorXd area_before, area_after;
  face_normals_and_areas(input, patch.mesh.F, before, area_before);
  face_normals_and_areas(V, patch.mesh.F, after, area_after);
  int inverted = 0;
  for (int f = 0; f < patch.mesh.num_faces(); ++f) inverted += before.row(f).dot(after.row(f)) <= 0;
  EXPECT_LT(inverted, patch.mesh.num_faces() / 200);
  const double noise_before = noise_index(input, patch.mesh.F, topo, region);
  const double noise_after = noise_index(V, patch.mesh.F, topo, region);
  std::printf("hammer patch: %d free vertices, %d accepted / %d rejected steps to t = %.3g, energy "
              "%.4g -> %.4g, noise index %.3f -> %.3f, %d of %d faces inverted\n",
              region.num_free(), report.accepted_steps, report.rejected_steps, report.time,
              report.initial_energy, report.final_energy, noise_before, noise_after, inverted,
              patch.mesh.num_faces());
}
