#include <fairsurf/mesh/mesh_summary.h>
#include <fairsurf/mesh/topology.h>

namespace fairsurf {
namespace {

// Sum over components of (2 - b - chi) / 2; callers ensure each component is an orientable
// manifold surface, for which the numerator is even and non-negative.
int total_genus(const Topology& topo, const Components& components,
                const std::vector<std::vector<int>>& loops) {
  std::vector<int> chi(components.count, 0), boundaries(components.count, 0);
  for (int v = 0; v < topo.num_vertices; ++v)
    if (components.vertex_component[v] >= 0) ++chi[components.vertex_component[v]];
  for (int e = 0; e < topo.edges.rows(); ++e) --chi[components.vertex_component[topo.edges(e, 0)]];
  for (int c : components.face_component) ++chi[c];
  for (const auto& loop : loops) ++boundaries[components.vertex_component[loop.front()]];
  int genus = 0;
  for (int c = 0; c < components.count; ++c) genus += (2 - boundaries[c] - chi[c]) / 2;
  return genus;
}

}  // namespace

MeshSummary summarize(const Mesh& mesh, const ValidationReport& report) {
  MeshSummary s;
  s.vertices = mesh.num_vertices();
  s.faces = mesh.num_faces();
  const Faces F = well_formed_faces(mesh.F, s.vertices);
  const Topology topo = build_topology(F, s.vertices);
  const Components components = connected_components(F, topo);
  const auto loops = boundary_loops(F, topo);

  for (int v = 0; v < s.vertices; ++v) {
    if (topo.vertex_faces.size(v) > 0) ++s.referenced_vertices;
    if (mesh.V.row(v).allFinite()) s.bounding_box.extend(mesh.V.row(v).transpose());
  }
  s.edges = static_cast<int>(topo.edges.rows());
  for (int e = 0; e < s.edges; ++e) s.boundary_edges += topo.is_boundary_edge(e);
  for (const auto& loop : loops) s.boundary_loop_lengths.push_back(static_cast<int>(loop.size()));
  for (int f = 0; f < F.rows(); ++f)
    s.lone_triangles += topo.is_boundary_edge(topo.face_edges[3 * f]) &&
                        topo.is_boundary_edge(topo.face_edges[3 * f + 1]) &&
                        topo.is_boundary_edge(topo.face_edges[3 * f + 2]);
  s.components = components.count;
  s.euler_characteristic = s.referenced_vertices - s.edges + static_cast<int>(F.rows());
  if (report.manifold() && report.orientable()) s.genus = total_genus(topo, components, loops);

  s.mean_edge_length = mean_edge_length(mesh.V, topo);
  return s;
}

}  // namespace fairsurf
