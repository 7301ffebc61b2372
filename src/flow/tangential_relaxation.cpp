#include <fairsurf/flow/tangential_relaxation.h>
#include <fairsurf/mesh/errors.h>

#include "parallel.h"

#include <string>

namespace fairsurf {
namespace {

// weight · (I − n nᵀ)(mean of the neighbours − x_v) for each listed vertex (#listed by 3).
Vertices tangential_moves(const Vertices& X, const Topology& topo, std::span<const int> vertices,
                          const Vertices& normals, double weight) {
  const auto count = static_cast<Eigen::Index>(vertices.size());
  Vertices moves(count, 3);
#pragma omp parallel for if (detail::worth_parallel(count)) schedule(static)
  for (Eigen::Index k = 0; k < count; ++k) {
    const int v = vertices[static_cast<std::size_t>(k)];
    const auto neighbours = topo.vertex_vertices.row(v);
    Eigen::RowVector3d towards = Eigen::RowVector3d::Zero();
    for (int u : neighbours) towards += X.row(u);
    if (!neighbours.empty()) towards = towards / static_cast<double>(neighbours.size()) - X.row(v);
    const Eigen::RowVector3d n = normals.row(v);
    moves.row(k) = weight * (towards - towards.dot(n) * n);
  }
  return moves;
}

}  // namespace

void relax_tangentially(Vertices& X, const Topology& topo, std::span<const int> vertices,
                        const Vertices& normals, double weight) {
  if (!(weight >= 0 && weight <= 1))
    throw InvalidArgument("relax_tangentially: weight " + std::to_string(weight) + " is outside [0, 1]");
  if (X.rows() != topo.num_vertices || normals.rows() != X.rows())
    throw InvalidArgument("relax_tangentially: " + std::to_string(X.rows()) + " positions and " +
                          std::to_string(normals.rows()) + " normals for " +
                          std::to_string(topo.num_vertices) + " vertices in the topology");
  if (weight == 0 || vertices.empty()) return;
  const Vertices moves = tangential_moves(X, topo, vertices, normals, weight);
  for (std::size_t k = 0; k < vertices.size(); ++k) X.row(vertices[k]) += moves.row(static_cast<Eigen::Index>(k));
}

}  // namespace fairsurf
