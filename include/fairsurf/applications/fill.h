// fairsurf — N-sided hole filling with G2 boundary data (method.md §7), end to end.
//
// Pipeline, per hole: the boundary loop (topology.h boundary_loops, in its order: loop i is hole i)
// is triangulated, refined to the surrounding edge length and relaxed to a G0 membrane (patch.h
// hole_patch); then the patch's new vertices are faired with the hole's border and the rest of the
// mesh fixed (fair_region.h: the sixth-order flow to a steady state for G2, or the cotangent ∆^k
// baseline), so the fixed rings around the hole carry the position, tangent plane and curvature
// data. The original vertices never move and keep their order and positions; new vertices and faces
// are appended after them. Per-vertex attributes (scalars, colours) are dropped once a hole is
// filled, since their length would no longer be #V.
//
// Holes whose fixed rings overlap (their borders are at most 2·rings − 2 edges apart, rings = the
// fixed rings of the requested continuity, 3 for G2) are filled jointly: one patch, one free region,
// so neither sees the other's open border as a cut in its boundary data. Other holes are filled one
// after another on the growing mesh, in the order of their first hole index. A hole whose
// surroundings offer fewer complete rings than the continuity needs (it comes close to a border that
// stays open) is faired with the continuity the data supports, and its report says so.
//
// A hole is filled at a continuity only if its flow reaches a steady state (FlowOptions
// steady_tolerance / steady_relative_tolerance): a flow that stops at its step limit, whether its
// max|V| ended below where it started ("did not settle") or above ("diverged"), fails the fill at
// that continuity, which is then (by default) retried one continuity lower: G2 → G1 → G0, the
// report's note saying why. So `supported` G2 means a settled G2 flow, never a partial one.
//
// A pinch of the border (a vertex with more than two border edges, several fans of faces) is
// filled: every loop through it is filled in one group, its border edges relinked at the pinch so
// that the patches join the fans into one disk, and the result is manifold there. Where another
// loop through the pinch is not filled, a loop is filled alone only where its patch joins the
// vertex's two fans (two holes touching at a corner); else it fails too.
//
// Failures are per hole and leave the mesh as it was before that hole: a pinch shared with a loop
// that is not filled ("non-manifold border"), a triangulation or refinement that throws, a patch
// that would make an edge or vertex non-manifold, or a patch whose faces cross the mesh
// (face_intersection.h) however it is faired, even not at all (FillOptions::fallback_on_failure).
// The other holes are still filled. A fill from the membrane that folds back against the surface
// (folds_back), or whose flow did, is made again from the refined triangulation, which is delivered
// where it does not fold back or folds less, and one that still folds back from another
// triangulation of its loop (FillOptions::refill_folded_back).
#pragma once

#include <fairsurf/applications/fair_region.h>
#include <fairsurf/energy/energy_function.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/patch/patch.h>

#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace fairsurf {

/// A fill is a region fairing of each hole's patch: the FairRegionOptions it derives from say how
/// (continuity, G2 by default; method, flow or harmonic; the flow's functions f, "H" by default,
/// stopping rule and solver: options.flow.functions), the fields below what to fill and how to
/// patch it.
struct FillOptions : FairRegionOptions {
  /// fair_region's harmonic_started() defaults, except that the ∆^k start is re-evaluated up to 8
  /// times (harmonic_start_iterations): a membrane patch is far from the G2 steady state, and from
  /// there the flow needs hundreds of steps with τ growing from 1e-9, from ∆³ a few (docs/fill.md).
  /// From there the flow takes a Newton-like first step (τ = 1e-2: the step control quarters it on
  /// rejection), and both linear solvers use the minimum-degree ordering (LinearSolverOptions::
  /// ordering), whose analysis is far cheaper than nested dissection's on patch-sized systems.
  /// The linear solution is delivered only where the held-out rings prefer it by more than 5%
  /// (held_out_margin = 1.05; docs/real-holes.md, "Ties go to the flow"); the re-evaluated ∆³ solution
  /// not at all where the surface around the hole is rough (held_out_max_roughness = 0.05;
  /// docs/real-holes.md, "Rough surroundings"): there the flow starts from, and falls back to, one ∆^k
  /// solve from the patch before its membrane, which the linear method delivers.
  FillOptions();

