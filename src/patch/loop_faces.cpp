#include "loop_faces.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <string>

namespace fairsurf::detail {
namespace {

// The mesh face that contains the directed edge a→b, -1 if none.
int face_with_directed_edge(const Faces& F, const Topology& topo, int a, int b) {
  for (int f : topo.vertex_faces.row(a))
    for (int k = 0; k < 3; ++k)
      if (F(f, k) == a && F(f, (k + 1) % 3) == b) return f;
  return -1;
}

}  // namespace

bool is_mesh_edge(const Topology& topo, int a, int b) {
  const auto row = topo.vertex_vertices.row(a);
  return std::binary_search(row.begin(), row.end(), b);
}

std::vector<int> loop_edge_faces(const Faces& F, const Topology& topo, std::span<const int> loop,
                                 const char* function) {
  const int n = static_cast<int>(loop.size());
  if (n < 3)
    throw InvalidArgument(std::string(function) + ": a loop needs at least 3 vertices, got " +
                          std::to_string(n));
  for (int v : loop)
    if (v < 0 || v >= topo.num_vertices)
      throw InvalidArgument(std::string(function) + ": loop vertex " + std::to_string(v) +
                            " is out of range [0, " + std::to_string(topo.num_vertices) + ")");
  std::vector<int> faces(n);
  for (int t = 0; t < n; ++t) {
    const int a = loop[t], b = loop[(t + 1) % n];
    faces[t] = face_with_directed_edge(F, topo, a, b);
    if (faces[t] < 0 || face_with_directed_edge(F, topo, b, a) >= 0)
      throw InvalidArgument(std::string(function) + ": loop edge " + std::to_string(a) + "-" +
                            std::to_string(b) + " is not a border edge with the surface on its left");
  }
  return faces;
}

}  // namespace fairsurf::detail
