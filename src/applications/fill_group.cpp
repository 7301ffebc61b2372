// One group's fill from one start of its patch (fill_group.h).
#include "fill_group.h"

#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/submesh.h>

#include "fill_groups.h"
#include "held_out.h"
#include "mesh/crossing_count.h"
#include "patch/border_pinches.h"
#include "stopwatch.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace fairsurf::fill_detail {
namespace {

using detail::Clock;
using detail::seconds_since;

// Local indices in `sub` of the global vertices `global` (all in the submesh).
std::vector<int> to_local(const Submesh& sub, const std::vector<int>& global) {
  std::vector<int> local;
  for (int v : global)
    local.push_back(static_cast<int>(std::lower_bound(sub.to_global.begin(), sub.to_global.end(), v) -
                                     sub.to_global.begin()));
  return local;
}

// A vertex of face `a` at exactly the position of a different vertex of face `b`, as (a's, b's), or
// (−1, −1): the two faces meet at a vertex that was split in two (`repair` splits a non-manifold
// vertex or edge into copies at one position), which the crossing test does not treat as shared.
std::pair<int, int> coincident_corners(const Vertices& V, const Faces& F, int a, int b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (F(a, i) != F(b, j) && V.row(F(a, i)) == V.row(F(b, j))) return {F(a, i), F(b, j)};
  return {-1, -1};
}

// (V, F) and `topo`: the patched mesh. When the first crossing is with another connected part of
// the mesh (two parts whose openings face each other, as in data/cgal_blobby_3cc.off), the reason
// says that a blend, not a fill, is what joins them; when the face crossed meets the patch at a
// split vertex (the repaired data/stanford_bunny_zipper_res2.ply), that the hole is such a junction.
std::string crossing_reason(const std::vector<FaceIntersection>& crossings, int input_faces, const Vertices& V,
                            const Faces& F, const Topology& topo) {
  const FaceIntersection& c = crossings.front();
  const bool other_new = c.other_face >= input_faces;
  std::string reason = "the faired patch crosses the mesh: new face " + std::to_string(c.query_face) + " crosses " +
                       (other_new ? "new" : "input") + " face " + std::to_string(c.other_face) + " (" +
                       detail::crossing_count(crossings) + ")";
  const Components parts = connected_components(F, topo);
  const bool other_part = parts.face_component[c.query_face] != parts.face_component[c.other_face];
  if (const auto [ours, theirs] = coincident_corners(V, F, c.query_face, c.other_face); ours >= 0)
    return reason + ", " + (other_part ? "a face of another part of the mesh " : "") + "whose vertex " +
           std::to_string(theirs) + " lies at vertex " + std::to_string(ours) +
           "'s position: the hole's border passes through a vertex split in two (as repair splits a "
           "non-manifold vertex or edge), and a patch there runs into the other side of the split";
  if (other_part) reason += ", a face of another part of the mesh: openings that face each other are joined by blend";
  return reason;
}

// `free` (the patch's free vertices, or one hole's) and `rings` rings around them, cut out of the
// patched mesh (fair_region would cut out the same rings): the cost of checking the mesh stays in
// proportion to the hole, and a defect far away (a pinched border elsewhere) does not concern this
// hole. `local`: the connectivity of sub.mesh, derived from the patched mesh's once: validation,
// fairing, its held-out trials and the continuity measures read it.
void cut_out_neighbourhood(const InitialPatch& patch, const std::vector<int>& free, int rings, Submesh& sub,
                           Topology& local) {
  sub = extract_neighbourhood(patch.mesh.V, patch.mesh.F, patch.topology, free, rings);
  local = derive_topology(patch.topology, sub.mesh.F, sub.to_global);
}

// Fairs the patch's free vertices on their neighbourhood `sub` (cut_out_neighbourhood; `local`
// its connectivity). `whole`: fair_valid_mesh's, on `sub`.
FairRegionReport fair_patch(const InitialPatch& patch, const FairRegionOptions& fairing_options,
                            const FlowObserver& step_observer, Submesh& sub, const Topology& local, bool& whole) {
  FairRegionReport fairing;
  fairing.requested = fairing.supported = fairing_options.continuity;
  fairing.method = fairing_options.method;
  whole = false;
  if (patch.free_vertices.empty()) return fairing;
  // One ∆^k solve from the patch as refinement left it is weighed beside the membrane's starts:
  // where the membrane creases the patch against the border, that is the closer one.
  Vertices refined;
  if (patch.refined_free.rows() > 0) {
    refined = sub.mesh.V;
    const std::vector<int> local_free = to_local(sub, patch.free_vertices);
    for (std::size_t k = 0; k < local_free.size(); ++k)
      refined.row(local_free[k]) = patch.refined_free.row(static_cast<Eigen::Index>(k));
  }
  return fair_detail::fair_checked_mesh(sub.mesh, local, sub.free_local, fairing_options, step_observer, true,
                                       &whole, refined.rows() > 0 ? &refined : nullptr);
}

// The report of a patch committed unfaired (PatchStart::unfaired): C0, linear, nothing run.
FairRegionReport unfaired_report() {
  FairRegionReport r;
  r.requested = r.supported = Continuity::G0;
  r.method = FairMethod::harmonic;
  r.linear = true;
  return r;
}

// What the group's fairing did, in the report of one of its holes (`flowed`: the flow's result).
void report_fairing(const FairRegionReport& fairing, bool flowed, HoleReport& r) {
  r.supported = fairing.supported;
  r.linear = fairing.linear;
  if (fairing.supported < fairing.requested)
    r.note = "the mesh around the hole has fewer than " + std::to_string(rings_needed(fairing.requested)) +
             " complete rings: faired with " + std::string(to_string(fairing.supported));
  if (!fairing.note.empty()) r.note += (r.note.empty() ? "" : "; ") + fairing.note;
  r.held_out_flow_error = fairing.held_out_flow_error;
  r.held_out_linear_error = fairing.held_out_linear_error;
  r.held_out_two_ring_flow_error = fairing.held_out_two_ring_flow_error;
  r.held_out_other_flow_error = fairing.held_out_other_flow_error;
  r.held_out_other_two_ring_flow_error = fairing.held_out_other_two_ring_flow_error;
  r.held_out_refined_linear_error = fairing.held_out_refined_linear_error;
  r.held_out_roughness = fairing.held_out_roughness;
  r.refined_start = fairing.refined_start;
  r.checks_chose_linear = fairing.checks_chose_linear;
  r.flow_folded_back = fairing.flow_folded_back;
  r.two_ring_boundary_fits = flowed && fairing.two_ring_boundary_fits;
  r.other_functions = fairing.other_functions;
  r.steps = flowed ? fairing.flow.accepted_steps : 0;
  r.harmonic_solves = fairing.harmonic.iterations;
  r.final_max_velocity = flowed ? fairing.flow.final_max_velocity : std::numeric_limits<double>::quiet_NaN();
  if (fairing.method == FairMethod::flow) r.well_posedness = fairing.flow.well_posedness;
}

// One hole of a joint group faired alone on the patched mesh (refair_each_hole): empty where its
// flow is delivered, at the group's continuity `supported` or above, steady and clear of the mesh
// (its free vertices then hold it in patch.mesh.V), else why not (patch.mesh.V may then hold
// anything there).
std::string fair_hole_alone(InitialPatch& patch, const std::vector<int>& free, const std::vector<int>& faces,
                            Continuity supported, const FairRegionOptions& fairing_options, const FillOptions& options,
                            const FlowObserver& observer, FairRegionReport& alone) {
  try {
    Submesh sub;
    Topology local;
    cut_out_neighbourhood(patch, free, options.submesh_rings, sub, local);
    alone = fair_detail::fair_checked_mesh(sub.mesh, local, sub.free_local, fairing_options, observer);
    if (alone.linear) return alone.note.empty() ? "its linear solution was kept" : alone.note;
    if (alone.supported < supported)
      return "the mesh around it supports " + std::string(to_string(alone.supported)) + " only";
    if (alone.flow.stop_reason != FlowStopReason::steady)
      return std::string("the ") + to_string(alone.flow_kind) + " flow " + unsettled_reason(alone.flow);
    write_back_free(sub, patch.mesh.V);
  } catch (const Error& e) {
    return e.what();
  }
  if (options.check_intersections && !find_face_intersections(patch.mesh.V, patch.mesh.F, faces, 1).empty())
    return "its flow's patch crosses the mesh";
  return "";
}

// Each hole of a joint group faired again on its own (fill_group), where the group's flow ran but
// was not kept (it folded against its start, did not settle or threw): a check over the whole group
// that one hole's flow may have failed for all (a row of windows, one of which folds, holds back the
// rest). Not where the held-out rings chose the linear solution: that verdict weighs the group as a
// whole, and one hole's own rings, which run over its neighbours' linear patches, judge worse. The
// group's other patches stay as the group left them, so the hole's fixed rings are complete; it
// keeps the flow where that fairing delivers one at the group's continuity or above, steady and
// clear of the mesh, and its linear solution otherwise, untouched (docs/real-holes.md, "Joint holes, one
// by one"). A hole given its flow has that linear solution as its floor, added to `floors`.
void refair_each_hole(InitialPatch& patch, const std::vector<int>& group, const std::vector<std::vector<int>>& free,
                      const std::vector<std::vector<int>>& faces, const FairRegionOptions& fairing_options,
                      const FillOptions& options, const FlowObserver& observer, std::vector<HoleReport>& reports,
                      std::vector<HoleFloor>& floors) {
  for (std::size_t k = 0; k < group.size(); ++k) {
    if (free[k].empty()) continue;
    HoleReport& r = reports[group[k]];
    const std::string order = std::to_string(static_cast<int>(r.supported) + 1);
    Vertices kept(free[k].size(), 3);
    for (std::size_t i = 0; i < free[k].size(); ++i)
      kept.row(static_cast<Eigen::Index>(i)) = patch.mesh.V.row(free[k][i]);
    FairRegionReport alone;
    const std::string lost = fair_hole_alone(patch, free[k], faces[k], r.supported, fairing_options, options,
                                             observer, alone);
    const std::string group_note = r.note;
    if (!lost.empty()) {
      for (std::size_t i = 0; i < free[k].size(); ++i)
        patch.mesh.V.row(free[k][i]) = kept.row(static_cast<Eigen::Index>(i));
      r.note = group_note + "; faired again alone, the group's other patches held as filled, it kept the linear ∆" +
               order + " solution: " + lost;
      continue;
    }
    floors.push_back({group[k], free[k], std::move(kept)});
    r.note.clear();
    report_fairing(alone, true, r);
    r.continuity = alone.continuity;
    r.note = "the joint fill kept the linear ∆" + order + " solution (" + group_note +
             "); faired again alone, the group's other patches held as filled" + (r.note.empty() ? "" : ": " + r.note);
  }
}

// The floor under the group's flow (fairing.floor_positions, rows in the order of sub.free_local),
// hole by hole: `hole_free` holds each hole's free vertices, rows of the patched mesh.
std::vector<HoleFloor> hole_floors(const FairRegionReport& fairing, const Submesh& sub, const std::vector<int>& group,
                                   const std::vector<std::vector<int>>& hole_free) {
  std::vector<HoleFloor> floors;
  for (std::size_t k = 0; k < group.size(); ++k) {
    if (hole_free[k].empty()) continue;
    HoleFloor floor{group[k], hole_free[k], Vertices(static_cast<Eigen::Index>(hole_free[k].size()), 3)};
    const std::vector<int> local = to_local(sub, hole_free[k]);
    for (std::size_t i = 0; i < local.size(); ++i) {
      const auto row = std::lower_bound(sub.free_local.begin(), sub.free_local.end(), local[i]) - sub.free_local.begin();
      floor.positions.row(static_cast<Eigen::Index>(i)) = fairing.floor_positions.row(row);
    }
    floors.push_back(std::move(floor));
  }
  return floors;
}

// A hole whose loop was joined to another's at a pinch of the border (PatchOwnership::patch_hole)
// has no patch of its own: it gets the report of the hole its patch is counted for (the same
// fairing and labels, and the border measure, which covers both loops), no vertex or face of its
// own, and a note naming that hole.
void report_shared_patches(const std::vector<int>& patch_hole, const std::vector<int>& group,
                           std::vector<HoleReport>& reports) {
  for (std::size_t k = 0; k < group.size(); ++k) {
    const int h = group[k], owner = patch_hole[k];
    if (owner == h) continue;
    HoleReport shared = reports[owner];
    shared.index = h;
    // What the loop itself is stays this loop's.
    shared.border_edges = reports[h].border_edges;
    shared.around_a_face = reports[h].around_a_face;
    shared.hanging_piece_at = reports[h].hanging_piece_at;
    shared.lone_triangle = reports[h].lone_triangle;
    shared.filled_with = reports[h].filled_with;
    shared.vertices_added = shared.faces_added = 0;
    shared.patch_shared_with = owner;
    shared.note = "filled in one patch with hole " + std::to_string(owner) +
                  ", whose loop meets this one at a pinch of the border; the patch's vertices and faces are "
                  "counted there" + (shared.note.empty() ? "" : ": " + shared.note);
    reports[h] = std::move(shared);
  }
}

}  // namespace