  PatchOptions patch;  ///< triangulation, refinement and membrane of the initial patch

  // Which boundary loops are filled. A loop left out is reported as skipped with the reason. A
  // 3-edge loop around a face of the mesh (a lone triangle) is skipped: its only fill on its own
  // is that face again, reversed; where the triangle hangs at a vertex of a hole's border, the
  // hole's patch takes it in instead (the two loops relinked at the vertex), or, where that fails,
  // it is skipped after all. So is a loop that is the whole border of a flat piece with no vertex
  // inside (a face of an unwelded triangle soup): its fill would be the piece reversed.
  std::vector<int> holes;   ///< loop indices (boundary_loops order); empty: every loop
  int max_hole_edges = 0;   ///< loops with more border edges are skipped; 0: no limit
  bool skip_largest = false;  ///< leave the longest loop (an open surface's outer border) open
  /// Reject a patch whose faces cross the surrounding mesh (face_intersection.h).
  bool check_intersections = true;
  /// When the fill of a hole fails (the flow throws or reaches no steady state without a linear
  /// floor, or the patch crosses the mesh), retry with the linear ∆^k solution at the requested
  /// continuity, then at each lower one down to the membrane (C0); the report's `note` says so. A
  /// lower continuity's flow runs only when asked for (`continuity`). If all of them fail, the same
  /// again with the fairings started from the refined triangulation instead of its membrane (a
  /// membrane folded against the border hands its fold to every fairing started there), and last
  /// that triangulation unfaired, C0 (linear) (docs/real-holes.md, "A loop that bites into a thin part").
  bool fallback_on_failure = true;
  /// With fallback_on_failure: where the flow's patch crosses the mesh, the flow is tried once more
  /// before the linear fallback, each of its trial states relaxed tangentially by this fraction
  /// (FlowOptions::tangential_relaxation). Such a crossing is mostly a few patch triangles sheared
  /// over where the border has a notch; relaxed, they stay well shaped while the surface they
  /// carry is the same (docs/real-holes.md, "A crossing flow, relaxed"). 0: no second try.
  double crossing_retry_relaxation = 0.5;
  /// Where a fill started from the membrane folds back against the surface (folds_back), or its
  /// flow folded back and gave way to the linear floor (HoleReport::flow_folded_back), the same
  /// chain runs again from the refined triangulation: the membrane may have creased the patch
  /// against its border, and every fairing from there keeps the crease. That fill is delivered
  /// where it turns the normal across the border less than the fill that folds back, or, in place
  /// of the floor, where it is the flow's and does not fold back; the note gives the angles
  /// (docs/real-holes.md, "A fill that folds back"). Needs patch.relax. Where the fill still folds
  /// back, the group is triangulated again from the lightest of the triangulation's starts
  /// (patch.triangulation.start_margin 0) and filled from there (both chains); that fill is
  /// delivered where it turns the normal by at most half as much (docs/real-holes.md, "Triangulated
  /// again"). Where it still folds back, once more within the faces of each loop's Delaunay
  /// tetrahedralization (patch.triangulation.delaunay_restricted), under the same rule
  /// (docs/real-holes.md, "Triangulated within the Delaunay faces"). With fallback_on_failure, a group
  /// whose fill failed is also filled once more from those faces.
  bool refill_folded_back = true;
  /// With fallback_on_failure: where a group fails, or every fairing of it crosses the mesh and its
  /// refined triangulation would be delivered unfaired, and flows delivered for earlier groups
  /// reach into the room its patch may take (a dome over the opening of a severed part, facing the
  /// other part's openings), those earlier holes are given the linear ∆^k solution their flow
  /// started from (FairRegionReport::floor_positions), where that does not cross the mesh, and the
  /// group is filled again. That fill is kept where it is faired (after a failure: where it fills
  /// the group without folding back); the notes of both say so (docs/real-holes.md, "An earlier flow
  /// given its floor").
  bool floor_earlier_flows = true;
};

enum class HoleStatus { filled, skipped, failed };
/// "filled", "skipped", "failed".
const char* to_string(HoleStatus status);

