// triangulate_hole's dynamic programme against Liepa's recurrence written out plainly: every
// candidate weighed with every arctangent, nothing pruned. The programme skips candidates it can
// prove heavier and the arctangents it can prove irrelevant (src/patch/hole_triangulation.cpp); its
// triangulation must be the plain recurrence's, face for face and bit for bit, on holes that fold
// (where most candidates tie on the largest angle and area decides) and on holes that do not.
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/hole_triangulation.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "analytic_meshes.h"
#include "flow_meshes.h"
#include "hole_meshes.h"

using namespace fairsurf;

namespace {

using Vec3 = Eigen::Vector3d;

// As the library weighs a triangle: unnormalized, zero where degenerate.
Vec3 face_normal(const Vec3& pa, const Vec3& pb, const Vec3& pc) {
  const Vec3 n = (pb - pa).cross(pc - pa);
  const double longest = std::max({(pb - pa).squaredNorm(), (pc - pb).squaredNorm(), (pa - pc).squaredNorm()});
  return n.norm() <= 1e-12 * longest ? Vec3::Zero() : n;
}

double angle_between(const Vec3& n1, const Vec3& n2) {
  if (n1.isZero() || n2.isZero()) return std::numbers::pi;
  return std::atan2(n1.cross(n2).norm(), n1.dot(n2));
}

struct PlainWeight {
  double angle = std::numeric_limits<double>::infinity(), area = std::numeric_limits<double>::infinity();
  bool reached = false;
};

bool plainly_lighter(const PlainWeight& a, const PlainWeight& b) {
  if (a.angle < b.angle - kAngleTie) return true;
  if (a.angle > b.angle + kAngleTie) return false;
  return a.area < b.area;
}

// Liepa's recurrence from the loop's first vertex, every candidate weighed: the largest dihedral
// over the candidate, its two sub-polygons, and (closing the loop) the face outside the last side;
// then area. Diagonals that are mesh edges are not taken. Faces as (v_k, v_j, v_i).
std::vector<Eigen::Vector3i> plain_recurrence(const Mesh& mesh, const std::vector<int>& loop,
                                              double& largest_angle) {
  const int m = static_cast<int>(loop.size());
  std::set<std::pair<int, int>> edges;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.F(f, k), v = mesh.F(f, (k + 1) % 3);
      edges.insert({std::min(u, v), std::max(u, v)});
    }
  const auto position = [&](int t) -> Vec3 { return mesh.V.row(loop[t]).transpose(); };
  std::vector<Vec3> side(m, Vec3::Zero());  // the face outside side t → t+1
  for (int t = 0; t < m; ++t)
    for (int f = 0; f < mesh.num_faces(); ++f)
      for (int k = 0; k < 3; ++k)
        if (mesh.F(f, k) == loop[t] && mesh.F(f, (k + 1) % 3) == loop[(t + 1) % m])
          side[t] = face_normal(mesh.V.row(mesh.F(f, 0)).transpose(), mesh.V.row(mesh.F(f, 1)).transpose(),
                                mesh.V.row(mesh.F(f, 2)).transpose());
  std::vector<std::vector<PlainWeight>> weight(m, std::vector<PlainWeight>(m));
  std::vector<std::vector<int>> apex(m, std::vector<int>(m, -1));
  std::vector<std::vector<Vec3>> apex_normal(m, std::vector<Vec3>(m, Vec3::Zero()));
  for (int i = 0; i + 1 < m; ++i) weight[i][i + 1] = {0, 0, true};
  const auto inner = [&](int i, int k) { return k == i + 1 ? side[i] : apex_normal[i][k]; };
  for (int span = 2; span < m; ++span)
    for (int i = 0; i + span < m; ++i) {
      const int k = i + span;
      const bool top = i == 0 && k == m - 1;
      if (!top && edges.contains({std::min(loop[i], loop[k]), std::max(loop[i], loop[k])})) continue;
      PlainWeight best;
      for (int j = i + 1; j < k; ++j) {
        const PlainWeight& left = weight[i][j];
        const PlainWeight& right = weight[j][k];
        if (!left.reached || !right.reached) continue;
        const Vec3 n = face_normal(position(k), position(j), position(i));
        double angle = std::max({left.angle, right.angle, angle_between(n, inner(i, j)), angle_between(n, inner(j, k))});
        if (top && !side[m - 1].isZero()) angle = std::max(angle, angle_between(n, side[m - 1]));
        const PlainWeight w{angle, left.area + right.area + 0.5 * n.norm(), true};
        if (plainly_lighter(w, best)) best = w, apex[i][k] = j;
      }
      weight[i][k] = best;
      if (apex[i][k] >= 0) apex_normal[i][k] = face_normal(position(k), position(apex[i][k]), position(i));
    }
  largest_angle = weight[0][m - 1].angle;
  std::vector<Eigen::Vector3i> faces;
  std::vector<std::pair<int, int>> stack{{0, m - 1}};
  while (!stack.empty()) {
    const auto [i, k] = stack.back();
    stack.pop_back();
    if (k - i < 2) continue;
    const int j = apex[i][k];
    faces.emplace_back(loop[k], loop[j], loop[i]);
    stack.emplace_back(i, j);
    stack.emplace_back(j, k);
  }
  return faces;
}

