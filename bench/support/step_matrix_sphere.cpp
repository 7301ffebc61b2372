#include "step_matrix_sphere.h"

#include <fairsurf/mesh/topology.h>

#include <Eigen/SparseCore>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace fairsurf::bench {

Mesh icosphere(int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> points = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0},
                                         {0, -1, t}, {0, 1, t},  {0, -1, -t}, {0, 1, -t},
                                         {t, 0, -1}, {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : points) p.normalize();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    const auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, static_cast<int>(points.size()));
      if (inserted) points.push_back((points[a] + points[b]).normalized());
      return it->second;
    };
    std::vector<Eigen::Vector3i> finer;
    finer.reserve(4 * faces.size());
    for (const auto& f : faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    faces = std::move(finer);
  }
  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) mesh.V.row(static_cast<Eigen::Index>(i)) = points[i];
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) mesh.F.row(static_cast<Eigen::Index>(f)) = faces[f];
  return mesh;
}

SparseRowMatrix sphere_step_matrix_proxy(int subdivisions, double tau, double beta) {
  const Mesh mesh = icosphere(subdivisions);
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const double h = mean_edge_length(mesh.V, topo);
  std::vector<Eigen::Triplet<double>> laplacian, difference;
  for (int i = 0; i < topo.num_vertices; ++i) {
    laplacian.emplace_back(i, i, topo.vertex_vertices.size(i));
    for (int j : topo.vertex_vertices.row(i)) {
      laplacian.emplace_back(i, j, -1.0);
      difference.emplace_back(i, j, (mesh.V(j, 2) - mesh.V(i, 2)) / h);
    }
  }
  const int n = topo.num_vertices;
  SparseRowMatrix L(n, n), D(n, n), identity(n, n);
  L.setFromTriplets(laplacian.begin(), laplacian.end());
  D.setFromTriplets(difference.begin(), difference.end());
  identity.setIdentity();
  const SparseRowMatrix L2 = L * L;
  const SparseRowMatrix L3 = L2 * L;
  const SparseRowMatrix L2D = L2 * D;
  SparseRowMatrix A = identity + (tau / std::pow(h, 6)) * (L3 + beta * L2D);
  A.makeCompressed();
  return A;
}

}  // namespace fairsurf::bench
