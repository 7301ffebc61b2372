// fairsurf — fairing a free region of a mesh with Gk boundary data: the shared engine of hole
// filling, region fairing (free-form design) and blending.
//
// The free vertices and six rings around them are cut out (submesh.h), so each step costs in
// proportion to the region. The continuity asked for picks the flow: G2 the sixth-order flow of
// the chosen f (three fixed rings), G1 Willmore flow (two rings), G0 mean curvature flow (one ring).
// Where the mesh offers fewer complete rings (the region comes near a mesh border), the continuity
// falls back to what the data supports and the report says so. The flow runs to a steady state
// (FlowOptions::steady_tolerance) or its step limit. The classical baseline (`harmonic`) solves the
// cotangent ∆^(k+1) x = 0 instead.
#pragma once

#include <fairsurf/flow/flow.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/solve/harmonic.h>

#include <limits>
#include <span>
#include <string>
#include <vector>

namespace fairsurf {

enum class FairMethod { flow, harmonic };
/// "flow" or "harmonic".
const char* to_string(FairMethod method);
/// Inverse of to_string; throws InvalidArgument naming the valid methods.
FairMethod parse_fair_method(const std::string& name);

struct FairRegionOptions {
  Continuity continuity = Continuity::G2;
  FairMethod method = FairMethod::flow;
  /// Flow settings, used as given. Leave `kind` unset: the flow follows from the continuity
  /// (flow_for; the supported one where the fixed rings fall short), and a kind that contradicts
  /// the requested continuity is refused (InvalidArgument). The defaults here run to a steady state:
  /// max|V| under steady_tolerance, at most max_steps steps.
  FlowOptions flow = default_fair_flow_options();
  LinearSolverOptions harmonic_solver;  ///< for method == harmonic (and harmonic_start)
  /// method == flow: start the flow from the cotangent ∆^k x = 0 solution (k = supported
  /// continuity + 1) instead of the given positions, solved up to this many times with the operator
  /// re-evaluated at the previous solution each time; 0: flow from the given positions.
  /// method == harmonic: the same re-evaluated solution (at least one solve). One solve is
  /// not enough from a flat patch: the operator frozen there carries the patch's kink along its
  /// border, and ∆³ then overshoots by O(1/h) (0.14, 0.27, 0.57 above a unit sphere cap at 386,
  /// 1536, 6460 patch vertices); re-evaluated, it settles within 3e-3 of the sphere in 4 solves.
  int harmonic_start_iterations = 0;
  /// The re-evaluation stops once a solve moves no free vertex by more than this times the mean
  /// length of the edges at free vertices (HarmonicOptions::tolerance).
  double harmonic_start_tolerance = 0.1;
  int submesh_rings = 6;                ///< rings kept around the free region (submesh.h)
  /// method == flow with a ∆^k start: when the flow throws or ends without a steady state, keep the
  /// ∆^k solution it started from — the linear C(k−1) result, reported `linear` with the reason —
  /// instead of throwing or returning an unsettled state. The result is then never worse than the
  /// classical baseline, and the energy descent (FlowStepKind::energy_descent) only lowers E from it.
  bool linear_floor = false;
  /// With the linear floor: hold out this many rings of fixed vertices around the free region, fair
  /// the enlarged region with the flow and with the linear ∆^k solution alone, and deliver the linear
  /// solution where it lies closer to the held-out input (mean distance along the input's vertex
  /// normals). A flow then never replaces the classical baseline where it extrapolates the
  /// surrounding surface worse (on real meshes the fitted energy can prefer shapes the surface does
  /// not have; docs/fill.md). Costs two more fairings of a slightly larger region; the flow's trial
  /// runs at most 40 accepted steps and is weighed where it stands (it only ranks). 0: off.
  int held_out_rings = 0;
  /// With held_out_rings: also weigh the flow with its boundary data fitted over 2-rings
  /// (FlowOptions::two_ring_boundary_fits, unless flow already sets it) and deliver whichever of the
  /// three fairings re-predicts the held-out rings best. On noisy surroundings the 2-ring fits
  /// average out the noise the flow would otherwise carry into the region (docs/real-holes.md, "Boundary
  /// data over two rings"). Costs one more fairing of the enlarged region.
  bool held_out_two_ring_fits = false;
  /// With held_out_rings: also weigh the flow with these energy functions instead of
  /// flow.functions (on 2-ring boundary fits too, where held_out_two_ring_fits), and run the flow
  /// with them where they re-predict the held-out rings best. {"H", "K/kappa"} adds the Gaussian
  /// curvature term, which pays on clean tori and machined parts and costs on noisy organic ones;
  /// the held-out rings choose per region (docs/real-holes.md, "Gaussian curvature in the energy"). Costs
  /// one more fairing of the enlarged region (two with the 2-ring fits). Empty: off. An entry that
  /// does not parse (parse_energy_functions) is refused, InvalidArgument, before any fairing.
  std::vector<std::string> held_out_other_functions;
  /// With held_out_rings: the linear solution is delivered only where its held-out error times this
  /// stays below the flow's (the better of the two flows'). 1 here: the plain comparison.
  /// harmonic_started() (`fairsurf fair`) uses 1.015 and FillOptions 1.05: within so little the
  /// held-out rings cannot tell the two fairings apart, and such a tie goes to the G2 that was asked
  /// for; on marked regions fill's 1.05 costs distance (docs/real-holes.md, "Ties go to the flow" and
  /// "Ties go to the flow, for regions too"). At least 1.
  double held_out_margin = 1.0;
  /// With held_out_rings: whether they may choose a linear solution (the ∆^k floor, or fill's solve
  /// from the patch before its membrane). false (keep_settled_flow): they only choose the flow's
  /// boundary fits, 1-ring or 2-ring (held_out_two_ring_fits), and are not run without the choice.
  bool held_out_may_choose_linear = true;
  /// With held_out_rings and held_out_may_choose_linear: where the surface around the region is
  /// rougher than this (roughness(), mesh_quality.h, over the vertices 3 and 4 rings out of the
  /// region, in edges), the re-evaluated ∆^k solution does not win by them (fill's solve from before
  /// the membrane still may, by its factor of 2). A linear solution held by the input's noisy rings
  /// follows their noise into the held-out rings and wins there by following it, not by lying
  /// closer to the surface. There, fill's solve from before the membrane is the linear solution
  /// instead: the flow starts from it (its held-out trials too) and falls back to it, and the linear
  /// method delivers it without weighing, since on noisy borders it lies closer to the surface than
  /// the re-evaluated solution (docs/real-holes.md, "The refined solve on rough surroundings"). ∞ (here,
  /// and for `fairsurf fair`): off;
  /// FillOptions uses 0.05, above the 0.000–0.021 of the clean meshes and scans of data/ and below
  /// the 0.073–0.084 that 0.1 edges of noise reads on them (docs/real-holes.md, "Rough surroundings").
  double held_out_max_roughness = std::numeric_limits<double>::infinity();
  /// With the linear floor: a flow whose steady state turns the normal across the region's border
  /// (ContinuityMeasure::max_normal_angle) by more than this many times the ∆^k solution it started
  /// from does, and by more than 5 degrees, folds against it: the linear solution is kept, reported
  /// `linear` with the angles in the note. Such a state is not the curvature-continuous surface it
  /// is labelled, and on real holes it lands farther from the surface than the floor more often than
  /// not (docs/real-holes.md, "A flow that folds against its start"). Where the surroundings are rough
  /// (above held_out_max_roughness), the largest angle is one border vertex's reading of the noise,
  /// and the flow folds only where it exceeds the ratio on average (mean_normal_angle) too, along
  /// one loop of the border (docs/real-holes.md, "A fold is a turn along the border"). Infinity: off.
  double max_border_angle_ratio = std::numeric_limits<double>::infinity();
  /// With the linear floor: a flow whose steady state folds back across the region's border (turns
  /// the normal by more than a right angle) where the ∆^k solution it started from does not is not
  /// delivered either, whatever max_border_angle_ratio says; keep_settled_flow keeps this check. The
  /// linear solution is kept, with both angles in the note, and FairRegionReport::flow_folded_back
  /// set (fill then tries the refined triangulation: docs/real-holes.md, "A fill that folds back").
  bool refuse_folding_back = true;
  /// With the linear floor and held_out_two_ring_fits: where the flow the held-out rings chose folds
  /// against its ∆^k start (max_border_angle_ratio, refuse_folding_back) and the floor is kept, the
  /// flow with the other boundary fits (2-ring for 1-ring, 1-ring for 2-ring) runs from the same
  /// start, if its held-out error was below the linear solution's, and is delivered where it
  /// settles without folding. The fold is often the noise of the border read by one of the two fits
  /// (docs/real-holes.md, "The other boundary fits after a fold"). false: the floor stays.
  bool retry_other_boundary_fits = false;
  /// With the linear floor: where the flow's result crosses the mesh where the given region did
  /// not, the flow runs once more from the same start, each trial that crosses the mesh rejected
  /// (FlowOptions::reject_crossings), so that it stops short of the contact instead of passing
  /// through it; its result is delivered where it settles as a flow clear of the mesh, before a
  /// linear solution takes the crossing result's place. A region over a thin part (a wing's edge, a
  /// fin) otherwise lost its G2 to a few triangles pushed through the other sheet (docs/blend.md,
  /// "Region fairing"). Fill retries the same way where its flow's patch crosses the mesh, relaxed
  /// too (FillOptions::crossing_retry_relaxation), and the linear ∆^k fill that replaces it does
  /// not; blend's descents reject crossing trials from the start. false: no such retry.
  bool retry_rejecting_crossings = true;

