// The paper's scenes (scenes.h) and what the flows do to them: Figs 7-8 in measured radii
// (method.md §8.5: mean curvature flow shrinks, Willmore inflates, the sixth-order flow with f = H keeps).
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/scenes.h>
#include <fairsurf/geometry/operators.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace fairsurf {
namespace {

Eigen::Vector3d face_normal(const Mesh& m, int f) {
  const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
  return (b - a).cross(c - a);
}

TEST(Scenes, AreValidAndOrientedOutward) {
  for (const auto& name : scene_names()) {
    const Scene s = make_scene(name, {0.2});
    const ValidationReport r = validate(s.mesh);
    EXPECT_TRUE(r.is_valid()) << name;
    // Outward: away from the z axis on cylinders and caps, up on the flat disk.
    int outward = 0;
    for (int f = 0; f < s.mesh.num_faces(); ++f) {
      const Eigen::Vector3d c = (s.mesh.V.row(s.mesh.F(f, 0)) + s.mesh.V.row(s.mesh.F(f, 1)) +
                                 s.mesh.V.row(s.mesh.F(f, 2))) / 3.0;
      const Eigen::Vector3d n = face_normal(s.mesh, f);
      const bool flat = name == "fig3" && std::abs(c.z()) < 1e-12;
      const Eigen::Vector3d centre = name == "fig3" ? Eigen::Vector3d(0, 0, 0.1) : Eigen::Vector3d::Zero();
      const Eigen::Vector3d away = name == "fig7" || name == "fig8" ? Eigen::Vector3d(c.x(), c.y(), 0) : c - centre;
      outward += flat ? n.z() > 0 : n.dot(away) > 0;
    }
    EXPECT_EQ(outward, s.mesh.num_faces()) << name;
    const Topology topo = build_topology(s.mesh.F, s.mesh.num_vertices());
    if (name == "fig3" || name == "fig4") {
      ASSERT_EQ(s.blend_loops.size(), 2u);
      EXPECT_TRUE(s.free_vertices.empty());
    } else {
      EXPECT_FALSE(s.free_vertices.empty()) << name;
      EXPECT_EQ(s.mesh.vertex_scalars.at("free").sum(), static_cast<double>(s.free_vertices.size()));
      const Region region = make_region(topo, s.free_vertices);
      EXPECT_EQ(region.complete_rings, 3) << name << ": G2 needs three fixed rings";
    }
  }
}

TEST(Scenes, RejectsUnknownNamesAndBadEdgeLengths) {
  try {
    make_scene("fig9");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "make_scene: unknown scene 'fig9' (scenes: fig3, fig4, fig7, fig8, sphere-cap)");
  }
  EXPECT_THROW(make_scene("fig3", {0.0}), InvalidArgument);
  EXPECT_EQ(icosphere(3).num_vertices(), 642);
}

double mean_radius_change(const Scene& s, const Vertices& V) {
  double sum = 0;
  for (int v : s.free_vertices) sum += V.row(v).head<2>().norm() - 1.0;
  return sum / static_cast<double>(s.free_vertices.size());
}

double max_radius_change(const Scene& s, const Vertices& V) {
  double worst = 0;
  for (int v : s.free_vertices) worst = std::max(worst, std::abs(V.row(v).head<2>().norm() - 1.0));
  return worst;
}

struct RadiusRun {
  double mean, max;
};

// The band flowed for T = 0.1 in scene units (normalize off), as method.md §8.5's cylinder.
RadiusRun flow_band(const Scene& s, Continuity c) {
  Mesh m = s.mesh;
  FairRegionOptions o;
  o.continuity = c;
  o.flow.normalize = false;
  o.flow.tau = 1e-3;
  o.flow.tau_max = 0.05;
  o.flow.end_time = 0.1;
  o.flow.steady_tolerance = 0;
  o.flow.steady_relative_tolerance = 0;
  const FairRegionReport r = fair_region(m, s.free_vertices, o);
  EXPECT_EQ(r.supported, c);
  return {mean_radius_change(s, m.V), max_radius_change(s, m.V)};
}

// The short fig8 ring is held by its clamped borders: Willmore flow inflates it far less than fig7.
void compare_flows(const std::string& name, double min_inflation) {
  const Scene s = make_scene(name, {0.2});
  const RadiusRun six = flow_band(s, Continuity::G2), willmore = flow_band(s, Continuity::G1),
                  mcf = flow_band(s, Continuity::G0);
  std::printf("[scenes] %s (%d free of %d vertices), T = 0.1: radius change (mean / max) sixth f = H %.3g / "
              "%.3g, Willmore %+.3g / %.3g, mean curvature %+.3g / %.3g\n",
              name.c_str(), static_cast<int>(s.free_vertices.size()), s.mesh.num_vertices(), six.mean, six.max,
              willmore.mean, willmore.max, mcf.mean, mcf.max);
  EXPECT_LT(six.max, 1e-3);
  EXPECT_GT(willmore.mean, min_inflation);
  EXPECT_LT(mcf.mean, -1e-2);
}

TEST(Scenes, Fig7CylinderShrinksUnderMeanCurvatureInflatesUnderWillmoreStaysUnderSixth) { compare_flows("fig7", 1e-3); }
TEST(Scenes, Fig8RingShrinksUnderMeanCurvatureInflatesUnderWillmoreStaysUnderSixth) { compare_flows("fig8", 5e-5); }

}  // namespace
}  // namespace fairsurf
