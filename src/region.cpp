#include <fairsurf/errors.h>
#include <fairsurf/region.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace fairsurf {

std::string_view to_string(Continuity c) {
  switch (c) {
    case Continuity::G0: return "G0";
    case Continuity::G1: return "G1";
    case Continuity::G2: return "G2";
  }
  return "G?";
}

std::string delivered_label(Continuity continuity, bool linear) {
  static const char* const geometric[] = {"G0", "G1", "G2"};
  static const char* const linear_labels[] = {"C0 (linear)", "C1 (linear)", "C2 (linear)"};
  const int k = std::clamp(static_cast<int>(continuity), 0, 2);
  return linear ? linear_labels[k] : geometric[k];
}

Continuity parse_continuity(std::string_view text) {
  if (text.size() == 2 && std::toupper(static_cast<unsigned char>(text[0])) == 'G' &&
      text[1] >= '0' && text[1] <= '2')
    return static_cast<Continuity>(text[1] - '0');
  throw InvalidArgument("parse_continuity: '" + std::string(text) +
                        "' is not a continuity (expected G0, G1 or G2)");
}

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
  for (int v = 0; v < topo.num_vertices; ++v)
    if (border[v] && r.ring[v] >= 0) r.complete_rings = std::min(r.complete_rings, r.ring[v]);
  const int supported = std::max(0, r.complete_rings - 1);
  r.supported = static_cast<Continuity>(std::min(static_cast<int>(requested), supported));
  return r;
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
