#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region.h>

#include <algorithm>

namespace fairsurf {

Region make_region(const Topology& topo, std::span<const int> free_vertices, Continuity requested) {
  if (free_vertices.empty()) throw InvalidArgument("make_region: the free set is empty");
  Region r;
  r.requested = requested;
  r.ring = ring_distances(topo, free_vertices, 3);  // validates the indices
  r.free_index.assign(topo.num_vertices, -1);
  for (int v = 0; v < topo.num_vertices; ++v)
    if (r.ring[v] == 0) {
      r.free_index[v] = static_cast<int>(r.free_vertices.size());
      r.free_vertices.push_back(v);
    }

  // The first ring (0 = the free set itself) that reaches the mesh border bounds the rings of data.
  const auto border = boundary_vertex_flags(topo);
  r.complete_rings = 3;
  int in_ring[4] = {0, 0, 0, 0};
  for (int v = 0; v < topo.num_vertices; ++v) {
    if (r.ring[v] >= 0) ++in_ring[r.ring[v]];
    if (border[v] && r.ring[v] >= 0) r.complete_rings = std::min(r.complete_rings, r.ring[v]);
  }
  // So does a ring left empty after the first: a region that takes nearly all of a closed mesh
  // leaves its few fixed vertices all next to it, with no second or third ring to carry tangent
  // planes or curvatures. (No fixed vertex at all, a closed mesh smoothed whole, needs no data.)
  for (int k = 2; k <= 3; ++k)
    if (in_ring[1] > 0 && in_ring[k] == 0) r.complete_rings = std::min(r.complete_rings, k - 1);
  const int supported = std::max(0, r.complete_rings - 1);
  r.supported = static_cast<Continuity>(std::min(static_cast<int>(requested), supported));
  return r;
}

std::vector<int> region_faces(const Faces& F, int num_vertices, std::span<const int> vertices) {
  std::vector<char> in(static_cast<std::size_t>(num_vertices), 0);
  for (int v : vertices)
    if (v >= 0 && v < num_vertices) in[static_cast<std::size_t>(v)] = 1;
  std::vector<int> faces;
  for (int f = 0; f < F.rows(); ++f)
    if (in[F(f, 0)] || in[F(f, 1)] || in[F(f, 2)]) faces.push_back(f);
  return faces;
}

std::vector<int> interior_vertices(const Topology& topo, int fixed_rings) {
  const auto border = boundary_vertex_flags(topo);
  std::vector<int> seeds;
  for (int v = 0; v < topo.num_vertices; ++v)
    if (border[v]) seeds.push_back(v);
  const auto dist = ring_distances(topo, seeds, std::max(0, fixed_rings - 1));
  std::vector<int> interior;
  for (int v = 0; v < topo.num_vertices; ++v)
    if (fixed_rings <= 0 || dist[v] < 0) interior.push_back(v);
  return interior;
}

}  // namespace fairsurf
