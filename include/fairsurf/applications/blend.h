// fairsurf — blending two boundary loops with a fair G2 tube (method.md §7, the paper's Figs 3–4).
//
// Two boundary loops of one mesh — or of two meshes concatenated first (concatenate_meshes) — are
// joined by an initial tube (patch.h's tube_patch: loops aligned, Hermite rings, zipper strips,
// refinement to the surrounding edge length, then the G0 membrane unless it pinches off), and the
// tube's new vertices are faired by fair_region (fair_region.h): by default the sixth-order flow of
// f = H to a steady state with the three rings of each surface around the loops as G2 boundary data
// (continued by the energy descent where the time-stepped flow does not settle: descent_fallback).
//
// Loops are numbered in topology.h's boundary_loops order (sorted by their smallest vertex index).
// Both surfaces must be oriented alike across the tube (tube.h): two outward-oriented pieces, or
// two pieces of one consistently oriented mesh.
#pragma once

#include <fairsurf/applications/fair_region.h>
#include <fairsurf/flow/flow.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/mesh_operations.h>
#include <fairsurf/patch/patch.h>

#include <string>
#include <vector>

namespace fairsurf {

/// A blend is a region fairing of the tube: the FairRegionOptions it derives from (fair_region's
/// plain defaults: continuity G2, the flow of f = H from the tube as built; options.flow.functions,
/// options.method, ...) say how, the fields below which loops to join and how to build the tube.
struct BlendOptions : FairRegionOptions {
  /// Indices of the two loops to join, into boundary_loops(mesh); both −1: the closest pair
  /// (tube.h's closest_loop_pair).
  int loop_a = -1, loop_b = -1;
  /// The initial tube. With patch.relax the G0 membrane is tried and kept only if it does not
  /// pinch off (see pinch_quality_ratio); patch.relax = false always starts from the Hermite tube.
  PatchOptions patch;
  /// The membrane is discarded, and the flow starts from the Hermite tube, when the membrane's
  /// worst triangle quality falls below this fraction of the Hermite tube's: no minimal surface
  /// spans loops far apart for their size (two ends of a cross), and the membrane collapses onto a
  /// sheet of slivers (quality 1e-9) that no flow can start from. It is still the last start where
  /// every tube without it crosses the mesh (blend_loops).
  double pinch_quality_ratio = 0.25;
  /// When the sixth-order flow steps in time (flow.step_kind = FlowStepKind::implicit_flow) and ends
  /// without a steady state or throws, continue with the energy descent (FlowStepKind::energy_descent,
  /// steady once a step lowers E by less than 1e-5 of itself, trials that would cross the mesh
  /// rejected: FlowOptions::reject_crossings) from its last accepted state, from the tube it started
  /// from and from the linear ∆^k tube from that, keep the result whose tube does not cross the mesh,
  /// then one that does not fold against the linear tube (its border normal angle above 1.5 times
  /// the linear tube's and above 5°, fill's rule), then the one of lowest energy (the observer sees
  /// that descent's steps only) and say so in the report's fair.note; a descent that settles is
  /// kept before one that does not, and where none settles the linear ∆^k tube is delivered if it
  /// does not cross the mesh (blend_loops). On real meshes the
  /// time-stepped flow often does not settle (the fitted EL is not the gradient of the discrete
  /// energy on irregular rings); where it does, as on the analytic scenes, its result is kept
  /// unchanged.
  bool descent_fallback = true;
  /// Rings around each loop kept when the continuity is measured at one border (both sides' 2-ring
  /// fits must fit inside). Each figure is taken at its own loop's vertices only.
  int measure_rings = 4;
  /// The reference measurement (BlendLoop::reference) is taken this many rings from each loop on
  /// the input; 0: not taken.
  int reference_ring = 3;
  /// Deliver the linear ∆^k tube where the flow's settled tube turns the normal across the loops
  /// more than it does or creases against it (docs/blend.md, "A G2 tube that turns more than the
  /// linear one", "Creased tubes"). false: keep the flow's tube wherever it settles clear of the
  /// mesh (keep_settled_flow).
  bool weigh_against_linear_tube = true;
  /// Where the flow's tube crosses the mesh, the flow is tried once more from the tube before the
  /// linear tube takes its place, each of its trial states relaxed tangentially by this fraction
  /// (FlowOptions::tangential_relaxation), as FillOptions::crossing_retry_relaxation does for a
  /// hole's patch: a crossing of a few tube triangles sheared over at a notch of a loop (the raw
  /// hammer scan's band, docs/blend.md). 0: no second try.
  double crossing_retry_relaxation = 0.5;
  /// Where the tube started from the G0 membrane folds back at a loop (folds_back), or is the linear
  /// tube kept in place of a flow's tube that turned the normal back (fair.flow_folded_back), or fell
  /// below the requested continuity because every tube above it crossed the mesh
  /// (crossing_fallback), the blend runs again from the Hermite tube (patch.relax off): between loops
  /// cut across a thin part the membrane can lie flat against one side and crease the tube at a
  /// loop, and every fairing from it keeps the crease. That tube is delivered where it turns the
  /// normal across the loops less (the larger of the two loops' angles), or, in place of a lower
  /// continuity, where it reaches a higher one and does not fold back; fair.note says which
  /// (docs/blend.md, "Built again from the Hermite tube", "A linear tube kept in place of a flow
  /// that folds back").
  bool rebuild_without_membrane = true;
};

/// keep_settled_flow for a blend: the base's checks off (fair_region.h) and the flow's settled tube
/// not weighed against the linear tube (weigh_against_linear_tube = false). The linear tube still
/// takes a tube that does not settle or crosses the mesh.
void keep_settled_flow(BlendOptions& options);

/// One of the two loops that were joined.
struct BlendLoop {
  int index = -1;            ///< into boundary_loops of the input
  int length = 0;            ///< vertices
  ContinuityMeasure border;  ///< measured at this loop after fairing (one-sided fits, continuity_measure.h)
  /// The same measurement on the untouched input, across the line of vertices reference_ring rings
  /// from the loop: what one-sided fits read where the surface is smooth by construction, i.e. the
  /// floor of `border` on this mesh (0 on a flat disk; on a coarse curved scan it is not small).
  ContinuityMeasure reference;
};

/// The tube folds back at `loop`: it turns the normal across the loop (border.max_normal_angle) by
/// more than a right angle and by more than twice the untouched input's reading there
/// (reference.max_normal_angle), a seam no fairing leaves where the two loops face each other. It
/// happens where they do not, as when a band is cut off a thin flat part (docs/blend.md).
bool folds_back(const BlendLoop& loop);

struct BlendReport {
  int loops_found = 0;        ///< boundary loops of the input
  bool automatic = false;     ///< the pair was chosen by closest_loop_pair
  double loop_distance = 0;   ///< symmetric mean nearest-vertex distance of the pair (tube.h)
  BlendLoop a, b;
  int tube_vertices = 0;      ///< new vertices (all free)
  int tube_faces = 0;         ///< new faces (after refinement)
  int tube_rings = 0;         ///< intermediate rings of the unrefined tube
  /// Worst triangle quality of the tube, 4√3·area / Σ edge² (1 equilateral, 0 degenerate): of the
  /// refined Hermite tube, and of the membrane (0 when not relaxed).
  double hermite_quality = 0, membrane_quality = 0;
  bool relaxed = false;       ///< the flow started from the membrane (false: not asked, or it pinched)
  /// The tube from the membrane folded back or fell below the requested continuity, and the one
  /// from the Hermite tube was delivered instead (BlendOptions::rebuild_without_membrane).
  bool rebuilt_without_membrane = false;
  /// The tube from Hermite rings crossed the mesh after fairing, even linear, and was built again
  /// with straight rings (TubeOptions::hermite = false); the qualities, sizes and `relaxed` are then
  /// that second tube's, and fair.note says why.
  bool straight_rings = false;
  FairRegionReport fair;      ///< requested/supported continuity, steps, final max|V|, whole border
  double seconds = 0;         ///< wall time of the whole call
};

/// Joins two boundary loops of `mesh` and fairs the tube. On return `mesh` holds the input's
/// vertices and faces first (unchanged), then the tube's (per-vertex attributes are dropped, as in
/// patch.h). Throws InvalidMeshError for fewer than two loops; InvalidArgument for an index out of
/// range (the message lists every loop with its length), equal indices or only one index given;
/// RepairableMeshError for two loops that share a vertex (a non-manifold vertex: repair.h splits
/// it); what tube_patch and fair_region throw otherwise (NumericalError with `mesh` at the last accepted
/// state of the flow).
///
/// The linear ∆^k tube from the same start replaces the flow's tube (fair.linear, with the reason
/// in fair.note; fair.method stays flow and fair.flow holds only the flow's well_posedness, as for
/// fair_region's floor) where it does not cross the mesh (find_face_intersections) and
/// - the flow's tube crosses it;
/// - the descent fallback ran and no descent settled ("did not settle"); a flow the user asked for
///   that did not settle (descent_fallback off, or the descent as the step kind) is delivered as it
///   stands, NOT steady;
/// - or the flow settled but is no gain over the linear tube: it turns the normal across the loops
///   (fair.continuity's max_normal_angle) by more than 1.05 times the linear tube's and by more
///   than 5° (docs/blend.md, "A G2 tube that turns more than the linear one"), or it creases
///   against it: more of its edges have faces whose normals turn by over 90° than twice the linear
///   tube's and than the linear tube's plus 4 (a fin folded out of the tube; "Creased tubes").
///   Where the ∆^k tube crosses the mesh, the first lower linear tube (∆^(k−1), ..., ∆) that does
///   not is the one weighed and delivered (fair.crossing_fallback).
/// Where the flow's tube and the linear one both cross, a tube from Hermite rings is built again
/// with straight rings and faired the same way (straight_rings; the observer sees both fairings'
/// steps). Where that one crosses as well, the linear tubes of the lower continuities (∆², then ∆),
/// from Hermite rings and then straight ones, replace it: the first that does not cross is
/// delivered (fair.linear and fair.crossing_fallback, fair.requested the continuity asked for,
/// fair.supported the lower one, the crossings in fair.note), as fill and fair_region fall back.
/// Where every one crosses and a G0 membrane was dropped as pinched (pinch_quality_ratio), all of
/// this runs once more from the membrane (relaxed; fair.note begins "every tube without the G0
/// membrane, which pinches off, crosses the mesh"). Where every one crosses still, NumericalError
/// names the first crossings (`mesh` then holds the last tube tried).
BlendReport blend_loops(Mesh& mesh, const BlendOptions& options = {}, const FlowObserver& observer = {});

/// A pair of loops blend_all_loops chose and could not join: both stay open, and neither is joined
/// to another loop.
struct UnjoinedLoops {
  /// Indices of the two loops into boundary_loops of the mesh blend_all_loops returns.
  int loop_a = -1, loop_b = -1;
  int length_a = 0, length_b = 0;  ///< their vertices
  std::string why;                 ///< what blend_loops threw for them
  /// It threw RepairableMeshError: the loops touch, or one passes through a vertex twice, at a
  /// non-manifold vertex that repair (repair.h) splits.
  bool repairable = false;
};

struct BlendAllReport {
  std::vector<BlendReport> blends;    ///< each pair joined, in order (loop indices as that blend found them)
  std::vector<UnjoinedLoops> unjoined;  ///< each pair that could not be joined, in the order tried
  int loops_left = 0;                 ///< boundary loops of the result
  double seconds = 0;                 ///< wall time of the whole call
};

/// Joins the closest pair of boundary loops, then the closest pair of the loops left, and so on
/// until fewer than two are left: blend_loops with the pair chosen each time, for a part cut apart
/// at several places (data/cgal_blobby_3cc.off: three pieces, two gaps). A pair blend_loops cannot
/// join (NumericalError: every tube crosses the mesh; RepairableMeshError: the loops touch) is left
/// as it was and listed in `unjoined`, and its two loops are paired with no other: the closest loop
/// to each of them was the other, and a tube to a farther loop would join what the cut did not
/// separate. The mesh then holds every other pair joined. Throws InvalidArgument where `options`
/// name a pair (loop_a, loop_b), InvalidMeshError where the mesh has fewer than two loops, and what
/// blend_loops throws otherwise (`mesh` then holding the pairs joined before).
BlendAllReport blend_all_loops(Mesh& mesh, const BlendOptions& options = {}, const FlowObserver& observer = {});

/// Measures continuity at the vertices of `loop` only: on the faces within `rings` rings of it,
/// with the free vertices among them (continuity_measure.h's measure_continuity).
ContinuityMeasure measure_continuity_at_loop(const Mesh& mesh, const std::vector<int>& loop,
                                             const std::vector<int>& free_vertices, int rings = 4);

}  // namespace fairsurf