// Fills the holes `group` jointly on `mesh` from the group's patch for `start` (PatchStart; built on
// `mesh` and its connectivity by `patches`); on success moves the filled mesh into `out` and fills
// the reports; on failure throws or returns the reason the patch was rejected. `crossed` says
// whether the rejected patch crosses the mesh, and whether it was a flow's.
std::string fill_group(const Mesh& mesh, const std::vector<std::vector<int>>& loops, const std::vector<int>& group,
                       GroupPatches& patches, const FillOptions& options, const FairRegionOptions& fairing_options,
                       PatchStart start, const FillObserver& observer, std::vector<HoleReport>& reports,
                       FilledMesh& out, PatchCrossing& crossed) {
  crossed = PatchCrossing::none;
  const bool unfaired = start == PatchStart::unfaired;
  InitialPatch patch = patches.get(start);  // a copy: the fairing moves its vertices
  const std::string non_manifold = detail::patch_non_manifold(patch.mesh.F, patch.topology, patch.first_patch_face);
  if (!non_manifold.empty()) return non_manifold;
  // Checked before the fairing, which would refuse the mesh: such a triangle has its corners on the
  // border (a loop through both copies of a split vertex), where no fairing moves them.
  const std::string zero_area = detail::patch_zero_area_face(patch.mesh.V, patch.mesh.F, patch.first_patch_face);
  if (!zero_area.empty()) return zero_area;

  Submesh sub;
  Topology local;
  bool whole = false;
  const FlowObserver step_observer = [&](const StepRecord& r) {
    if (observer) observer(group, r);
  };
  if (!patch.free_vertices.empty())
    cut_out_neighbourhood(patch, patch.free_vertices, options.submesh_rings, sub, local);
  const FairRegionReport fairing = unfaired ? unfaired_report()
                                            : fair_patch(patch, fairing_options, step_observer, sub, local, whole);
  if (!patch.free_vertices.empty() && !unfaired) {
    const FlowReport& flow = fairing.flow;
    if (!fairing.linear && flow.stop_reason != FlowStopReason::steady)
      return std::string("the ") + to_string(fairing.flow_kind) + " flow " + unsettled_reason(flow);
    write_back_free(sub, patch.mesh.V);
  }

  std::vector<int> new_faces(patch.mesh.num_faces() - patch.first_patch_face);
  std::iota(new_faces.begin(), new_faces.end(), patch.first_patch_face);
  if (options.check_intersections) {
    const auto crossings =
        find_face_intersections(patch.mesh.V, patch.mesh.F, new_faces, detail::kCrossingsSought);
    if (!crossings.empty()) {
      crossed = !fairing.linear && !patch.free_vertices.empty() ? PatchCrossing::flow : PatchCrossing::other;
      return crossing_reason(crossings, mesh.num_faces(), patch.mesh.V, patch.mesh.F, patch.topology);
    }
  }

  std::vector<char> taken_in;
  for (int h : group) taken_in.push_back(reports[h].around_a_face || reports[h].hanging_piece_at >= 0);
  const fill_detail::PatchOwnership own =
      fill_detail::patch_ownership(patch, mesh.num_vertices(), loops, group, taken_in);
  const bool flowed = !fairing.linear && !patch.free_vertices.empty();
  std::vector<std::vector<int>> hole_free(group.size()), hole_faces(group.size());
  for (std::size_t k = 0; k < group.size(); ++k) {
    const int h = group[k];
    HoleReport& r = reports[h];
    std::vector<int>& free = hole_free[k];
    for (std::size_t i = 0; i < own.vertex_hole.size(); ++i)
      if (own.vertex_hole[i] == h) free.push_back(mesh.num_vertices() + static_cast<int>(i));
    for (std::size_t f = 0; f < own.face_hole.size(); ++f)
      if (own.face_hole[f] == h) hole_faces[k].push_back(patch.first_patch_face + static_cast<int>(f));
    r.vertices_added = static_cast<int>(free.size());
    r.faces_added = static_cast<int>(hole_faces[k].size());
    report_fairing(fairing, flowed, r);
    if (!free.empty()) {
      // The fairing measured the same positions, faces and free set when it ran on `sub` itself
      // (as for a group of one hole): not measured twice.
      const std::vector<int> hole_free_local = to_local(sub, free);
      r.continuity = whole && hole_free_local == sub.free_local
                         ? fairing.continuity
                         : measure_continuity(sub.mesh.V, sub.mesh.F, local, hole_free_local);
    }
    if (free.empty()) {  // nothing was faired: the patch is the triangulation of the loop
      r.supported = Continuity::G0;
      r.linear = true;
      r.steps = 0;
      r.note = "the patch has no interior vertex: the loop's triangulation alone, continuous in position only";
    }
  }
  std::vector<HoleFloor> floors;
  if (flowed && fairing.floor_positions.rows() > 0) floors = hole_floors(fairing, sub, group, hole_free);
  if (group.size() > 1 && !unfaired && fairing.linear && !fairing.held_out_linear &&
      fairing_options.method == FairMethod::flow) {
    // Each hole's own first try: the tangential relaxation is the group's answer to its own patch
    // crossing the mesh (crossing_retry_relaxation), not a default for a hole faired alone.
    FairRegionOptions alone = fairing_options;
    alone.flow.tangential_relaxation = options.flow.tangential_relaxation;
    refair_each_hole(patch, group, hole_free, hole_faces, alone, options, step_observer, reports, floors);
  }
  report_shared_patches(own.patch_hole, group, reports);
  out = {std::move(patch.mesh.V), std::move(patch.mesh.F), std::move(patch.topology), std::move(floors)};
  return "";
}


}  // namespace fairsurf::fill_detail
