// blend_all_loops: the closest pairs of loops joined one after the other (blend.h).
#include <fairsurf/applications/blend.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/tube.h>

#include "stopwatch.h"

#include <algorithm>
#include <string>

namespace fairsurf {
namespace {

// A loop's smallest vertex index names it from one blend to the next: blend_loops appends the
// tube's vertices and faces and leaves the others as they were.
int loop_name(const std::vector<int>& loop) { return *std::min_element(loop.begin(), loop.end()); }

std::vector<std::vector<int>> loops_of(const Mesh& mesh) {
  return boundary_loops(mesh.F, build_topology(mesh.F, mesh.num_vertices()));
}

int index_of(const std::vector<std::vector<int>>& loops, int name) {
  for (int i = 0; i < static_cast<int>(loops.size()); ++i)
    if (loop_name(loops[i]) == name) return i;
  return -1;
}

// Indices into `loops` of those not set aside.
std::vector<int> open_loops(const std::vector<std::vector<int>>& loops, const std::vector<int>& set_aside) {
  std::vector<int> open;
  for (int i = 0; i < static_cast<int>(loops.size()); ++i)
    if (std::find(set_aside.begin(), set_aside.end(), loop_name(loops[i])) == set_aside.end()) open.push_back(i);
  return open;
}

// The closest pair among the loops `open` (indices into `loops`), as blend_loops' own choice.
LoopPair closest_open_pair(const Vertices& V, const std::vector<std::vector<int>>& loops,
                           const std::vector<int>& open) {
  std::vector<std::vector<int>> candidates;
  for (int i : open) candidates.push_back(loops[i]);
  const LoopPair closest = closest_loop_pair(V, candidates);
  return {open[closest.first], open[closest.second], closest.distance};
}

}  // namespace

BlendAllReport blend_all_loops(Mesh& mesh, const BlendOptions& options, const FlowObserver& observer) {
  const auto start = detail::Clock::now();
  if (options.loop_a >= 0 || options.loop_b >= 0)
    throw InvalidArgument("blend_all_loops: the pairs are chosen one after the other; loop_a and loop_b must be -1");
  std::vector<std::vector<int>> loops = loops_of(mesh);  // the mesh's as it stands
  if (loops.size() < 2)
    throw InvalidMeshError("blend_all_loops: the mesh has " + std::to_string(loops.size()) +
                           (loops.size() == 1 ? " boundary loop" : " boundary loops") + "; blending needs two");
  BlendAllReport report;
  std::vector<int> set_aside;  // names of the loops of pairs that could not be joined
  std::vector<UnjoinedLoops> failures;  // loop_a and loop_b hold the loops' names until the end
  for (;; loops = loops_of(mesh)) {
    const std::vector<int> open = open_loops(loops, set_aside);
    if (open.size() < 2) break;
    const LoopPair pair = closest_open_pair(mesh.V, loops, open);
    BlendOptions chosen = options;
    chosen.loop_a = pair.first;
    chosen.loop_b = pair.second;
    const Mesh before = mesh;
    const auto set_pair_aside = [&](const Error& e, bool repairable) {
      mesh = before;
      const int a = loop_name(loops[pair.first]), b = loop_name(loops[pair.second]);
      set_aside.insert(set_aside.end(), {a, b});
      failures.push_back({a, b, 0, 0, e.what(), repairable});
    };
    try {
      BlendReport blend = blend_loops(mesh, chosen, observer);
      blend.automatic = true;
      blend.loop_distance = pair.distance;
      report.blends.push_back(std::move(blend));
    } catch (const NumericalError& e) {
      set_pair_aside(e, false);
    } catch (const RepairableMeshError& e) {
      set_pair_aside(e, true);
    }
  }
  for (UnjoinedLoops& pair : failures) {
    pair.loop_a = index_of(loops, pair.loop_a);
    pair.loop_b = index_of(loops, pair.loop_b);
    pair.length_a = static_cast<int>(loops[pair.loop_a].size());
    pair.length_b = static_cast<int>(loops[pair.loop_b].size());
  }
  report.unjoined = std::move(failures);
  report.loops_left = static_cast<int>(loops.size());
  report.seconds = detail::seconds_since(start);
  return report;
}

}  // namespace fairsurf
