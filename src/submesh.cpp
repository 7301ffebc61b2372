#include <fairsurf/submesh.h>

namespace fairsurf {

Submesh extract_neighbourhood(const Vertices& V, const Faces& F, const Topology& topo,
                              std::span<const int> free_vertices, int rings) {
  const std::vector<int> dist = ring_distances(topo, free_vertices, rings);
  std::vector<char> keep_face(F.rows(), 0), keep_vertex(V.rows(), 0);
  for (int v = 0; v < topo.num_vertices; ++v)
    if (dist[v] >= 0)
      for (int f : topo.vertex_faces.row(v)) keep_face[f] = 1;
  int num_faces = 0;
  for (int f = 0; f < F.rows(); ++f)
    if (keep_face[f]) {
      ++num_faces;
      for (int k = 0; k < 3; ++k) keep_vertex[F(f, k)] = 1;
    }
  for (int v : free_vertices) keep_vertex[v] = 1;  // an isolated free vertex still belongs

  Submesh sub;
  std::vector<int> to_local(V.rows(), -1);
  for (int v = 0; v < V.rows(); ++v)
    if (keep_vertex[v]) {
      to_local[v] = static_cast<int>(sub.to_global.size());
      sub.to_global.push_back(v);
    }
  sub.mesh.V.resize(static_cast<Eigen::Index>(sub.to_global.size()), 3);
  for (std::size_t i = 0; i < sub.to_global.size(); ++i) sub.mesh.V.row(i) = V.row(sub.to_global[i]);
  sub.mesh.F.resize(num_faces, 3);
  for (int f = 0, row = 0; f < F.rows(); ++f)
    if (keep_face[f])
      for (int k = 0; k < 3; ++k) sub.mesh.F(row, k) = to_local[F(f, k)], row += (k == 2);
  for (int v = 0; v < topo.num_vertices; ++v)
    if (dist[v] == 0) sub.free_local.push_back(to_local[v]);
  return sub;
}

void write_back_free(const Submesh& sub, Vertices& V) {
  for (int local : sub.free_local) V.row(sub.to_global[local]) = sub.mesh.V.row(local);
}

}  // namespace fairsurf
