#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_quality.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace fairsurf {

int count_inverted_faces(const Vertices& reference, const Vertices& V, const Faces& F) {
  if (reference.rows() != V.rows())
    throw InvalidArgument("count_inverted_faces: the reference has " + std::to_string(reference.rows()) +
                          " vertices, the mesh " + std::to_string(V.rows()));
  Eigen::MatrixX3d before, after;
  Eigen::VectorXd area_before, area_after;
  face_normals_and_areas(reference, F, before, area_before);
  face_normals_and_areas(V, F, after, area_after);
  int inverted = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) inverted += !(before.row(f).dot(after.row(f)) > 0);
  return inverted;
}

double noise_index(const Vertices& V, const Faces& F, const Topology& topo,
                   const std::vector<char>& counted) {
  if (!counted.empty() && static_cast<int>(counted.size()) != topo.num_vertices)
    throw InvalidArgument("noise_index: " + std::to_string(counted.size()) + " flags for " +
                          std::to_string(topo.num_vertices) + " vertices");
  Eigen::MatrixX3d face_normal;
  Eigen::VectorXd face_area;
  face_normals_and_areas(V, F, face_normal, face_area);
  Eigen::VectorXd umbrella = Eigen::VectorXd::Zero(topo.num_vertices);
  for (int v = 0; v < topo.num_vertices; ++v) {
    if (topo.vertex_vertices.size(v) == 0) continue;
    Eigen::RowVector3d normal = Eigen::RowVector3d::Zero(), centre = Eigen::RowVector3d::Zero();
    for (int f : topo.vertex_faces.row(v)) normal += face_area[f] * face_normal.row(f);
    for (int u : topo.vertex_vertices.row(v)) centre += V.row(u);
    centre /= static_cast<double>(topo.vertex_vertices.size(v));
    umbrella[v] = (centre - V.row(v)).dot(normal);
  }
  int edges = 0, opposite = 0;
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e) {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    if (!counted.empty() && !(counted[a] && counted[b])) continue;
    ++edges;
    opposite += umbrella[a] * umbrella[b] < 0;
  }
  return edges > 0 ? static_cast<double>(opposite) / edges : 0.0;
}

namespace {

// Fewer 2-ring neighbours leave the six coefficients of the height function barely determined.
constexpr int kFewestRoughnessNeighbours = 8;
// A 2-ring with a face steeper than 60° to the vertex's normal is no height function over its
// tangent plane (a crease, the edge of a thin part): no quadratic predicts it, smooth or not.
constexpr double kSteepestRoughnessFace = 0.5;

// Face f's normal times twice its area.
Eigen::RowVector3d area_normal(const Vertices& V, const Faces& F, int f) {
  const Eigen::RowVector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
  return (b - a).cross(c - a);
}

// roughness at one vertex; NaN where it is left out.
double vertex_roughness(const Vertices& V, const Faces& F, const Topology& topo, const Eigen::RowVector3d& normal,
                        int v, std::vector<int>& neighbours) {
  neighbours.clear();
  for (int u : topo.vertex_vertices.row(v))
    for (int w : topo.vertex_vertices.row(u))
      if (w != v) neighbours.push_back(w);
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  const int n = static_cast<int>(neighbours.size());
  if (n < kFewestRoughnessNeighbours || !(normal.norm() > 0)) return NAN;
  for (int u : topo.vertex_vertices.row(v))
    for (int f : topo.vertex_faces.row(u)) {
      const Eigen::RowVector3d face_normal = area_normal(V, F, f);
      if (!(face_normal.dot(normal) > kSteepestRoughnessFace * face_normal.norm())) return NAN;
    }
  const Eigen::RowVector3d axis =
      std::abs(normal.x()) < 0.9 ? Eigen::RowVector3d::UnitX() : Eigen::RowVector3d::UnitY();
  const Eigen::RowVector3d e1 = normal.cross(axis).normalized(), e2 = normal.cross(e1);
  double edge = 0;
  for (int u : topo.vertex_vertices.row(v)) edge += (V.row(u) - V.row(v)).norm();
  edge /= static_cast<double>(topo.vertex_vertices.size(v));
  Eigen::MatrixXd basis(n, 6);
  Eigen::VectorXd height(n);
  for (int k = 0; k < n; ++k) {
    const Eigen::RowVector3d d = (V.row(neighbours[k]) - V.row(v)) / edge;
    const double x = d.dot(e1), y = d.dot(e2);
    basis.row(k) << 1, x, y, x * x, x * y, y * y;
    height[k] = d.dot(normal);
  }
  return std::abs(basis.colPivHouseholderQr().solve(height)[0]);
}

}  // namespace

double roughness(const Vertices& V, const Faces& F, const Topology& topo, std::span<const int> vertices) {
  std::vector<double> offsets;
  std::vector<int> neighbours;
  for (int v : vertices) {
    if (v < 0 || v >= topo.num_vertices)
      throw InvalidArgument("roughness: vertex " + std::to_string(v) + " is not one of the " +
                            std::to_string(topo.num_vertices));
    Eigen::RowVector3d normal = Eigen::RowVector3d::Zero();  // area-weighted
    for (int f : topo.vertex_faces.row(v)) normal += area_normal(V, F, f);
    if (normal.norm() > 0) normal.normalize();
    if (const double offset = vertex_roughness(V, F, topo, normal, v, neighbours); !std::isnan(offset))
      offsets.push_back(offset);
  }
  if (offsets.empty()) return 0;
  const auto middle = offsets.begin() + static_cast<std::ptrdiff_t>(offsets.size() / 2);
  std::nth_element(offsets.begin(), middle, offsets.end());
  return *middle;
}

}  // namespace fairsurf
