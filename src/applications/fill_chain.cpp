// The fallback chain of one group's fill (fill_chain.h).
#include "fill_chain.h"

#include <fairsurf/mesh/errors.h>
#include <fairsurf/patch/hole_triangulation.h>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace fairsurf::fill_detail {
namespace {

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
  for (int h : group) reports[h].unfaired = c.reason.empty() && c.start == PatchStart::unfaired;
  if (c.reason.empty() && !c.first_failure.empty())
    for (int h : group)
      reports[h].note = fallback_note(options, c.first_failure, c.start, c.fairing, c.relaxed_retry,
                                      c.rejecting_retry, c.previous_start_failure, reports[h]);
  return c;
}


// A group filled from the membrane whose patch folds back against the surface (folds_back), or
// whose flow folded back and gave way to its linear floor (flow_folded_back): the membrane can
// crease a patch against its border (a loop round a corner), and every fairing started there keeps
// the crease. The chain runs again from the refined triangulation, and its fill takes the first
// one's place where it turns the normal across the border less than a fill that folds back, or, in
// place of a floor kept for a flow that folded back, where it is the flow's and does not fold back;
// the note says so (FillOptions::refill_folded_back; docs/real-holes.md, "A fill that folds back").
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

}  // namespace

void mark(std::vector<HoleReport>& reports, const std::vector<int>& group, HoleStatus status,
          const std::string& reason) {
  for (int h : group) {
    reports[h].status = status;
    reports[h].reason = reason;
  }
}
double largest_border_angle(const std::vector<HoleReport>& reports, const std::vector<int>& group) {
  double angle = 0.0;
  for (int h : group) {
    if (reports[h].continuity.border_vertices == 0) return std::numeric_limits<double>::quiet_NaN();
    angle = std::max(angle, reports[h].continuity.max_normal_angle);
  }
  return angle;
}

bool group_folds_back(const std::vector<HoleReport>& reports, const std::vector<int>& group) {
  return std::any_of(group.begin(), group.end(), [&](int h) { return folds_back(reports[h]); });
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

namespace {

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
// surface as often as closer (docs/real-holes.md, "Triangulated again", "Triangulated within the Delaunay
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

}  // namespace

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
// (bench_real_holes --cut blob --random 10 --seed 2, spot 1828 8h with noise; docs/real-holes.md,
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

}  // namespace fairsurf::fill_detail