/// What happened to one boundary loop of the input.
struct HoleReport {
  int index = 0;         ///< the loop's index in boundary_loops order
  int border_edges = 0;  ///< edges of the loop
  HoleStatus status = HoleStatus::skipped;
  std::string reason;    ///< why it was skipped or failed; empty when filled
  std::vector<int> filled_with;  ///< other holes filled jointly with it (overlapping rings)
  int vertices_added = 0;        ///< this hole's new vertices
  int faces_added = 0;           ///< this hole's new faces
  /// Where relinking at a pinch of the border made one loop of this hole and another (two loops
  /// that meet at a vertex, as a figure eight), the hole whose report counts their one patch: this
  /// report then has no vertex or face added and repeats that hole's labels, fairing figures and
  /// border measure (which covers both loops). A loop around a piece the patch takes in (a lone
  /// triangle, a piece hanging at a vertex) never counts a patch another loop shares. −1 otherwise.
  int patch_shared_with = -1;
  /// Where the hole failed at a pinch of its border (`reason` "non-manifold border: ..."), the loop
  /// it shares that vertex with, which is not filled (its own report says why: not selected,
  /// skipped, or failed at a pinch of its own, a chain that open_at_lone_triangle follows); −1
  /// otherwise.
  int pinched_by = -1;
  /// The loop runs around a face of the mesh, a lone triangle with every edge on the border: filled
  /// with the hole at whose border the triangle hangs, in one patch that takes the triangle in;
  /// skipped elsewhere or where that fails, since its own fill could only be that face again
  /// (repair removes such debris).
  bool around_a_face = false;
  /// The loop is the whole border of a piece of more than one face with no vertex inside, joined
  /// to the rest of the mesh at this vertex of the loop (a piece hanging inside a hole, as a cut
  /// through a thin part leaves): only a patch of this loop and the hole's, relinked at the vertex,
  /// can take the piece in, and where none does, this hole's reason says what the loop is. −1
  /// otherwise.
  int hanging_piece_at = -1;
  /// A longer loop that also runs around a lone triangle: a face of the mesh whose three edges are
  /// all on this loop, hanging at a vertex the loop passes twice (debris a scan or a cut leaves
  /// inside a hole). The patch must wrap round it, which it often cannot clear of the mesh; where
  /// the hole fails, its reason says so and that repair removes the triangle
  /// (open_at_lone_triangle). The face's index; −1 otherwise.
  int lone_triangle = -1;
  Continuity requested = Continuity::G2;
  Continuity supported = Continuity::G2;  ///< the continuity the fairing used
  /// The patch is the linear ∆^k solution (k = supported + 1): C(k−1), not G(k−1) — the harmonic
  /// method, or the floor kept when the flow did not settle or its patch crossed the mesh. It is
  /// the re-evaluated solution from the membrane, except where the held-out rings prefer one solve
  /// from the patch before its membrane by more than twice (refined_start; no flow is then tried),
  /// and where the surface around the hole is rough (held_out_max_roughness; refined_start too).
  /// delivered_label(supported, linear) names it ("G2", "C2 (linear)"). A patch without interior
  /// vertex (a small loop's triangulation alone) or committed unfaired (fallback_on_failure's last
  /// resort) is reported C0 (linear), with a note.
  bool linear = false;
  /// FairRegionOptions::held_out_rings: mean normal distance of the held-out rings from the input after
  /// the flow and after the linear solution, in mean edge lengths (∞: that fairing failed; NaN: not
  /// measured, as for the flows where refined_start won before they were tried).
  double held_out_flow_error = std::numeric_limits<double>::quiet_NaN();
  double held_out_linear_error = std::numeric_limits<double>::quiet_NaN();
  /// FairRegionOptions::held_out_two_ring_fits: the same after the flow on 2-ring boundary fits.
  double held_out_two_ring_flow_error = std::numeric_limits<double>::quiet_NaN();
  /// FairRegionOptions::held_out_other_functions: the same after the flow with those functions, on
  /// 1-ring and 2-ring boundary fits (FairRegionReport's).
  double held_out_other_flow_error = std::numeric_limits<double>::quiet_NaN();
  double held_out_other_two_ring_flow_error = std::numeric_limits<double>::quiet_NaN();
  /// Of one ∆^k solve from the patch before its membrane (FairRegionReport's).
  double held_out_refined_linear_error = std::numeric_limits<double>::quiet_NaN();
  /// FairRegionOptions::held_out_max_roughness: the roughness around the hole it was weighed against
  /// (FairRegionReport's); NaN when not measured.
  double held_out_roughness = std::numeric_limits<double>::quiet_NaN();
  /// The delivered linear solution is that one (FairRegionReport::refined_start).
  bool refined_start = false;
  /// The patch is the refined triangulation delivered unfaired, continuous in position only (C0):
  /// every fairing of it failed or crossed the mesh, and this is the fallback chain's last resort.
  bool unfaired = false;
  /// The delivered flow read its boundary data from 2-ring fits (FlowOptions::two_ring_boundary_fits).
  bool two_ring_boundary_fits = false;
  /// The held-out rings chose the flow with FairRegionOptions::held_out_other_functions, and it ran
  /// with them (FairRegionReport::other_functions; the floor may still have been kept, as `linear`
  /// and the note say).
  bool other_functions = false;
  /// The linear solution was delivered over the flow by the held-out rings or the fold check, the
  /// checks keep_settled_flow switches off (FairRegionReport's).
  bool checks_chose_linear = false;
  /// The flow settled but folded back where its linear floor does not, and the floor was kept
  /// (FairRegionReport's); fill then tries the refined triangulation (refill_folded_back).
  bool flow_folded_back = false;
  /// Why `supported` is below `requested` (too few complete rings around the hole, or a failed
  /// attempt at a higher continuity — a throw, no steady state, a crossing: FillOptions::
  /// fallback_on_failure). Empty otherwise.
  std::string note;
  int steps = 0;                 ///< accepted flow steps (0 for the harmonic method)
  /// Cotangent ∆^k solves: the flow's start (FairRegionOptions::harmonic_start_iterations) or the
  /// harmonic method's one solve.
  int harmonic_solves = 0;
  double seconds = 0;            ///< wall time of patch, fairing and checks (of the joint region)
  /// max|V| on the free vertices at the end, in the flow's units (flow.h; |EL| for the sixth-order
  /// flow); NaN for the harmonic method or a patch without interior vertices.
  double final_max_velocity = 0;
  /// Where the sixth-order flow's f is not parabolic on its input (method.md §4; energy_function.h):
  /// of the flow that ran or was weighed (FairRegionReport::flow); zero when none reported it.
  WellPosedness well_posedness;
  /// Normal angle and mean-curvature jump across this hole's border, measured after fairing
  /// (border_vertices == 0 when the patch has no interior vertex).
  ContinuityMeasure continuity;
};

