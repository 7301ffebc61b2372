// fill_holes (fill.h): the holes selected, grouped where their rings overlap, and each group filled
// through the fallback chain around fill_group (fill_group.h): other starts, retries, triangulations.
#include <fairsurf/applications/fill.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/mesh_attributes.h>
#include <fairsurf/mesh/topology.h>

#include "border_fold.h"
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
#include <numbers>
#include <numeric>
#include <optional>

namespace fairsurf {
namespace {

using detail::Clock;
using detail::seconds_since;

using fill_detail::FilledMesh;
using fill_detail::GroupPatches;
using fill_detail::HoleFloor;
using fill_detail::PatchCrossing;
using fill_detail::PatchStart;

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

void mark(std::vector<HoleReport>& reports, const std::vector<int>& group, HoleStatus status,
          const std::string& reason) {
  for (int h : group) {
    reports[h].status = status;
    reports[h].reason = reason;
  }
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

// The note of a hole filled after `first_failure`: what was delivered instead, and from where.
std::string fallback_note(const FillOptions& options, const std::string& first_failure, PatchStart start,
                          const FairRegionOptions& fairing, bool relaxed_retry, bool rejecting_retry,
                          const std::string& previous_start_failure, const HoleReport& r) {
  const std::string failed = "the " + std::string(to_string(options.continuity)) + " fill failed (" + first_failure + ")";
  if (start == PatchStart::unfaired)
    return failed + "; so did every fairing from the membrane and from the refined triangulation (the last: " +
           previous_start_failure + "): the refined triangulation is delivered unfaired, continuous in position only";
  const std::string from = start == PatchStart::refined && !previous_start_failure.empty()
                               ? "; every fairing from the membrane failed (the last: " + previous_start_failure +
                                     "); faired from the refined triangulation instead"
                               : "";
  if ((relaxed_retry || rejecting_retry) && fairing.method == FairMethod::flow) {
    std::string retries = relaxed_retry ? "; flowed again with its trial states relaxed tangentially" : "";
    if (rejecting_retry)
      retries += std::string(relaxed_retry ? ", which crossed too, and again" : "; flowed again") +
                 " with each trial that crosses the mesh rejected";
    return failed + from + retries + (r.note.empty() ? "" : ": " + r.note);
  }
  if (fairing.method == FairMethod::flow) return failed + from + (r.note.empty() ? "" : ": " + r.note);
  return failed + from + "; filled with " + delivered_label(fairing.continuity, r.linear);
}

// Where a run of the fallback chain ended: filled (`reason` empty, the filled mesh in `filled`) or
// failed, from which start, with which fairing, and what failed on the way.
struct ChainOutcome {
  std::string reason, first_failure, previous_start_failure;
  PatchStart start = PatchStart::membrane;
  FairRegionOptions fairing;
  bool relaxed_retry = false, rejecting_retry = false;
  // The last flow from this start whose patch crossed the mesh (retry_rejecting_crossings).
  std::optional<FairRegionOptions> crossing_flow;
  FilledMesh filled;
};

// Where the flow's patch crossed the mesh (relaxed too) and the linear ∆^k solution that replaced it,
// `c`, does not: the flow once more, with each trial that crosses the mesh rejected
// (FairRegionOptions::retry_rejecting_crossings), so that it stops short of the contact. That flow
// starts from the same ∆^k solution, which does not cross, so the rejection is on (a start that
// crosses turns it off, and then the retry would only repeat the flow). Where it fills the group,
// it replaces the linear fill in `c` and `reports`.
void retry_rejecting_crossings(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                               const std::vector<int>& group, GroupPatches& patches, const FillOptions& options,
                               const FillObserver& observer, std::vector<HoleReport>& reports, ChainOutcome& c) {
  if (!options.retry_rejecting_crossings) return;
  FairRegionOptions rejecting = *c.crossing_flow;
  rejecting.flow.reject_crossings = true;
  std::vector<HoleReport> linear;
  for (int h : group) linear.push_back(reports[h]);
  FilledMesh filled;
  PatchCrossing crossed = PatchCrossing::none;
  std::string reason;
  try {
    reason = fill_group(mesh, loops, group, patches, options, rejecting, c.start, observer, reports, filled, crossed);
  } catch (const Error& e) {
    reason = e.what();
  }
  if (!reason.empty()) {
    for (std::size_t k = 0; k < group.size(); ++k) reports[group[k]] = std::move(linear[k]);
    return;
  }
  c.filled = std::move(filled);
  c.fairing = rejecting;
  c.rejecting_retry = true;
}

// Fills `group` (fill_group) from `start`, and with FillOptions::fallback_on_failure tries on where
// it fails: the flow again with its trials relaxed tangentially where its patch crossed the mesh
// (crossing_retry_relaxation), then the linear ∆^k solutions from the requested continuity down
// (never a flow the user did not ask for), where the first of them is clear of the mesh the flow
// once more from it, rejecting the trials that cross (retry_rejecting_crossings); all that again
// from the refined triangulation instead of its membrane; last, that triangulation unfaired: where
// a loop bites deep into a thin part, every fairing from the membrane may cross the mesh while the
// refined patch does not. Marks the reports.
ChainOutcome run_fallback_chain(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                                const std::vector<int>& group, GroupPatches& patches, const FillOptions& options,
                                const FillObserver& observer, std::vector<HoleReport>& reports, PatchStart start) {
  ChainOutcome c;
  c.start = start;
  c.fairing = options;  // the fairing part of the options (sliced on purpose)
  for (;;) {
    PatchCrossing crossed = PatchCrossing::none;
    try {
      c.reason = fill_group(mesh, loops, group, patches, options, c.fairing, c.start, observer, reports, c.filled,
                            crossed);
    } catch (const Error& e) {
      c.reason = e.what();
    }
    if (c.start == PatchStart::unfaired && !c.reason.empty())
      c.reason = c.previous_start_failure + (crossed != PatchCrossing::none ? "; the refined triangulation, unfaired, crosses the mesh"
                                             : c.reason == c.previous_start_failure
                                                 ? "; the refined triangulation, unfaired, failed too, for the same reason"
                                                 : "; the refined triangulation, unfaired, failed too: " + c.reason);
    if (c.reason.empty() && c.crossing_flow && c.fairing.method == FairMethod::harmonic &&
        c.fairing.continuity == options.continuity)
      retry_rejecting_crossings(mesh, loops, group, patches, options, observer, reports, c);
    if (c.reason.empty() || !options.fallback_on_failure || c.start == PatchStart::unfaired) break;
    if (c.first_failure.empty()) c.first_failure = c.reason;
    if (crossed == PatchCrossing::flow) c.crossing_flow = c.fairing;
    if (crossed == PatchCrossing::flow && c.fairing.flow.tangential_relaxation < options.crossing_retry_relaxation) {
      c.fairing.flow.tangential_relaxation = options.crossing_retry_relaxation;
      c.relaxed_retry = true;
    } else if (c.fairing.method == FairMethod::flow || c.fairing.continuity != Continuity::G0) {
      if (c.fairing.method == FairMethod::harmonic)
        c.fairing.continuity = static_cast<Continuity>(static_cast<int>(c.fairing.continuity) - 1);
      c.fairing.method = FairMethod::harmonic;
    } else {  // the C0 (linear) solution failed too: the next start
      c.previous_start_failure = c.reason;
      c.start = c.start == PatchStart::membrane && options.patch.relax ? PatchStart::refined : PatchStart::unfaired;
      c.fairing = options;
      c.crossing_flow.reset();
      c.relaxed_retry = false;
    }
  }
  mark(reports, group, c.reason.empty() ? HoleStatus::filled : HoleStatus::failed, c.reason);
  if (c.reason.empty() && !c.first_failure.empty())
    for (int h : group)
      reports[h].note = fallback_note(options, c.first_failure, c.start, c.fairing, c.relaxed_retry,
                                      c.rejecting_retry, c.previous_start_failure, reports[h]);
  return c;
}

// The largest normal angle across the borders of the group's holes (radians); NaN where a hole's
// border was not measured (a patch of a few vertices leaves its border's one-sided fits too few
// points), so that no comparison takes it for a patch that does not fold.
double largest_border_angle(const std::vector<HoleReport>& reports, const std::vector<int>& group) {
  double angle = 0.0;
  for (int h : group) {
    if (reports[h].continuity.border_vertices == 0) return std::numeric_limits<double>::quiet_NaN();
    angle = std::max(angle, reports[h].continuity.max_normal_angle);
  }
  return angle;
}

// Whether the fill of some hole of the group folds back (folds_back).
bool group_folds_back(const std::vector<HoleReport>& reports, const std::vector<int>& group) {
  return std::any_of(group.begin(), group.end(), [&](int h) { return folds_back(reports[h]); });
}

// Fills `group` again with `again` (which returns the chain's outcome, its reports in `reports`),
// from the group's reports before any fill (`unfilled`), and keeps that fill in place of `outcome`
// where `gain` (given the new outcome) says why it is better: that reason then leads each report's
// note. Where the fill failed or `gain` returns "", `outcome` and its reports stay.
template <class Again, class Gain>
void fill_again_where_better(const std::vector<int>& group, const std::vector<HoleReport>& unfilled,
                             std::vector<HoleReport>& reports, ChainOutcome& outcome, Again again, Gain gain) {
  std::vector<HoleReport> kept;
  for (std::size_t k = 0; k < group.size(); ++k) {
    kept.push_back(std::move(reports[group[k]]));
    reports[group[k]] = unfilled[k];
  }
  ChainOutcome retried = again();
  const std::string why = retried.reason.empty() ? gain(retried) : std::string();
  if (why.empty()) {
    for (std::size_t k = 0; k < group.size(); ++k) reports[group[k]] = std::move(kept[k]);
    return;
  }
  for (int h : group) reports[h].note = why + (reports[h].note.empty() ? "" : ": " + reports[h].note);
  outcome = std::move(retried);
}

constexpr double kDegrees = 180 / std::numbers::pi;

// A group filled from the membrane whose patch folds back against the surface (folds_back), or
// whose flow folded back and gave way to its linear floor (flow_folded_back): the membrane can
// crease a patch against its border (a loop round a corner), and every fairing started there keeps
// the crease. The chain runs again from the refined triangulation, and its fill takes the first
// one's place where it turns the normal across the border less than a fill that folds back, or, in
// place of a floor kept for a flow that folded back, where it is the flow's and does not fold back;
// the note says so (FillOptions::refill_folded_back; docs/fill.md, "A fill that folds back").
// `unfilled`: the group's reports before the first fill.
void refill_if_folded_back(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                           const std::vector<int>& group, GroupPatches& patches, const FillOptions& options,
                           const FillObserver& observer, const std::vector<HoleReport>& unfilled,
                           std::vector<HoleReport>& reports, ChainOutcome& outcome) {
  const auto any = [&](auto&& predicate) {
    return std::any_of(group.begin(), group.end(), [&](int h) { return predicate(reports[h]); });
  };
  const bool fill_folded = group_folds_back(reports, group);
  if (!fill_folded && !any([](const HoleReport& r) { return r.flow_folded_back; })) return;
  const double folded = largest_border_angle(reports, group);
  const auto from_refined = [&] {
    return run_fallback_chain(mesh, loops, group, patches, options, observer, reports, PatchStart::refined);
  };
  const auto gain = [&](const ChainOutcome& refined) -> std::string {
    if (refined.start != PatchStart::refined) return "";
    const double angle = largest_border_angle(reports, group);
    char text[256];
    if (fill_folded) {
      if (!(angle < folded)) return "";
      std::snprintf(text, sizeof text,
                    "the fill from the membrane folds back (it turns the normal across the border by %.1f deg); "
                    "filled from the refined triangulation instead, which turns it by %.1f deg",
                    folded * kDegrees, angle * kDegrees);
    } else {
      if (any([](const HoleReport& r) { return r.linear || folds_back(r); })) return "";
      std::snprintf(text, sizeof text,
                    "the flow from the membrane folds back where its linear floor does not; filled from the "
                    "refined triangulation instead, whose flow turns the normal across the border by %.1f deg",
                    angle * kDegrees);
    }
    return text;
  };
  fill_again_where_better(group, unfilled, reports, outcome, from_refined, gain);
}

// The fallback chain (run_fallback_chain) from the membrane of `patches`, and again from their refined
// triangulation where that fill folds back (refill_if_folded_back).
ChainOutcome fill_from_membrane(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                                const std::vector<int>& group, GroupPatches& patches, const FillOptions& options,
                                const FillObserver& observer, const std::vector<HoleReport>& unfilled,
                                std::vector<HoleReport>& reports) {
  ChainOutcome outcome =
      run_fallback_chain(mesh, loops, group, patches, options, observer, reports, PatchStart::membrane);
  if (outcome.reason.empty() && outcome.start == PatchStart::membrane && options.patch.relax &&
      options.refill_folded_back)
    refill_if_folded_back(mesh, loops, group, patches, options, observer, unfilled, reports, outcome);
  return outcome;
}

// Whether the patches `a` and `b` triangulate each loop alike (false where either cannot be built).
bool same_triangulations(GroupPatches& a, GroupPatches& b) {
  try {
    const std::vector<HoleTriangulation>& x = a.get(PatchStart::membrane).holes;
    const std::vector<HoleTriangulation>& y = b.get(PatchStart::membrane).holes;
    return std::equal(x.begin(), x.end(), y.begin(), y.end(), [](const HoleTriangulation& s, const HoleTriangulation& t) {
      return s.faces.rows() == t.faces.rows() && s.faces == t.faces;
    });
  } catch (const Error&) {
    return false;
  }
}

// Where the fill `outcome` still folds back, the group is triangulated again and filled from there:
// first with the lightest of the triangulation's starts (HoleTriangulationOptions::start_margin 0),
// then, where that fill folds back too, within the faces of each loop's Delaunay tetrahedralization
// (HoleTriangulationOptions::delaunay_restricted, CGAL's search). The first start's triangulation is
// kept unless another is lighter by the margin, since a few degrees lighter is no better a patch in
// general; but a fill that folds back is no patch at all. The starts' largest angles may differ by a
// few degrees where their shapes differ wholly (airplane 5947 4h: a loop round the edge of a thin
// plate, bridged through the plate from the first start at 110°, laid along both its sides from the
// lightest at 25°). A loop through a pinch twice (a lone triangle taken in) is first cut between its
// passes along the shortest cut, which decides the patch's shape there; it is next triangulated
// along the lightest of kBridgeCutsWeighed cuts (airplane trial 933 of bench_stress --cut irregular
// --seed 901: 106.6° from the shortest cut, 47.9° from the lightest), before the Delaunay faces,
// which do not apply to it. And where the largest angle is an edge that every triangulation has,
// area alone decides, and the least area may crease the patch across the hole, which the Delaunay faces leave
// out (spot 1294 8h, a blob: 168° from every start, 36.5° within them). A new fill is delivered where
// it turns the normal across the border by at most half as much (kRetriangulatedAngleRatio): a few
// degrees less on a folded patch, mostly noise in the border's fits, gave fills farther from the
// surface as often as closer (docs/fill.md, "Triangulated again", "Triangulated within the Delaunay
// faces").
constexpr double kRetriangulatedAngleRatio = 0.5;
constexpr int kBridgeCutsWeighed = 8;

// A triangulation to fill a folded group from again (retriangulate_if_folded_back), and how the note
// names it.
struct Retriangulation {
  FillOptions options;
  std::string name;       // "triangulated again from <name>"
  std::string where = "from";  // "triangulated again <where> <name>, it failed too"
};

// Whether the Delaunay restriction applies to some loop of `patch_loops`
// (delaunay_restriction_applies): where it applies to none, a triangulation within the faces would
// be the first one again, and building its patch only to find that out costs a whole patch (a
// scan's outer border: thousands of edges).
bool delaunay_applies(const std::vector<std::vector<int>>& patch_loops, const HoleTriangulationOptions& options) {
  return std::any_of(patch_loops.begin(), patch_loops.end(),
                     [&](const std::vector<int>& loop) { return delaunay_restriction_applies(loop, options); });
}

// Where a loop of `patch_loops` passes a pinch twice and the options weigh fewer cuts between its
// passes: the lightest of kBridgeCutsWeighed cuts (HoleTriangulationOptions::bridge_cuts_weighed).
void add_weighed_cuts(const FillOptions& options, const std::vector<std::vector<int>>& patch_loops,
                      std::vector<Retriangulation>& tries) {
  const bool through_a_pinch_twice = std::any_of(
      patch_loops.begin(), patch_loops.end(), [](const std::vector<int>& loop) { return passes_a_vertex_twice(loop); });
  if (!through_a_pinch_twice || options.patch.triangulation.bridge_cuts_weighed >= kBridgeCutsWeighed) return;
  tries.push_back({options, "the lightest of " + std::to_string(kBridgeCutsWeighed) +
                                " cuts between the loop's passes through a pinch"});
  tries.back().options.patch.triangulation.bridge_cuts_weighed = kBridgeCutsWeighed;
}

// Where the Delaunay restriction applies to a loop and is not on: the faces of the loops'
// tetrahedralizations.
void add_delaunay_faces(const FillOptions& options, const std::vector<std::vector<int>>& patch_loops,
                        std::vector<Retriangulation>& tries) {
  const HoleTriangulationOptions& triangulation = options.patch.triangulation;
  if (triangulation.delaunay_restricted || !delaunay_applies(patch_loops, triangulation)) return;
  tries.push_back({options, "the faces of the loop's Delaunay tetrahedralization", "within"});
  tries.back().options.patch.triangulation.delaunay_restricted = true;
}

std::vector<Retriangulation> retriangulations(const FillOptions& options,
                                              const std::vector<std::vector<int>>& patch_loops) {
  const HoleTriangulationOptions& triangulation = options.patch.triangulation;
  std::vector<Retriangulation> tries;
  if (triangulation.start_vertices > 1 && triangulation.start_margin > 0) {
    tries.push_back({options, "the lightest of " + std::to_string(triangulation.start_vertices) + " starts"});
    tries.back().options.patch.triangulation.start_margin = 0;
  }
  add_weighed_cuts(options, patch_loops, tries);
  add_delaunay_faces(options, patch_loops, tries);
  return tries;
}

// The triangulations a failed group is filled from again: within the faces of each loop's Delaunay
// tetrahedralization, where that applies, then, where a loop passes a pinch twice, along the
// lightest of the cuts between its passes (spot trial 1717 of bench_stress --cut irregular --seed
// 1701: the patch from the shortest cut crossed the mesh, the lightest cut's does not).
std::vector<Retriangulation> failure_retriangulations(const FillOptions& options,
                                                      const std::vector<std::vector<int>>& patch_loops) {
  std::vector<Retriangulation> tries;
  add_delaunay_faces(options, patch_loops, tries);
  add_weighed_cuts(options, patch_loops, tries);
  return tries;
}

void retriangulate_if_folded_back(const Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                                  const std::vector<int>& group, const std::vector<std::vector<int>>& patch_loops,
                                  GroupPatches& first_patches, const FillOptions& options,
                                  const FillObserver& observer, const std::vector<HoleReport>& unfilled,
                                  std::vector<HoleReport>& reports, ChainOutcome& outcome) {
  if (!options.refill_folded_back) return;
  for (const Retriangulation& again : retriangulations(options, patch_loops)) {
    if (!group_folds_back(reports, group)) return;
    GroupPatches patches(mesh, topo, patch_loops, again.options.patch);
    // The same triangulation: the same chains would give the same fill.
    if (same_triangulations(first_patches, patches)) continue;
    const double folded = largest_border_angle(reports, group);
    const auto refill = [&] {
      return fill_from_membrane(mesh, loops, group, patches, again.options, observer, unfilled, reports);
    };
    const auto gain = [&](const ChainOutcome&) -> std::string {
      const double angle = largest_border_angle(reports, group);
      if (!(angle <= kRetriangulatedAngleRatio * folded)) return "";
      char text[320];
      std::snprintf(text, sizeof text,
                    "the fill folds back (it turns the normal across the border by %.1f deg); triangulated again "
                    "from %s, whose fill turns it by %.1f deg",
                    folded * kDegrees, again.name.c_str(), angle * kDegrees);
      return text;
    };
    fill_again_where_better(group, unfilled, reports, outcome, refill, gain);
  }
}

// Where the group's fill failed (every patch of the fallback chain crossed the mesh or threw), it is
// made once more from the faces of each loop's Delaunay tetrahedralization (HoleTriangulationOptions::
// delaunay_restricted, CGAL's search). Round a thin tongue of the mesh reaching into a hole, the
// lightest triangulation from every start can cross the mesh where the Delaunay faces do not
// (bench_real_holes --cut blob --random 10 --seed 2, spot 1828 8h with noise; docs/fill.md,
// "Triangulated within the Delaunay faces"). Where a loop passes a pinch twice, to which those faces
// do not apply, it is made again along the lightest of the cuts between its passes
// (failure_retriangulations). A fill that folds back is not taken: from those faces a horn tip cut
// off by a ball (a part of its own, whose opening blend joins to the head's) was capped folded back
// at 172°, where the failure's reason says to blend.
void retriangulate_if_failed(const Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                             const std::vector<int>& group, const std::vector<std::vector<int>>& patch_loops,
                             GroupPatches& first_patches, const FillOptions& options, const FillObserver& observer,
                             const std::vector<HoleReport>& unfilled, std::vector<HoleReport>& reports,
                             ChainOutcome& outcome) {
  if (!options.fallback_on_failure) return;
  const std::string failure = reports[group.front()].reason;
  for (const Retriangulation& again : failure_retriangulations(options, patch_loops)) {
    if (outcome.reason.empty()) return;
    GroupPatches patches(mesh, topo, patch_loops, again.options.patch);
    if (same_triangulations(first_patches, patches)) continue;
    std::string failed_again;
    const auto refill = [&] {
      ChainOutcome retried =
          fill_from_membrane(mesh, loops, group, patches, again.options, observer, unfilled, reports);
      failed_again = reports[group.front()].reason;
      return retried;
    };
    const auto gain = [&](const ChainOutcome&) -> std::string {
      if (group_folds_back(reports, group)) {
        char text[160];
        std::snprintf(text, sizeof text, "its fill folds back: it turns the normal across the border by %.1f deg",
                      largest_border_angle(reports, group) * kDegrees);
        failed_again = text;
        return "";
      }
      return "the fill failed (" + failure + "); triangulated again from " + again.name;
    };
    fill_again_where_better(group, unfilled, reports, outcome, refill, gain);
    if (outcome.reason.empty()) return;
    for (int h : group)
      if (reports[h].status == HoleStatus::failed)
        reports[h].reason += "; triangulated again " + again.where + " " + again.name + ", it failed too (" +
                             failed_again + ")";
  }
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
// failure, fills the group at all). Returns which flows it gave their floors ({} where it did not
// replace `outcome`). (docs/fill.md, "An earlier flow given its floor".)
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

// Fills `group` from the membrane and the refined triangulation (fill_from_membrane), triangulated
// again where that fill folds back (retriangulate_if_folded_back) or fails (retriangulate_if_failed),
// and commits the fill, unless it folds back against a lone triangle it takes in.
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

// A joint group that failed as a whole (fill_group_falling_back): each hole again alone, in order,
// the others open or as filled before it, so that one hole no fairing can close (the outer border of
// an open surface) does not keep the holes whose rings overlap its own open. A hole filled alone
// says that the joint fill failed; one that fails alone keeps its own reason, with the joint one.
void fill_failed_group_one_by_one(Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                                  const std::vector<int>& group, const FillOptions& options,
                                  const FillObserver& observer, std::vector<HoleReport>& reports,
                                  std::optional<Topology>& filled, std::vector<CommittedFlows>& flows) {
  const std::string joint_failure = reports[group.front()].reason;
  for (int h : group) {
    HoleReport& r = reports[h];
    const std::string joint_fill = "the joint fill with " + hole_list(r.filled_with);
    const std::string joint = joint_fill + " failed (" + joint_failure + ")";
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
  // Within 5% the held-out rings cannot tell a hole's flow and linear fill apart (docs/fill.md,
  // "Ties go to the flow"): such a tie goes to the G2 that was asked for.
  held_out_margin = 1.05;
  // On noisy surroundings the held-out rings reward the linear fill for following the noise
  // (docs/fill.md, "Rough surroundings"): there the re-evaluated ∆³ solution does not win by them.
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
    if (group.size() > 1 && report.holes[group.front()].status == HoleStatus::failed)
      fill_failed_group_one_by_one(mesh, topo, loops, group, options, observer, report.holes, filled, flows);
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
