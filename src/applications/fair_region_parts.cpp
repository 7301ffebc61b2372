#include "fair_region_parts.h"

#include "stopwatch.h"

#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <string>
#include <vector>

namespace fairsurf {

std::vector<std::vector<int>> region_parts(const Topology& topo, std::span<const int> free_vertices, int rings) {
  std::vector<int> free(free_vertices.begin(), free_vertices.end());
  std::sort(free.begin(), free.end());
  free.erase(std::unique(free.begin(), free.end()), free.end());
  const std::vector<int> distance = ring_distances(topo, free, rings);
  std::vector<int> part_of(distance.size(), -1);
  std::vector<std::vector<int>> parts;
  std::vector<int> stack;
  for (int seed : free) {
    if (part_of[seed] >= 0) continue;
    const int part = static_cast<int>(parts.size());
    parts.emplace_back();
    part_of[seed] = part;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int u : topo.vertex_vertices.row(v))
        if (distance[u] >= 0 && part_of[u] < 0) {
          part_of[u] = part;
          stack.push_back(u);
        }
    }
  }
  for (int v : free) parts[part_of[v]].push_back(v);
  return parts;
}

namespace fair_detail {
namespace {

// Adds a part's flow to the whole region's (FairRegionReport::parts): steps and energies summed,
// max|V| and time the largest, steady only while every flowed part is.
void add_part_flow(const FairRegionReport& part, FlowReport& whole) {
  whole.well_posedness.vertices += part.flow.well_posedness.vertices;
  whole.well_posedness.violating_vertices += part.flow.well_posedness.violating_vertices;
  if (part.linear || !part.has_flow_report()) return;
  const FlowReport& f = part.flow;
  if (whole.free_vertices == 0) {
    whole.stop_reason = FlowStopReason::steady;
    whole.length_scale = f.length_scale;
    whole.curvature_scale = f.curvature_scale;
    whole.tau = f.tau;
    whole.supported = f.supported;
  }
  whole.records.insert(whole.records.end(), f.records.begin(), f.records.end());
  if (whole.stop_reason == FlowStopReason::steady) whole.stop_reason = f.stop_reason;
  whole.accepted_steps += f.accepted_steps;
  whole.rejected_steps += f.rejected_steps;
  whole.time = std::max(whole.time, f.time);
  whole.tau = std::min(whole.tau, f.tau);
  whole.initial_energy += f.initial_energy;
  whole.final_energy += f.final_energy;
  whole.initial_max_velocity = std::max(whole.initial_max_velocity, f.initial_max_velocity);
  whole.final_max_velocity = std::max(whole.final_max_velocity, f.final_max_velocity);
  whole.free_vertices += f.free_vertices;
  whole.supported = std::min(whole.supported, f.supported);
}

// The whole region's report from its parts' (FairRegionReport::parts), but for continuity and
// seconds, which the caller measures.
FairRegionReport combined_report(std::vector<FairRegionReport> parts, const FairRegionOptions& options) {
  FairRegionReport whole;
  whole.requested = options.continuity;
  whole.method = options.method;
  whole.supported = Continuity::G2;
  std::string labels;
  for (const FairRegionReport& part : parts) {
    whole.free_vertices += part.free_vertices;
    whole.supported = std::min(whole.supported, part.supported);
    whole.linear = whole.linear || part.linear;
    whole.checks_chose_linear = whole.checks_chose_linear || part.checks_chose_linear;
    whole.flow_folded_back = whole.flow_folded_back || part.flow_folded_back;
    whole.crossing_fallback = whole.crossing_fallback || part.crossing_fallback;
    whole.harmonic.free_vertices += part.harmonic.free_vertices;
    whole.harmonic.iterations += part.harmonic.iterations;
    whole.harmonic.backward_error = std::max(whole.harmonic.backward_error, part.harmonic.backward_error);
    whole.harmonic.max_move = std::max(whole.harmonic.max_move, part.harmonic.max_move);
    add_part_flow(part, whole.flow);
    labels += (labels.empty() ? "" : ", ") + delivered_label(part.supported, part.linear) + " (" +
              std::to_string(part.free_vertices) + " free vertices)";
  }
  if (whole.linear) {  // as for one region whose floor was kept: the flow's well-posedness alone
    const WellPosedness weighed = whole.flow.well_posedness;
    whole.flow = FlowReport{};
    whole.flow.well_posedness = weighed;
  }
  whole.flow_kind = flow_for(whole.supported);
  whole.harmonic.order = static_cast<int>(whole.supported) + 1;
  whole.note = "faired in " + std::to_string(parts.size()) +
               " parts whose fixed rings do not meet, each on its own: " + labels;
  whole.parts = std::move(parts);
  return whole;
}

// What of a marked region can be faired: the free vertices whose connected component of the mesh
// also has a fixed vertex. A vertex no face uses (scans list some: the Stanford bunny's OBJ has
// 1113) is not on the surface, and a component marked whole has no ring to be faired against: both
// stay where they are, counted for fair_region's note.
struct AnchoredRegion {
  std::vector<int> free;        // ascending
  int loose_vertices = 0;       // free vertices no face uses
  int whole_components = 0;     // components of the mesh whose every vertex is free
  int in_whole_components = 0;  // their vertices
  bool complete() const { return loose_vertices == 0 && whole_components == 0; }
  // "1 vertex on no face, 2 components of the mesh marked whole (84 vertices)".
  std::string left_out() const;
};

std::string AnchoredRegion::left_out() const {
  std::string t;
  if (loose_vertices > 0) t = std::to_string(loose_vertices) + (loose_vertices == 1 ? " vertex" : " vertices") + " on no face";
  if (whole_components > 0)
    t += (t.empty() ? "" : ", ") + std::to_string(whole_components) +
         (whole_components == 1 ? " component" : " components") + " of the mesh marked whole (" +
         std::to_string(in_whole_components) + " vertices)";
  return t;
}

// The AnchoredRegion of `free_vertices` (in range): each connected set of free vertices, anchored
// where it reaches a fixed one.
AnchoredRegion anchored_region(const Topology& topo, std::span<const int> free_vertices) {
  AnchoredRegion a;
  std::vector<char> state(topo.num_vertices, 0);  // 1: free, 2: reached
  for (int v : free_vertices) state[v] = 1;
  std::vector<int> component, stack;
  for (int seed : free_vertices) {
    if (state[seed] != 1) continue;
    component.clear();
    stack.assign(1, seed);
    state[seed] = 2;
    bool anchored = false;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      component.push_back(v);
      for (int u : topo.vertex_vertices.row(v)) {
        anchored = anchored || state[u] == 0;
        if (state[u] == 1) state[u] = 2, stack.push_back(u);
      }
    }
    if (anchored) {
      a.free.insert(a.free.end(), component.begin(), component.end());
    } else if (topo.vertex_faces.size(seed) == 0) {
      ++a.loose_vertices;
    } else {
      ++a.whole_components;
      a.in_whole_components += static_cast<int>(component.size());
    }
  }
  std::sort(a.free.begin(), a.free.end());
  return a;
}

// "part 2 (1279 free vertices): <what>", as the summary numbers parts.
std::string part_text(std::size_t index, std::size_t size, const std::string& what) {
  return "part " + std::to_string(index + 1) + " (" + std::to_string(size) + " free vertices): " + what;
}

// fair_in_parts on a region whose every vertex is in range and anchored. A part whose fairing fails
// is put back where it was given and the others are faired all the same (as fill leaves a hole that
// failed open and fills the rest); then NumericalError names the parts that failed.
FairRegionReport fair_anchored_parts(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                     const FairRegionOptions& options, const PartFairing& fair_part) {
  const std::vector<std::vector<int>> parts = region_parts(topo, free_vertices, rings_needed(options.continuity));
  if (parts.size() <= 1) return fair_part(free_vertices);
  const auto start = detail::Clock::now();
  std::vector<FairRegionReport> reports;
  std::string failed, faired;
  int failures = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Vertices given(static_cast<Eigen::Index>(parts[i].size()), 3);
    for (std::size_t k = 0; k < parts[i].size(); ++k) given.row(static_cast<Eigen::Index>(k)) = mesh.V.row(parts[i][k]);
    try {
      reports.push_back(fair_part(parts[i]));
      faired += (faired.empty() ? "" : ", ") +
                part_text(i, parts[i].size(), delivered_label(reports.back().supported, reports.back().linear));
    } catch (const NumericalError& e) {
      for (std::size_t k = 0; k < parts[i].size(); ++k) mesh.V.row(parts[i][k]) = given.row(static_cast<Eigen::Index>(k));
      std::string what = e.what();
      if (what.starts_with("fair_region: ")) what.erase(0, std::string("fair_region: ").size());
      failed += (failed.empty() ? "" : "; ") + part_text(i, parts[i].size(), what);
      ++failures;
    }
  }
  if (failures > 0)
    throw NumericalError("fair_region: " + std::to_string(failures) + " of " + std::to_string(parts.size()) +
                         " parts whose fixed rings do not meet could not be faired and stay as given (" + failed +
                         (faired.empty() ? ")" : "); the others were faired: " + faired));
  FairRegionReport whole = combined_report(std::move(reports), options);
  whole.continuity = measure_continuity(mesh.V, mesh.F, topo, free_vertices);
  whole.seconds = detail::seconds_since(start);
  return whole;
}

}  // namespace

FairRegionReport fair_in_parts(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                               const FairRegionOptions& options, const PartFairing& fair_part) {
  for (int v : free_vertices)
    if (v < 0 || v >= mesh.num_vertices()) return fair_part(free_vertices);
  const AnchoredRegion anchored = anchored_region(topo, free_vertices);
  if (anchored.complete()) return fair_anchored_parts(mesh, topo, free_vertices, options, fair_part);
  if (anchored.free.empty())
    throw InvalidArgument("fair_region: no vertex of the free region has a fixed vertex in its component of the "
                          "mesh (" + anchored.left_out() + "), so there is nothing to fair it against");
  FairRegionReport report = fair_anchored_parts(mesh, topo, anchored.free, options, fair_part);
  const std::string left = "left where they are, with no fixed vertex to fair them against: " + anchored.left_out();
  report.note = report.note.empty() ? left : left + "; " + report.note;
  return report;
}

}  // namespace fair_detail
}  // namespace fairsurf
