// Which holes fill_holes fills together, and which hole owns each piece of their patch
// (fill_groups.h).
#include "fill_groups.h"

#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace fairsurf::fill_detail {
namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<std::vector<int>> overlapping_groups(const Topology& topo, const std::vector<std::vector<int>>& loops,
                                                 const std::vector<int>& holes, int rings) {
  std::vector<int> parent(loops.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> owner(topo.num_vertices, -1);
  for (int h : holes)
    for (int v : k_ring(topo, loops[h], rings - 1)) {
      if (owner[v] >= 0) parent[find_root(parent, h)] = find_root(parent, owner[v]);
      owner[v] = h;
    }
  std::vector<std::vector<int>> groups;
  std::vector<int> group_of(loops.size(), -1);
  for (int h : holes) {
    const int root = find_root(parent, h);
    if (group_of[root] < 0) group_of[root] = static_cast<int>(groups.size()), groups.emplace_back();
    groups[group_of[root]].push_back(h);
  }
  return groups;
}

PatchOwnership patch_ownership(const InitialPatch& patch, int input_vertices,
                               const std::vector<std::vector<int>>& loops, std::span<const int> holes,
                               std::span<const char> taken_in) {
  const Faces& F = patch.mesh.F;
  const int first = patch.first_patch_face, count = static_cast<int>(F.rows()) - first;
  const auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  std::unordered_map<std::uint64_t, int> face_of;  // directed patch edge -> patch face (− first)
  for (int f = 0; f < count; ++f)
    for (int k = 0; k < 3; ++k) face_of[key(F(first + f, k), F(first + f, (k + 1) % 3))] = f;
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [edge, f] : face_of) {
    const auto twin = face_of.find((edge << 32) | (edge >> 32));
    if (twin != face_of.end()) parent[find_root(parent, f)] = find_root(parent, twin->second);
  }
  std::vector<int> hole_of_root(count, -1), loop_root;  // loop_root: per hole, its patch's piece
  std::vector<char> owner_taken_in(count, 0);
  for (std::size_t k = 0; k < holes.size(); ++k) {
    const int h = holes[k];
    loop_root.push_back(-1);
    for (std::size_t t = 0; t < loops[h].size(); ++t) {
      const auto across = face_of.find(key(loops[h][(t + 1) % loops[h].size()], loops[h][t]));
      if (across == face_of.end()) continue;
      const int root = loop_root.back() = find_root(parent, across->second);
      if (hole_of_root[root] >= 0 && taken_in[k] && !owner_taken_in[root]) continue;
      hole_of_root[root] = h;
      owner_taken_in[root] = taken_in[k];
    }
  }
  PatchOwnership own;
  for (std::size_t k = 0; k < holes.size(); ++k)
    own.patch_hole.push_back(loop_root[k] < 0 ? holes[k] : hole_of_root[loop_root[k]]);
  own.vertex_hole.assign(patch.mesh.num_vertices() - input_vertices, -1);
  for (int f = 0; f < count; ++f) {
    own.face_hole.push_back(hole_of_root[find_root(parent, f)]);
    for (int k = 0; k < 3; ++k)
      if (F(first + f, k) >= input_vertices) own.vertex_hole[F(first + f, k) - input_vertices] = own.face_hole.back();
  }
  return own;
}

}  // namespace fairsurf::fill_detail