  static FlowOptions default_fair_flow_options();
  /// The options that settle a disk-like region (a hole's patch, a marked region) in a few steps:
  /// the flow starts from the cotangent ∆^k solution with the region's own operator
  /// (harmonic_start_iterations = 1: on a real surface, the classical fairing; FillOptions'
  /// defaults re-evaluate it up to 8 times, since a patch starts as a membrane)
  /// with a Newton-like first step (flow.tau = 1e-2; a rejected step still quarters it); the
  /// sixth-order flow descends the energy (FlowStepKind::energy_descent, steady once a step lowers E
  /// by less than 1e-5 of itself, 30 rejections in a row allowed), keeps the ∆³ solution as its
  /// floor (linear_floor) and delivers it where it re-predicts 2 held-out rings better
  /// (held_out_rings), the flow weighed also on 2-ring boundary fits (held_out_two_ring_fits), or
  /// where the flow folds against it (max_border_angle_ratio 1.5) and the flow with the other
  /// boundary fits does too or re-predicts them worse (retry_other_boundary_fits);
  /// and both linear solvers use the minimum-degree ordering, whose analysis is far cheaper on
  /// patch-sized systems. From a flattened cap the plain defaults do not settle
  /// beyond about a thousand free vertices (docs/blend.md). Used by fill_holes and `fairsurf fair`; not
  /// by blend, whose tubes' ∆³ re-evaluation can fold a tube around a corner (fairing_cross).
  static FairRegionOptions harmonic_started();
};

/// Keeps the flow wherever it settles: switches off the two checks that weigh a settled flow against
/// its linear floor, the held-out rings' choice of a linear solution (held_out_may_choose_linear =
/// false; they still choose the flow's 1-ring or 2-ring boundary fits) and the fold check
/// (max_border_angle_ratio = ∞). The floor still takes a flow that throws, does not settle, or folds
/// back where the floor does not (refuse_folding_back), and fill's fallbacks a patch that crosses
/// the mesh. For a user who wants the G2 asked for over a C2 result that may lie closer to the
/// surface, which on real holes it often does (docs/fill.md, "Keeping the flow").
void keep_settled_flow(FairRegionOptions& options);

struct FairRegionReport {
  int free_vertices = 0;
  Continuity requested = Continuity::G2;
  Continuity supported = Continuity::G2;  ///< what the fixed rings allow; the flow used this one
  FairMethod method = FairMethod::flow;
  FlowKind flow_kind = FlowKind::sixth_order;  ///< when method == flow
  /// When method == flow. Where held_out_rings chose the linear solution, only its
  /// well_posedness is set: that of the flow's trial on the enlarged region.
  FlowReport flow;
  /// When method == harmonic, or of the flow's start (FairRegionOptions::harmonic_start_iterations)
  HarmonicReport harmonic;
  /// The result is the linear ∆^k solution (C(k−1), reported as such, not as G(k−1)): method
  /// harmonic, or the flow's floor (FairRegionOptions::linear_floor); `note` says why for the floor.
  bool linear = false;
  std::string note;
  /// held_out_rings: mean normal distance of the held-out vertices from the input after the flow and
  /// after the linear solution, in mean edge lengths (∞: that fairing failed; NaN: not measured, as
  /// for the flows of a fill hole whose refined_start won before they were tried).
  double held_out_flow_error = std::numeric_limits<double>::quiet_NaN();
  double held_out_linear_error = std::numeric_limits<double>::quiet_NaN();
  /// held_out_two_ring_fits: the same after the flow with its boundary data fitted over 2-rings.
  double held_out_two_ring_flow_error = std::numeric_limits<double>::quiet_NaN();
  /// Fill only: the same for one ∆^k solve from the patch as refinement left it, before the
  /// membrane (InitialPatch::refined_free); NaN when not weighed. It is weighed before the flows.
  double held_out_refined_linear_error = std::numeric_limits<double>::quiet_NaN();
  /// FairRegionOptions::held_out_max_roughness: the roughness of the surface around the region it
  /// was weighed against; NaN when not measured (the limit is off, or the rings could not choose a
  /// linear solution anyway).
  double held_out_roughness = std::numeric_limits<double>::quiet_NaN();
  /// Fill only: the delivered linear solution is that one (report.linear is then true too), taken
  /// where its held-out error is under half the re-evaluated linear solution's, from which the
  /// flows start; they are then not tried (their errors NaN). The linear method (method = harmonic,
  /// with held_out_rings) weighs the same two linear solutions and no flow. Around a region rougher
  /// than held_out_max_roughness it is the linear solution without weighing: the linear method's
  /// result, and the flow's floor, set where the floor is kept.
  bool refined_start = false;
  /// The held-out rings chose a linear solution (refined_start's or the re-evaluated one) over the
  /// flow, which was then not run on the region; where the flow ran and was not kept (it did not
  /// settle, threw or folded against its start), false.
  bool held_out_linear = false;
  /// The linear solution was delivered over the flow by a check that keep_settled_flow switches
  /// off: the held-out rings (held_out_linear) or the fold check (a settled flow that folds against
  /// its start); blend: the angle or crease rule against the linear tube. Not where the flow did not
  /// settle, threw or crossed the mesh. For a region in parts, set where any part's is.
  bool checks_chose_linear = false;
  /// The flow settled but folded back where the linear solution it started from does not, and the
  /// linear solution was kept (FairRegionOptions::refuse_folding_back). For a region in parts, set
  /// where any part's is. Blend: the linear tube was kept by the angle or crease rule in place of a
  /// flow's tube that turned the normal across the loops by more than a right angle.
  bool flow_folded_back = false;
  /// The fairing first reached crossed the mesh, and the linear solution delivered is the first
  /// that does not, possibly at a lower continuity than the rings support (`supported` is then
  /// that lower one; `note` says so).
  bool crossing_fallback = false;
  /// The flow ran with FlowOptions::two_ring_boundary_fits (given, or chosen by the held-out rings).
  bool two_ring_boundary_fits = false;
  /// held_out_other_functions: the errors of the flow with those functions, on 1-ring and 2-ring
  /// boundary fits (as held_out_flow_error), and whether the held-out rings chose them: the flow
  /// then ran with them.
  double held_out_other_flow_error = std::numeric_limits<double>::quiet_NaN();
  double held_out_other_two_ring_flow_error = std::numeric_limits<double>::quiet_NaN();
  bool other_functions = false;
  /// Where a flow was delivered over the linear floor (linear_floor on, `linear` false), the floor:
  /// the positions of the free vertices at the linear ∆^k solution the flow started from, #free by
  /// 3, one row per free vertex in ascending vertex order. Empty otherwise, and for a region in
  /// parts. (fill gives a patch its floor where the flow's patch takes the room of a later hole.)
  Vertices floor_positions;
  ContinuityMeasure continuity;                ///< measured after fairing
  double seconds = 0;                          ///< wall time of the whole call
  /// A region in parts whose fixed rings do not meet (region_parts) is faired part by part, each
  /// with its own flow, floor, held-out choice and checks, the later parts on the mesh as the
  /// earlier ones left it; their reports are here, in the order of their smallest vertex. The
  /// fields above then describe the whole: free_vertices, seconds and the flow's steps summed,
  /// `supported` the lowest part's, `linear` set where any part's result is linear (so that
  /// delivered_label never claims more than every part has), `flow` the parts' flows together
  /// where every part flowed (steady only where each is; else, as for a kept floor, only its
  /// well_posedness), `continuity` over the whole region, `note` each part's label. Empty for a
  /// region of one part.
  std::vector<FairRegionReport> parts;

