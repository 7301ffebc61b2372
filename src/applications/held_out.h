// Private to fair_region: choosing between the flow and its linear floor by how well each
// re-predicts the input around the free region (FairRegionOptions::held_out_rings; docs/real-holes.md,
// "Which fairing a hole gets").
#pragma once

#include <fairsurf/applications/fair_region.h>
#include <fairsurf/mesh/submesh.h>

#include <limits>

namespace fairsurf::fair_detail {

/// Fill's solve from the patch before its membrane is taken where it re-predicts the held-out rings
/// this many times better than the re-evaluated ∆^k solution, which the flows start from; the flows
/// are then not tried. Between candidates whose truth distances are close the held-out verdict is a
/// coin toss, and this one is no better on average; where the membrane creases a patch (blub's tail
/// fin) it wins by 3-4× and lands 3× closer to the surface, while flows from the creased start crawl
/// at τ ≈ 1e-18 for seconds (docs/real-holes.md, "The patch before its membrane").
inline constexpr double kRefinedStartMargin = 2.0;

/// The flows' held-out trials rank the fairings; they need not settle. A trial still descending
/// after this many accepted steps is weighed where it stands. Half the descents on bench_real_holes
/// settle within 6 steps and 95% within 33; a few crawl with τ collapsed below 1e-10 of its start,
/// up to the 200-step limit, most of them already within 17% of their final energy 20 steps into
/// the crawl (docs/real-holes.md, "The held-out trials' budget").
inline constexpr int kHeldOutTrialSteps = 40;

/// Whether the held-out rings weigh the flow on 2-ring boundary fits too: asked for
/// (held_out_two_ring_fits) and not already the flow's own fits.
inline bool weighs_two_ring_fits(const FairRegionOptions& fairing) {
  return fairing.held_out_two_ring_fits && !fairing.flow.two_ring_boundary_fits;
}

/// Mean normal distance of the held-out input vertices from where each fairing puts them, in units
/// of the mean edge length at those vertices. ∞ when that fairing failed.
struct HeldOutErrors {
  /// NaN when not weighed: refined_start_wins().
  double flow = 0;
  double linear = 0;
  /// FairRegionOptions::held_out_two_ring_fits: the flow with FlowOptions::two_ring_boundary_fits;
  /// NaN when not weighed.
  double two_ring_flow = std::numeric_limits<double>::quiet_NaN();
  /// One ∆^k solve from other positions of the free vertices (fill: the patch before its membrane);
  /// NaN when none were given.
  double refined_linear = std::numeric_limits<double>::quiet_NaN();
  /// FairRegionOptions::held_out_other_functions: the flow with those functions, on 1-ring and
  /// 2-ring fits (as two_ring_flow); NaN when not weighed.
  double other_flow = std::numeric_limits<double>::quiet_NaN();
  double other_two_ring_flow = std::numeric_limits<double>::quiet_NaN();
  /// Of the flow's trial on the enlarged region (its report's, or its error's when the flow threw).
  WellPosedness flow_well_posedness;

  /// The solve from the other positions beats the re-evaluated one by kRefinedStartMargin (false
  /// when there was none).
  bool refined_start_wins() const { return kRefinedStartMargin * refined_linear < linear; }
};

/// Throws InvalidArgument, naming `caller`, where held_out_margin is below 1,
/// held_out_max_roughness below 0 (either NaN), or a held_out_other_functions entry does not parse.
void require_valid_held_out_options(const FairRegionOptions& options, const char* caller);

/// Frees the `rings` rings of fixed vertices around the free vertices in a copy of `sub`, fairs that
/// larger region with `fairing` (the flow with its linear floor; held_out_rings ignored), with the
/// same flow on 2-ring boundary fits where fairing.held_out_two_ring_fits asks, and with its
/// linear ∆^k solution alone, and measures how far each moved the held-out vertices off the input's
/// tangent planes there. `refined`, if given (#V of sub.mesh by 3, differing from it at the free
/// vertices only), is weighed too, before the flows: one ∆^k solve from those positions; where it
/// wins (HeldOutErrors::refined_start_wins) the flows are not tried, nor where `weigh_flows` is false
/// (the linear method: only the two linear solutions are weighed). The flows' trials start from the
/// re-evaluated linear solution, or from the refined solve where `flows_from_refined` (rough
/// surroundings: the delivered flow starts there too).
/// `local`: the connectivity of sub.mesh.
HeldOutErrors held_out_errors(const Submesh& sub, const Topology& local, int rings, const FairRegionOptions& fairing,
                              const Vertices* refined = nullptr, bool weigh_flows = true,
                              bool flows_from_refined = false);

/// fair_region on a mesh that has passed its validation, with `topo` the connectivity of mesh.F.
/// `measure`: measure report.continuity (a trial whose report is discarded skips it). `whole`, if
/// given, receives whether the neighbourhood of the free region was all of `mesh`: then fairing
/// ran on the mesh itself and report.continuity is measure_continuity(mesh.V, mesh.F, free set).
FairRegionReport fair_valid_mesh(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                 const FairRegionOptions& options, const FlowObserver& observer = {},
                                 bool measure = true, bool* whole = nullptr);

/// fair_valid_mesh with the ∆^k start already solved: the free vertices of `mesh` hold the linear
/// solution `start` reports (the held-out trials solve it once for their three fairings, which all
/// start from it). Only for the flow with a harmonic start; the result is what fair_valid_mesh
/// gives on the mesh before that solve.
FairRegionReport fair_valid_mesh_from(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                      const FairRegionOptions& options, const HarmonicReport& start);

/// fair_valid_mesh after require_valid(validate(mesh, topo)), a pinch of the border allowed
/// (detail::allow_border_pinches): fill's fairing of a hole's neighbourhood, which may hold a loop
/// through a pinch that is not filled (a lone triangle hanging at another hole's border), outside
/// the region or in its rings as a border vertex. fair_region(mesh, topo, ...) with
/// fair_valid_mesh's further arguments.
/// `refined` (fill): other positions of mesh's free vertices (#V by 3, equal elsewhere), from which
/// one ∆^k solve is a further candidate of the held-out choice (FairRegionReport::refined_start).
FairRegionReport fair_checked_mesh(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                   const FairRegionOptions& options, const FlowObserver& observer = {},
                                   bool measure = true, bool* whole = nullptr, const Vertices* refined = nullptr);

}  // namespace fairsurf::fair_detail
