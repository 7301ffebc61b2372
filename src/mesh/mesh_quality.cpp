#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_quality.h>

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

}  // namespace fairsurf
