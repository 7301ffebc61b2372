// Private to fill_holes: the fallback chain of one group's fill (fill_group.h fills from one start;
// this chains the starts, the linear solutions down the continuities, the retries, and the group's
// triangulations again), and what fill.cpp needs to weigh one outcome against another.
#pragma once

#include <fairsurf/applications/fill.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include "fill_group.h"

#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace fairsurf::fill_detail {

inline constexpr double kDegrees = 180 / std::numbers::pi;

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


/// Sets the status and reason of each hole of `group`.
void mark(std::vector<HoleReport>& reports, const std::vector<int>& group, HoleStatus status,
          const std::string& reason);

// The largest normal angle across the borders of the group's holes (radians); NaN where a hole's
// border was not measured (a patch of a few vertices leaves its border's one-sided fits too few
// points), so that no comparison takes it for a patch that does not fold.
double largest_border_angle(const std::vector<HoleReport>& reports, const std::vector<int>& group);

// Whether the fill of some hole of the group folds back (folds_back).
bool group_folds_back(const std::vector<HoleReport>& reports, const std::vector<int>& group);

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


// The fallback chain from the membrane of `patches`, and again from their refined triangulation
// where that fill folds back (FillOptions::refill_folded_back). `unfilled`: the group's reports
// before the first fill.
ChainOutcome fill_from_membrane(const Mesh& mesh, const std::vector<std::vector<int>>& loops,
                                const std::vector<int>& group, GroupPatches& patches, const FillOptions& options,
                                const FillObserver& observer, const std::vector<HoleReport>& unfilled,
                                std::vector<HoleReport>& reports);

// Where the fill `outcome` still folds back, the group triangulated again and filled from there
// (fill_chain.cpp says from which triangulations, and when a new fill is delivered).
void retriangulate_if_folded_back(const Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                                  const std::vector<int>& group, const std::vector<std::vector<int>>& patch_loops,
                                  GroupPatches& first_patches, const FillOptions& options,
                                  const FillObserver& observer, const std::vector<HoleReport>& unfilled,
                                  std::vector<HoleReport>& reports, ChainOutcome& outcome);

// Where the group's fill failed, it made once more from other triangulations of its loops
// (fill_chain.cpp).
void retriangulate_if_failed(const Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
                             const std::vector<int>& group, const std::vector<std::vector<int>>& patch_loops,
                             GroupPatches& first_patches, const FillOptions& options, const FillObserver& observer,
                             const std::vector<HoleReport>& unfilled, std::vector<HoleReport>& reports,
                             ChainOutcome& outcome);

}  // namespace fairsurf::fill_detail
