#include <fairsurf/mesh/submesh.h>

#include <algorithm>

namespace fairsurf {
namespace {

// Fans of the kept faces around v: the faces at v form paths and cycles in v's link, so the count
// of path components is (#link vertices − #faces) when no cycle is closed.
int kept_fans(const Faces& F, const Topology& topo, const std::vector<char>& keep_face, int v) {
  std::vector<int> link;
  int faces = 0;
  for (int f : topo.vertex_faces.row(v)) {
    if (!keep_face[f]) continue;
    ++faces;
    for (int k = 0; k < 3; ++k)
      if (F(f, k) != v) link.push_back(F(f, k));
  }
  std::sort(link.begin(), link.end());
  const int distinct = static_cast<int>(std::unique(link.begin(), link.end()) - link.begin());
  return distinct - faces;
}

// Keeps every face of each vertex where the kept faces would meet in two or more fans: the rings
// around a free region can touch themselves on their outer side (a saddle, a thin part), and the
// neighbourhood would then have a non-manifold vertex the whole mesh does not have. Growing it
// there only adds fixed data.
void close_pinches(const Faces& F, const Topology& topo, std::vector<char>& keep_face) {
  std::vector<int> work;
  for (int f = 0; f < F.rows(); ++f)
    if (keep_face[f])
      for (int k = 0; k < 3; ++k) work.push_back(F(f, k));
  while (!work.empty()) {
    const int v = work.back();
    work.pop_back();
    const auto faces = topo.vertex_faces.row(v);
    const bool all_kept = std::all_of(faces.begin(), faces.end(), [&](int f) { return keep_face[f] != 0; });
    if (all_kept || kept_fans(F, topo, keep_face, v) < 2) continue;
    for (int f : faces)
      if (!keep_face[f]) {
        keep_face[f] = 1;
        for (int k = 0; k < 3; ++k) work.push_back(F(f, k));
      }
  }
}

}  // namespace

Submesh extract_neighbourhood(const Vertices& V, const Faces& F, const Topology& topo,
                              std::span<const int> free_vertices, int rings) {
  const std::vector<int> dist = ring_distances(topo, free_vertices, rings);
  std::vector<char> keep_face(F.rows(), 0), keep_vertex(V.rows(), 0);
  for (int v = 0; v < topo.num_vertices; ++v)
    if (dist[v] >= 0)
      for (int f : topo.vertex_faces.row(v)) keep_face[f] = 1;
  close_pinches(F, topo, keep_face);
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