struct FillReport {
  std::vector<HoleReport> holes;  ///< one per boundary loop of the input, in loop order
  int filled = 0, skipped = 0, failed = 0;
  int input_vertices = 0, input_faces = 0;
  double seconds = 0;  ///< wall time of the whole call
};

/// The filled hole's patch folds back against the surface: it turns the normal across the hole's
/// border (continuity.max_normal_angle) by more than a right angle. No fill of a hole in a smooth
/// surface does (the uncut meshes of bench_real_holes read at most 29° across the same borders):
/// the loop is not a hole (the edge of a fin), or the hole cuts across a thin part (docs/fill.md).
bool folds_back(const HoleReport& hole);

/// The hole (one of report.holes) failed at a pinch of its border shared with a loop round a lone
/// triangle (HoleReport::pinched_by, around_a_face), directly or through holes that failed at
/// pinches the same way, or failed with a lone triangle on its own loop (HoleReport::lone_triangle):
/// debris that repair removes, after which the hole can be filled.
bool open_at_lone_triangle(const FillReport& report, const HoleReport& hole);

/// Called after every trial flow step with the holes being faired together (ascending indices).
using FillObserver = std::function<void(std::span<const int> holes, const StepRecord& record)>;

/// Fills the selected boundary loops of `mesh` in place (see the header).
/// Throws InvalidMeshError ("fill_holes: mesh has ...") if the mesh has non-finite coordinates,
/// malformed, degenerate or duplicate faces, non-manifold edges, inconsistent orientation, or
/// non-manifold vertices that are not pinches of the border; InvalidArgument for a hole index outside
/// the loops or a negative max_hole_edges. Everything else is reported per hole.
FillReport fill_holes(Mesh& mesh, const FillOptions& options = {}, const FillObserver& observer = {});

}  // namespace fairsurf