  /// The flow ran on the region and `flow` holds its report. False for method harmonic, where
  /// held_out_rings chose the linear solution before any flow on the region, and where the flow
  /// threw and the floor was kept (`note` says so).
  bool has_flow_report() const { return method == FairMethod::flow && flow.free_vertices > 0; }
};

/// The flow that reaches continuity `c` from c+1 fixed rings: mean curvature (G0), Willmore (G1),
/// sixth order (G2).
FlowKind flow_for(Continuity c);

/// The parts of the free region `free_vertices` (valid indices of topo's vertices) whose `rings`
/// fixed rings do not meet: the free vertices grouped by the connected components of the vertices
/// within `rings` rings of the region, so that parts are more than 2·rings + 1 edges apart and the
/// fairing of one reads none of another's vertices. Each part ascending, without repeats; the parts
/// in the order of their smallest vertex.
std::vector<std::vector<int>> region_parts(const Topology& topo, std::span<const int> free_vertices, int rings);

/// Fairs the vertices `free_vertices` of `mesh` (mesh.V updated in place; only free vertices move).
/// Requires a manifold, consistently oriented mesh without degenerate faces (InvalidMeshError).
/// Throws InvalidArgument for an empty or out-of-range free set or a flow.kind that contradicts the
/// continuity, NumericalError if the flow or the solve fails — with mesh.V at the last accepted state.
/// With the linear floor (harmonic_started()), a result whose region crosses the mesh where the
/// given region did not (find_face_intersections; faces that crossed in the given mesh, as a noisy
/// scan's may, may cross other faces once they move, but no more often in all) is replaced by
/// the first linear ∆^k solution from the given positions,
/// k from the continuity reached down to 1, that does not (reported `linear`, the reason in
/// `note`); NumericalError if every one crosses, with mesh.V at the result. A region in parts is
/// faired part by part (FairRegionReport::parts); a part whose fairing throws NumericalError is put
/// back where it was given, the others are faired all the same, and then NumericalError names the
/// parts that failed and what the others got (mesh.V holds the faired parts).
/// Free vertices with no fixed vertex in their connected component of the mesh (a vertex no face
/// uses, a component marked whole) have nothing to be faired against: they stay where they are, the
/// others are faired as if they were not free (`free_vertices` does not count them), and `note`
/// starts with what stayed; InvalidArgument if that is the whole region.
FairRegionReport fair_region(Mesh& mesh, std::span<const int> free_vertices,
                             const FairRegionOptions& options = {},
                             const FlowObserver& observer = {});
/// The same on `topo`, the connectivity of mesh.F (build_topology), instead of building it again.
FairRegionReport fair_region(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                             const FairRegionOptions& options = {}, const FlowObserver& observer = {});

}  // namespace fairsurf