std::set<std::vector<int>> face_set(const std::vector<Eigen::Vector3i>& faces) {
  std::set<std::vector<int>> out;
  for (const Eigen::Vector3i& f : faces) out.insert({f[0], f[1], f[2]});
  return out;
}

std::set<std::vector<int>> face_set(const Faces& faces) {
  std::set<std::vector<int>> out;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) out.insert({faces(f, 0), faces(f, 1), faces(f, 2)});
  return out;
}

// The single boundary loop of `mesh`.
std::vector<int> only_loop(const Mesh& mesh) {
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const auto loops = boundary_loops(mesh.F, topo);
  EXPECT_EQ(loops.size(), 1u);
  return loops.empty() ? std::vector<int>{} : loops.front();
}

}  // namespace

TEST(LiepaProgramme, GivesThePlainRecurrencesTriangulationOnHolesThatFoldAndHolesThatDoNot) {
  // Crowns of 20 to 150 edges whose every triangulation folds (largest angle above 2 rad), and a
  // bumpy sphere cut by balls of three sizes (below 1 rad).
  std::vector<std::pair<Mesh, std::vector<int>>> holes;
  for (const auto& [n, waves, amplitude] : {std::tuple{20, 2, 3.0}, {40, 2, 8.0}, {80, 5, 8.0}, {150, 3, 8.0}}) {
    Mesh crown = test::wavy_annulus(n, 1, amplitude, waves, 0.0);
    const Topology topo = build_topology(crown.F, crown.num_vertices());
    for (const std::vector<int>& loop : boundary_loops(crown.F, topo))
      if (std::find(loop.begin(), loop.end(), 0) != loop.end()) holes.emplace_back(crown, loop);
  }
  const Mesh bumpy = test::jittered_sphere(3, 1.0, 0.02, 3);
  for (const double radius : {0.3, 0.5, 0.8}) {
    Mesh holed = test::cut_ball(bumpy, Vec3(0, 0.6, 0.8), radius);
    const std::vector<int> loop = only_loop(holed);
    holes.emplace_back(std::move(holed), loop);
  }
  ASSERT_EQ(holes.size(), 7u);
  int folded = 0;
  for (const auto& [mesh, loop] : holes) {
    ASSERT_GE(loop.size(), 8u);
    ASSERT_LE(loop.size(), 200u);  // one programme, not divided
    double plain_angle = 0;
    const std::vector<Eigen::Vector3i> plain = plain_recurrence(mesh, loop, plain_angle);
    const Topology topo = build_topology(mesh.F, mesh.num_vertices());
    const HoleTriangulation got =
        triangulate_hole(mesh.V, mesh.F, topo, loop, {.start_vertices = 1, .max_crossing_rounds = 0});
    EXPECT_EQ(face_set(got.faces), face_set(plain)) << "loop of " << loop.size() << " edges";
    EXPECT_EQ(got.max_dihedral_angle, plain_angle) << "loop of " << loop.size() << " edges";
    folded += plain_angle > 2.0;
    EXPECT_TRUE(plain_angle > 2.0 || plain_angle < 1.0) << "loop of " << loop.size() << " edges";
  }
  EXPECT_EQ(folded, 4);  // the crowns
}
