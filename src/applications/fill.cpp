// fill_holes (fill.h): the holes selected, grouped where their rings overlap, and each group filled
// through the fallback chain (fill_chain.h) around fill_group (fill_group.h); an earlier flow in a
// group's way given its floor, a failed joint group filled hole by hole, and the reports completed.
#include <fairsurf/applications/fill.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/mesh_attributes.h>
#include <fairsurf/mesh/topology.h>

#include "border_fold.h"
#include "fill_chain.h"
#include "fill_group.h"
#include "fill_groups.h"
#include "fill_selection.h"
#include "held_out.h"
#include "patch/border_pinches.h"
#include "stopwatch.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <numeric>
#include <optional>

namespace fairsurf {
namespace {

using detail::Clock;
using detail::seconds_since;

using fill_detail::ChainOutcome;
using fill_detail::FilledMesh;
using fill_detail::fill_again_where_better;
using fill_detail::fill_from_membrane;
using fill_detail::group_folds_back;
using fill_detail::GroupPatches;
using fill_detail::HoleFloor;
using fill_detail::kDegrees;
using fill_detail::largest_border_angle;
using fill_detail::mark;
using fill_detail::PatchStart;
using fill_detail::retriangulate_if_failed;
using fill_detail::retriangulate_if_folded_back;

// Replaces `mesh` by the filled one and `filled` by its connectivity (the group's GroupPatches, which
// may read the old one, is not used after this).
void commit(FilledMesh& out, Mesh& mesh, std::optional<Topology>& filled) {
  mesh.V = std::move(out.V);
  mesh.F = std::move(out.F);
  mesh.vertex_scalars.clear();
  mesh.vertex_colors.resize(0, 3);
  pad_face_attributes(mesh);  // the input's faces keep theirs; the patch's have none
  filled = std::move(out.topology);
}

// One report per boundary loop, before anything is tried.
std::vector<HoleReport> hole_reports(const std::vector<std::vector<int>>& loops, const FillOptions& options) {
  std::vector<HoleReport> reports;
  for (int i = 0; i < static_cast<int>(loops.size()); ++i) {
    HoleReport r;
    r.index = i;
    r.border_edges = static_cast<int>(loops[i].size());
    r.requested = r.supported = options.continuity;
    reports.push_back(r);
  }
  return reports;
}


// "holes 3, 5 and 7"
std::string hole_list(const std::vector<int>& holes) {
  std::string text = holes.size() == 1 ? "hole " : "holes ";
  for (std::size_t i = 0; i < holes.size(); ++i)
    text += (i == 0 ? "" : i + 1 == holes.size() ? " and " : ", ") + std::to_string(holes[i]);
  return text;
}

// A committed group's flows over their linear floors (FilledMesh::floors) and the group's patch
// faces, rows of the filled mesh: what a later group may give back its floor
// (fill_again_with_earlier_floors).
struct CommittedFlows {
  std::vector<HoleFloor> floors;
  std::vector<int> faces;
};

// The room a patch of `patch_loops` may take: their bounding box, grown on every side by its
// diagonal (a dome over a loop rises about as far as the loop is wide).
Eigen::AlignedBox3d patch_room(const Vertices& V, const std::vector<std::vector<int>>& patch_loops) {
  Eigen::AlignedBox3d box;
  for (const std::vector<int>& loop : patch_loops)
    for (int v : loop) box.extend(V.row(v).transpose());
  const double grow = box.diagonal().norm();
  box.min().array() -= grow;
  box.max().array() += grow;
  return box;
}

bool reaches_into(const Eigen::AlignedBox3d& room, const Vertices& V, const CommittedFlows& flows) {
  for (const HoleFloor& floor : flows.floors)
    for (int v : floor.vertices)
      if (room.contains(V.row(v).transpose())) return true;
  return false;
}

void place(const std::vector<HoleFloor>& floors, Vertices& V) {
  for (const HoleFloor& floor : floors)
    for (std::size_t i = 0; i < floor.vertices.size(); ++i)
      V.row(floor.vertices[i]) = floor.positions.row(static_cast<Eigen::Index>(i));
}

// The holes of `floors`, in order.
std::vector<int> floor_holes(const std::vector<CommittedFlows>& flows, const std::vector<std::size_t>& which) {
  std::vector<int> holes;
  for (std::size_t i : which)
    for (const HoleFloor& floor : flows[i].floors) holes.push_back(floor.hole);
  std::sort(holes.begin(), holes.end());
  return holes;
}

// The group's fill `outcome` failed, or was delivered unfaired, and flows that this fill delivered
// before it (`flows`) reach into the room its patch may take: a flow's patch, a longer dome than its
// linear floor, can take the room a later patch needs (two openings of a severed part that face
// each other), and then every fairing of the later group crosses it. Those flows are given their
// floors on a copy of the mesh (where the floor does not cross the mesh itself), and the group is
// filled again there (`again(mesh)`); that fill replaces `outcome` where it is faired (or, after a
// failure, fills the group without folding back). Returns which flows it gave their floors ({} where it did not
// replace `outcome`). (docs/real-holes.md, "An earlier flow given its floor".)
template <class Again>
std::vector<std::size_t> fill_again_with_earlier_floors(const Mesh& mesh,
                                                        const std::vector<std::vector<int>>& patch_loops,
                                                        const std::vector<int>& group,
                                                        const std::vector<CommittedFlows>& flows,
                                                        const std::vector<HoleReport>& unfilled,
                                                        std::vector<HoleReport>& reports, ChainOutcome& outcome,
                                                        Again again) {
  const bool failed = !outcome.reason.empty();
  if (!failed && outcome.start != PatchStart::unfaired) return {};
  const Eigen::AlignedBox3d room = patch_room(mesh.V, patch_loops);
  std::vector<std::size_t> given;
  std::optional<Mesh> floored;
  for (std::size_t i = 0; i < flows.size(); ++i) {
    if (!reaches_into(room, mesh.V, flows[i])) continue;
    if (!floored) floored = mesh;
    place(flows[i].floors, floored->V);
    if (find_face_intersections(floored->V, floored->F, flows[i].faces, 1).empty()) {
      given.push_back(i);
      continue;
    }
    for (const HoleFloor& floor : flows[i].floors)
      for (int v : floor.vertices) floored->V.row(v) = mesh.V.row(v);
  }
  if (given.empty()) return {};
  const std::string before = failed ? "the fill failed (" + reports[group.front()].reason + ")"
                                    : std::string("every fairing crossed the mesh (the last resort: the refined "
                                                  "triangulation, unfaired)");
  bool kept = false;
  const auto gain = [&](const ChainOutcome& retried) -> std::string {
    if (!failed && retried.start == PatchStart::unfaired) return "";
    // As retriangulate_if_failed: a failed group is not closed by a patch that folds back (a part's
    // opening facing another's, which blend joins).
    if (failed && group_folds_back(reports, group)) return "";
    kept = true;
    const std::vector<int> holes = floor_holes(flows, given);
    const bool one = holes.size() == 1;
    return before + "; the flow's patch of " + hole_list(holes) + ", filled before, reaches into its room: " +
           (one ? "that hole" : "those holes") + " given the linear solution " + (one ? "its" : "their") +
           " flow started from, filled again";
  };
  fill_again_where_better(group, unfilled, reports, outcome, [&] { return again(*floored); }, gain);
  return kept ? given : std::vector<std::size_t>{};
}

// The reports of the flows `given` their floors by a later group's fill (`later`), now committed
// into `mesh` (connectivity `topo`): each hole is the linear solution its flow started from,
// measured again; the flows are taken off `flows`.
void report_given_floors(const Mesh& mesh, const Topology& topo, const std::vector<int>& later,
                         std::vector<std::size_t> given, std::vector<CommittedFlows>& flows,
                         std::vector<HoleReport>& reports) {
  std::sort(given.rbegin(), given.rend());
  for (std::size_t i : given) {
    for (const HoleFloor& floor : flows[i].floors) {
      HoleReport& r = reports[floor.hole];
      const std::string flow_note = r.note;
      r.linear = true;
      r.steps = 0;
      r.final_max_velocity = std::numeric_limits<double>::quiet_NaN();
      r.two_ring_boundary_fits = false;
      r.continuity = measure_continuity(mesh.V, mesh.F, topo, floor.vertices);
      r.note = "its " + std::string(to_string(flow_for(r.supported))) + " flow's patch took the room of " +
               hole_list(later) + ", filled after it, every fairing of which crossed it: given the linear ∆" +
               std::to_string(static_cast<int>(r.supported) + 1) + " solution the flow started from" +
               (flow_note.empty() ? "" : " (the flow: " + flow_note + ")");
    }
    flows.erase(flows.begin() + static_cast<std::ptrdiff_t>(i));
  }
}

// Whether a loop of `group` runs around a lone triangle, which the group's patch takes in.
bool takes_in_a_lone_triangle(const std::vector<HoleReport>& reports, const std::vector<int>& group) {
  return std::any_of(group.begin(), group.end(), [&](int h) { return reports[h].around_a_face; });
}

bool filled_alone_instead(Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                          const std::vector<int>& group, const std::string& joint_outcome, const FillOptions& options,
                          const FillObserver& observer, const std::vector<HoleReport>& unfilled,
                          std::vector<HoleReport>& reports, std::optional<Topology>& filled,
                          std::vector<CommittedFlows>& flows);

// The order of continuity a hole's fill delivers: 2, 1, 0 for G2 or C2 (linear), G1 or C1, G0 or C0;
// −1 for a patch left unfaired.
int delivered_order(const HoleReport& r) { return r.unfaired ? -1 : static_cast<int>(r.supported); }

// The orders of continuity the holes of `group` are delivered at, summed weighed by border edges.
long weighed_order(const std::vector<HoleReport>& reports, const std::vector<int>& group) {
  long sum = 0;
  for (int h : group) sum += static_cast<long>(reports[h].border_edges) * delivered_order(reports[h]);
  return sum;
}

// Whether the holes of `group` filled one by one (`alone`) fare better than their joint fill
// (`joint`): every hole closes, none unfaired where the joint fill was not, none folding back where
// it did not or further than it did (the edges of fins, data/triple_vierbein.obj repaired: a G2
// fill at 158° is no better than the joint C0 at 153°), and the orders of continuity rise, summed
// over the holes weighed by their border edges, or they stay and the joint fill's fold back is
// gone. A hole may come out lower alone, where a neighbour still open when it is filled leaves it
// fewer complete rings than the joint patch had (bench_stress --cut small-balls on spot, seed
// 95001: a 64-edge hole G0 instead of C1, while 19 holes beside it rise from C1 to G2 or C2 and a
// 116-edge one no longer folds back at 145°).
bool better_alone(const std::vector<HoleReport>& joint, const std::vector<HoleReport>& alone,
                  const std::vector<int>& group) {
  for (int h : group) {
    if (alone[h].status != HoleStatus::filled || (alone[h].unfaired && !joint[h].unfaired)) return false;
    if (folds_back(alone[h]) && (!folds_back(joint[h]) || alone[h].continuity.max_normal_angle >
                                                              joint[h].continuity.max_normal_angle))
      return false;
  }
  const long gain = weighed_order(alone, group) - weighed_order(joint, group);
  return gain > 0 || (gain == 0 && group_folds_back(joint, group) && !group_folds_back(alone, group));
}

// Why a joint group's fill is tried again hole by hole, or "" where it is not: the group closed
// only unfaired, or below the requested order after its requested fairing failed (the ∆³ floor
// crossed the mesh too, and ∆² or ∆ closed it), which one crossing among many holes can cause. A
// group whose retried flow or ∆³ closed it is not, though its loops without interior vertex are C0.
std::string joint_shortfall(const ChainOutcome& outcome, const std::vector<HoleReport>& reports,
                            const std::vector<int>& group, const FillOptions& options) {
  if (group.size() < 2) return "";
  if (outcome.start == PatchStart::unfaired) return "closed only as its refined triangulation, unfaired";
  if (outcome.first_failure.empty()) return "";
  // The group's fairing is its highest order: a loop without interior vertex is C0 under any.
  const auto h = *std::max_element(group.begin(), group.end(), [&](int a, int b) {
    return delivered_order(reports[a]) < delivered_order(reports[b]);
  });
  if (delivered_order(reports[h]) >= static_cast<int>(options.continuity)) return "";
  return "closed only " + delivered_label(reports[h].supported, reports[h].linear) + " after its " +
         to_string(options.continuity) + " fill failed (" + outcome.first_failure + ")";
}

// Fills `group` from the membrane and the refined triangulation (fill_from_membrane), triangulated
// again where that fill folds back (retriangulate_if_folded_back) or fails (retriangulate_if_failed),
// and all that again where it still fails or is delivered unfaired, with the earlier flows in its
// way at their floors (fill_again_with_earlier_floors, FillOptions::floor_earlier_flows); commits
// the fill, unless it folds back against a lone triangle it takes in or, closed short of what was
// asked (joint_shortfall), its holes close better one by one (filled_alone_instead), and keeps its
// flows' floors in `flows`.
void fill_group_falling_back(Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                             const std::vector<int>& group, const std::vector<std::vector<int>>& patch_loops,
                             const FillOptions& options, const FillObserver& observer,
                             std::vector<HoleReport>& reports, std::optional<Topology>& filled,
                             std::vector<CommittedFlows>& flows) {
  const Topology& current = filled ? *filled : topo;
  std::vector<HoleReport> unfilled;
  for (int h : group) unfilled.push_back(reports[h]);
  const auto fill_on = [&](const Mesh& on) {
    GroupPatches patches(on, current, patch_loops, options.patch);
    ChainOutcome outcome = fill_from_membrane(on, loops, group, patches, options, observer, unfilled, reports);
    if (outcome.reason.empty())
      retriangulate_if_folded_back(on, current, loops, group, patch_loops, patches, options, observer, unfilled,
                                   reports, outcome);
    else
      retriangulate_if_failed(on, current, loops, group, patch_loops, patches, options, observer, unfilled, reports,
                              outcome);
    return outcome;
  };
  ChainOutcome outcome = fill_on(mesh);
  const std::vector<std::size_t> given =
      options.fallback_on_failure && options.floor_earlier_flows
          ? fill_again_with_earlier_floors(mesh, patch_loops, group, flows, unfilled, reports, outcome, fill_on)
          : std::vector<std::size_t>{};
  if (outcome.reason.empty() && takes_in_a_lone_triangle(reports, group) && group_folds_back(reports, group)) {
    // A lone triangle folded against the patch that took it in: not a fill of the surface it was
    // cut from; the group fails, and the triangle's loop is reported as not taken in.
    char text[200];
    std::snprintf(text, sizeof text,
                  "the patch that takes the lone triangle in folds back (it turns the normal across the border by "
                  "%.1f deg)",
                  largest_border_angle(reports, group) * kDegrees);
    for (std::size_t k = 0; k < group.size(); ++k) reports[group[k]] = unfilled[k];
    mark(reports, group, HoleStatus::failed, text);
    return;
  }
  if (!outcome.reason.empty()) return;
  if (const std::string shortfall = joint_shortfall(outcome, reports, group, options);
      !shortfall.empty() &&
      filled_alone_instead(mesh, topo, loops, group, shortfall, options, observer, unfilled, reports, filled, flows))
    return;
  const int first_face = mesh.num_faces();
  std::vector<HoleFloor> floors = std::move(outcome.filled.floors);
  commit(outcome.filled, mesh, filled);
  if (!given.empty()) report_given_floors(mesh, *filled, group, given, flows, reports);
  if (floors.empty()) return;
  std::vector<int> faces(static_cast<std::size_t>(mesh.num_faces() - first_face));
  std::iota(faces.begin(), faces.end(), first_face);
  flows.push_back({std::move(floors), std::move(faces)});
}

// The loops of `group` as one patch fills them: relinked at the border's pinches (relink_pinched_loops),
// or nullopt with `error` saying why a pinch's wedges could not be relinked.
std::optional<std::vector<std::vector<int>>> relinked_loops(const Mesh& mesh, const Topology& topo,
                                                            const std::vector<std::vector<int>>& loops,
                                                            const std::vector<int>& group, std::string& error) {
  std::vector<std::vector<int>> group_loops;
  for (int h : group) group_loops.push_back(loops[h]);
  try {
    return detail::relink_pinched_loops(mesh.V, mesh.F, topo, group_loops);
  } catch (const Error& e) {
    error = e.what();
    return std::nullopt;
  }
}

// Whether loop `h` shares a vertex with a loop of `group` around a lone triangle.
bool beside_a_lone_triangle(const std::vector<std::vector<int>>& loops, const std::vector<int>& group,
                            const std::vector<HoleReport>& reports, int h) {
  std::vector<char> lone(loops.size(), 0);
  for (int other : group) lone[static_cast<std::size_t>(other)] = reports[other].around_a_face;
  return fill_detail::flagged_loop_at_a_pinch(loops, h, lone).first >= 0;
}

// A joint group that failed as a whole (fill_group_falling_back), or that closed short of what was
// asked (filled_alone_instead): each hole again alone, in the order of `group`, the others open or
// as filled before it, so that one hole no fairing can close (the outer border of an open surface)
// does not keep the holes whose rings overlap its own open or unfaired. A hole filled alone
// says what the joint fill did (`joint_outcome`: "failed (...)"); one that fails alone keeps its own
// reason with the joint one, which it does not repeat where it failed for the same (`joint_failure`).
void fill_group_one_by_one(Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                           const std::vector<int>& group, const std::string& joint_outcome,
                           const std::string& joint_failure, const FillOptions& options, const FillObserver& observer,
                           std::vector<HoleReport>& reports, std::optional<Topology>& filled,
                           std::vector<CommittedFlows>& flows) {
  for (int h : group) {
    HoleReport& r = reports[h];
    const std::string joint_fill = "the joint fill with " + hole_list(r.filled_with);
    const std::string joint = joint_fill + " " + joint_outcome;
    r.filled_with.clear();
    // A lone triangle's loop alone, or a loop through its pinch alone, could only close a cone
    // there: they keep the joint failure (report_lone_triangles_not_taken_in says the rest).
    if (r.around_a_face || beside_a_lone_triangle(loops, group, reports, h)) continue;
    std::string relink_error;
    const auto patch_loops = relinked_loops(mesh, topo, loops, {h}, relink_error);
    if (!patch_loops) {
      r.reason = relink_error + "; " + joint;
      continue;
    }
    fill_group_falling_back(mesh, topo, loops, {h}, *patch_loops, options, observer, reports, filled, flows);
    if (r.status == HoleStatus::filled)
      r.note = joint + "; filled alone" + (r.note.empty() ? "" : "; " + r.note);
    else
      r.reason += r.reason == joint_failure ? "; " + joint_fill + " failed too, for the same reason" : "; " + joint;
  }
}

// A joint group's holes filled one by one on a copy of the mesh (fill_group_one_by_one).
struct AloneFill {
  Mesh mesh;
  std::optional<Topology> topology;
  std::vector<CommittedFlows> flows;
  std::vector<HoleReport> reports;
};

// A joint group that closed short of what was asked (joint_shortfall, said by `joint_outcome`: only
// its refined triangulation unfaired, or ∆² or ∆ after every higher fairing of the joint patch
// crossed the mesh), filled again hole by hole (fill_group_one_by_one) on a copy of `mesh`, before
// the group's fill is committed: one opening no fairing closes no longer leaves the openings beside
// it unfaired (bench_stress on Demosthenes, seed 21005: a 43-edge hole beside a 146-edge one closes
// C2 (linear) alone), and one crossing among 81 small holes no longer leaves them all at the
// membrane (bench_stress --cut small-balls on blub, seed 95005). The holes go once in index order
// and once shortest first: a hole filled later has its neighbours' patches in its fixed rings,
// where an open neighbour leaves it fewer complete rings and a lower order. Which order serves best
// depends on the group (on Demosthenes the 146-edge hole, unfaired, gives its small neighbour its
// rings; on spot, seed 95001, a 64-edge hole comes out G0 in index order and G2 shortest first).
// The copy with the higher weighed order that fares better than the joint fill (better_alone)
// replaces it; ties go to index order, and the second order is skipped where the first delivers
// every hole at the requested order. `unfilled`: the group's reports before its fill. Returns
// whether it replaced the group's fill.
bool filled_alone_instead(Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                          const std::vector<int>& group, const std::string& joint_outcome, const FillOptions& options,
                          const FillObserver& observer, const std::vector<HoleReport>& unfilled,
                          std::vector<HoleReport>& reports, std::optional<Topology>& filled,
                          std::vector<CommittedFlows>& flows) {
  std::optional<AloneFill> best;
  const auto fill_alone = [&](const std::vector<int>& order) {
    AloneFill alone{mesh, filled, flows, reports};
    for (std::size_t k = 0; k < group.size(); ++k) alone.reports[group[k]] = unfilled[k];
    fill_group_one_by_one(alone.mesh, topo, loops, order, joint_outcome, "", options, observer, alone.reports,
                          alone.topology, alone.flows);
    if (better_alone(reports, alone.reports, group) &&
        (!best || weighed_order(alone.reports, group) > weighed_order(best->reports, group)))
      best = std::move(alone);
  };
  fill_alone(group);
  std::vector<int> shortest_first = group;
  std::stable_sort(shortest_first.begin(), shortest_first.end(),
                   [&](int a, int b) { return loops[a].size() < loops[b].size(); });
  const auto every_hole_at_requested_order = [&](const AloneFill& fill) {
    return std::all_of(group.begin(), group.end(), [&](int h) {
      return delivered_order(fill.reports[h]) == static_cast<int>(options.continuity);
    });
  };
  if (shortest_first != group && !(best && every_hole_at_requested_order(*best))) fill_alone(shortest_first);
  if (!best) return false;
  mesh = std::move(best->mesh);
  filled = std::move(best->topology);
  flows = std::move(best->flows);
  reports = std::move(best->reports);
  return true;
}

// A failed hole's reason, told that its loop also runs round lone triangle `r.lone_triangle`, with
// one repair hint where the reason already gives one for the triangle at a pinch.
void add_lone_triangle_reason(HoleReport& r) {
  const std::string lone = "; the loop also runs round a lone triangle, face " + std::to_string(r.lone_triangle) +
                           ", hanging at a vertex it passes twice: ";
  if (!r.reason.ends_with(fill_detail::kLoneTriangleRepairHint)) {
    r.reason += lone + "repair splits the vertex and removes the triangle";
    return;
  }
  r.reason.resize(r.reason.size() - fill_detail::kLoneTriangleRepairHint.size());
  r.reason += lone + "repair splits those vertices and removes the lone triangles";
}

}  // namespace

const char* to_string(HoleStatus status) {
  switch (status) {
    case HoleStatus::filled: return "filled";
    case HoleStatus::skipped: return "skipped";
    case HoleStatus::failed: return "failed";
  }
  return "unknown";
}

FillOptions::FillOptions() : FairRegionOptions(harmonic_started()) {
  // A patch starts as a membrane, not a surface estimate: its own operator carries the membrane's
  // kink along the border, so ∆^k is re-evaluated until it settles (fair_region.h).
  harmonic_start_iterations = 8;
  // Within 5% the held-out rings cannot tell a hole's flow and linear fill apart (docs/real-holes.md,
  // "Ties go to the flow"): such a tie goes to the G2 that was asked for.
  held_out_margin = 1.05;
  // On noisy surroundings the held-out rings reward the linear fill for following the noise
  // (docs/real-holes.md, "Rough surroundings"): there the re-evaluated ∆³ solution does not win by them.
  held_out_max_roughness = 0.05;
}

bool folds_back(const HoleReport& hole) {
  return hole.status == HoleStatus::filled && detail::turns_back(hole.continuity.max_normal_angle);
}

bool open_at_lone_triangle(const FillReport& report, const HoleReport& hole) {
  // Along the chain of pinches; each hole on it names one found unfillable before it, so it ends.
  const HoleReport* at = &hole;
  for (std::size_t steps = 0; steps < report.holes.size(); ++steps) {
    if (at->status != HoleStatus::failed) return false;
    if (at->lone_triangle >= 0) return true;
    if (at->pinched_by < 0) return false;
    at = &report.holes[static_cast<std::size_t>(at->pinched_by)];
    if (at->around_a_face) return true;
  }
  return false;
}

FillReport fill_holes(Mesh& mesh, const FillOptions& options, const FillObserver& observer) {
  const auto start = Clock::now();
  if (options.max_hole_edges < 0)
    throw InvalidArgument("fill_holes: max_hole_edges must be >= 0, got " + std::to_string(options.max_hole_edges));
  if (!(options.crossing_retry_relaxation >= 0 && options.crossing_retry_relaxation <= 1))
    throw InvalidArgument("fill_holes: crossing_retry_relaxation must lie in [0, 1], got " +
                          std::to_string(options.crossing_retry_relaxation));
  fair_detail::require_valid_held_out_options(options, "fill_holes");
  const Topology topo = fill_detail::require_fillable(mesh);
  FillReport report;
  report.input_vertices = mesh.num_vertices();
  report.input_faces = mesh.num_faces();
  // The connectivity of the mesh once groups are filled into it: the next group's patch reads it.
  // The loops, groups and pinches stay those of the input (`topo`).
  std::optional<Topology> filled;
  // The flows filled so far over their linear floors, which a later group may give back.
  std::vector<CommittedFlows> flows;
  const auto loops = boundary_loops(mesh.F, topo);
  report.holes = hole_reports(loops, options);

  const std::vector<int> fillable = fill_detail::fillable_holes(mesh.V, mesh.F, topo, loops, options, report.holes);
  const int rings = rings_needed(options.continuity);
  for (const auto& group : fill_detail::overlapping_groups(topo, loops, fillable, rings)) {
    std::string relink_error;
    const auto patch_loops = relinked_loops(mesh, topo, loops, group, relink_error);
    if (!patch_loops) {
      mark(report.holes, group, HoleStatus::failed, relink_error);
      continue;
    }
    for (int h : group)
      for (int other : group)
        if (other != h) report.holes[h].filled_with.push_back(other);
    const auto group_start = Clock::now();
    fill_group_falling_back(mesh, topo, loops, group, *patch_loops, options, observer, report.holes, filled, flows);
    if (group.size() > 1 && report.holes[group.front()].status == HoleStatus::failed) {
      const std::string joint_failure = report.holes[group.front()].reason;
      fill_group_one_by_one(mesh, topo, loops, group, "failed (" + joint_failure + ")", joint_failure, options,
                            observer, report.holes, filled, flows);
    }
    for (int h : group) report.holes[h].seconds = seconds_since(group_start);
  }
  fill_detail::report_lone_triangles_not_taken_in(loops, report.holes);
  for (auto& r : report.holes) {
    if (r.status != HoleStatus::failed) continue;
    if (r.lone_triangle >= 0) add_lone_triangle_reason(r);
    if (r.hanging_piece_at >= 0)
      r.reason += "; the loop is the whole border of a piece with no vertex inside that hangs at vertex " +
                  std::to_string(r.hanging_piece_at) + " (debris?): no patch took it in";
  }
  for (const auto& r : report.holes) {
    report.filled += r.status == HoleStatus::filled;
    report.skipped += r.status == HoleStatus::skipped;
    report.failed += r.status == HoleStatus::failed;
  }
  report.seconds = seconds_since(start);
  return report;
}

}  // namespace fairsurf
