// fairsurf — geometric flows of triangle meshes: the sixth-order flow of E = Σ_l ∫ ‖∇f_l‖² dA and
// three baselines, by semi-implicit normal steps with step control (method.md §4–§7).
//
// Every flow moves the free vertices along their fitted normals n (operators.h; outward on a closed
// counter-clockwise mesh, H = −1/R on a sphere) with a normal velocity V:
//   sixth_order        V = −EL = −Σ_l EL_l   (energy.h; descends E — the paper prints the ascent +EL),
//                      with part of its term c ∆f limited where the mesh does not resolve the
//                      curvature (FlowOptions::curvature_resolution)
//   mean_curvature     V = 2H                (a sphere shrinks)
//   surface_diffusion  V = −∆H
//   willmore           V = −(∆H + 2H(H² − K)) (descends ∫ H² dA; a cylinder inflates), its cubic
//                      term limited likewise
// The step (method.md §5). Freeze fits, stencils, n, f_H, f_K, c and w at x^k, linearize
// V^{k+1} ≈ V^k + J d and solve for the normal displacement d of the free vertices F:
//   (I − τ J_FF) d_F = τ V_F,  d = 0 on fixed vertices,  x^{k+1} = x^k + d ∘ n^k, with
//   sixth_order        J = Σ_l P′_l Q_l,  P′ = R L∆ − Σ_c diag(w_c) G_c,
//                      R = L∆ diag(f_H) + 2 L□ diag(f_K) + diag(c),  w = 2H∇f − 2◇f,
//                      Q = ½ diag(f_H) A_H + diag(f_K) A_K   (EL = −P′f; the first-order term w·∇f
//                      is semi-implicit, inside P′; the Newton factor of K is 1, not ½)
//   mean_curvature     J = A_H                (H^{k+1} = H^k + ½ A_H d exactly)
//   surface_diffusion  J = −½ L∆ A_H
//   willmore           J = −½ L∆ A_H          (the cubic term 2H(H² − K) is explicit)
// with A_H = L∆ ∘ (n_i·n_j), A_K = L□ ∘ (n_i·n_j) (operators.h normal_weighted). Fits and operators
// are re-evaluated every step at every vertex (fixed vertices of rings 1–2 see the free ones); only
// the free rows and columns are solved. J_FF's pattern (the 3-ring stencil for the sixth order, the
// 2-ring for surface diffusion and Willmore, the 1-ring for mean curvature) is built once per run
// and its values are computed in place every step, so the solver analyzes it once and refactors
// every step.
//
// Units (method.md §7). With FlowOptions::normalize (the default) the engine translates and scales the
// mesh to unit bounding-box diagonal, flows, and scales back: τ, end_time, tau_max and
// steady_tolerance are in those units. Time scales like length⁶ for the sixth-order flow, length⁴
// for surface diffusion and Willmore, length² for mean curvature flow: a unit sphere (diagonal 2√3)
// flowed for t in its own units corresponds to t / (2√3)⁶ = t / 1728 in unit-diagonal units for the
// sixth-order flow. |V| (= |EL| for the sixth-order flow) is in 1/length⁵ (f = H), 1/length
// (mean curvature), 1/length³ (surface diffusion, Willmore).
//
// Step control (method.md §5). A trial step is rejected if max_i |d_i| exceeds max_displacement_ratio
// times the mean length of the edges at vertex i, if the flow's energy more than doubles
// (E' > max_energy_growth·E + round-off floor), or if it produces a non-finite value, an inverted face
// (a face normal turned by more than 90° against its orientation at x^k) or a failed linear solve;
// then τ ← τ·reject_factor. After an accepted step τ ← min(accept_factor·τ, tau_max) (with the
// control disabled too: set tau_max = tau for a fixed step). On rough input d is not monotone in τ:
// small τ gives d ≈ τV with V huge, large τ a damped, Newton-like step −J⁻¹V, and τ ≈ 1/λ for the
// positive eigenvalues λ of J (lower-order terms) a near-singular system; so a rejected large step
// is not always cured by a smaller one.
// Rough input (raw scans, `fairsurf smooth`): optionally each |d_i| is clipped instead of rejected
// (limit_displacement), non-dissipative rows of J are damped (jacobian_dominance), the trial is
// relaxed tangentially (FlowOptions::tangential_relaxation, scaled with τ by the control: ×reject_
// factor after a rejection, ×accept_factor after an acceptance, up to the option's value) and the
// vertices of faces it would turn over — against x^k or against the input — are held back
// (hold_back_turned_faces). The face, energy and finiteness checks then apply to that trial.
// The energy the control watches is the flow's own: E = Σ_l ∫‖∇f_l‖² (sixth order), the area (mean
// curvature, surface diffusion) or ∫H² dA (Willmore), summed over the free vertices and their three
// fixed rings.
//
// Safety. run_flow only ever writes accepted states into the caller's V: when it throws, V holds the
// last accepted state (the input if none). It throws NumericalError ("run_flow: step N: ...") after
// more than max_consecutive_rejections rejections in a row; with step control disabled, on the first
// non-finite value, inverted face or failed solve; and, in either mode, when an accepted state's
// energy exceeds runaway_energy_factor times the initial energy.
#pragma once

#include <fairsurf/energy/energy_function.h>
#include <fairsurf/flow/flow_kind.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/solve/linear_solver.h>

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace fairsurf {

/// How a trial step is computed and judged (docs/flow.md).
///   implicit_flow   the semi-implicit time step of method.md §5 with the step control below: follows
///                   the flow in time (`fairsurf smooth`).
///   energy_descent  the sixth-order flow (the others step in time regardless): minimizes the discrete energy E directly (Levenberg–Marquardt
///                   on its Gauss–Newton model, energy_descent.h): (N + diag(A_F)/(2τ)) d_F = −g, a
///                   trial accepted only if E decreases and no face turns over, τ ← τ·reject_factor
///                   otherwise (no displacement bound: the energy test is the trust region). Small τ
///                   gives the flow's explicit step, large τ the Gauss–Newton step. E is monotone
///                   over accepted steps; the run is steady once E stops decreasing (FlowOptions::
///                   steady_energy_tolerance: an accepted step lowers E by less than that fraction,
///                   or two rejected trials in a row whose damping no longer changes the model's
///                   promise (within 1%) are promised less than it, or less than ten times it and
///                   less than E rose by on both: the model's own minimum is that close, or closer
///                   than the model resolves; or max_consecutive_rejections rejections in a row: no
///                   descent is left to
///                   round-off). For fill, fair and blend, which need the steady
///                   state only: on real meshes the fitted EL is not the gradient of the discrete E
///                   (method.md §3: composed operators are inconsistent on irregular meshes), so its
///                   Newton steps can raise E and its small steps stall above zero.
enum class FlowStepKind { implicit_flow, energy_descent };

struct FlowOptions {
  /// The flow to run. Unset: the sixth-order flow (run_flow, smooth), or in fair_region (and fill
  /// and blend, which call it) the flow that reaches the requested continuity (flow_for); there a
  /// kind that contradicts the continuity is refused rather than replaced.
  std::optional<FlowKind> kind;
  /// The flow run_flow runs: `kind`, or the sixth-order flow where it is unset.
  FlowKind kind_to_run() const { return kind.value_or(FlowKind::sixth_order); }
  /// The functions f_l of the sixth-order energy (energy_function.h names or formulas).
  std::vector<std::string> functions{"H"};
  /// Regularization ε = relative_epsilon · κ of singular functions (energy_function.h).
  double relative_epsilon = 1e-3;
  /// The flows' lower-order curvature term is weighed by w_i = min(1, curvature_resolution /
  /// (A_i κ_i²)), κ_i² = 2H_i² − K_i and A_i the vertex area: sixth order, energies of H alone
  /// (every f_l with f_K = 0: H, H², absHpH:p), EL's factor c = 2(2H² − K) f_H (energy.h) in the
  /// velocity and the Jacobian; Willmore, the cubic term 2H(H² − K). Where the radius of curvature
  /// falls below about an edge (A κ² above this), that term outweighs the leading one at the mesh's
  /// own scale and pushes a single raised vertex further out, a quarter edge a step (sixth order
  /// from 0.6 edges, Willmore from about 1.2), where the flow without it pulls it back (docs/flow.md,
  /// "Unresolved curvature"). Where the curvature is resolved w = 1, so the limiter vanishes as the
  /// mesh is refined. The energy E and the descent's gradient do not use it, nor do energies with a
  /// K part (limited, f = K diverged on a raw scan). Must be positive; ∞ turns the limiter off.
  double curvature_resolution = 0.5;
  /// κ in the flow's units; 0: curvature_scale() of the input (after normalization), kept fixed
  /// for the whole flow so that energies of different steps are comparable.
  double curvature_scale = 0;

  bool normalize = true;  ///< flow the mesh scaled to unit bounding-box diagonal (see the header)
  double tau = 1e-3;      ///< initial time step
  double tau_max = 1.0;   ///< largest time step the control may reach

  // Stopping: whichever comes first.
  int max_steps = 1000;  ///< accepted steps
  double end_time = std::numeric_limits<double>::infinity();  ///< the last step is shortened to hit it
  /// Steady state when max over free vertices of |V| (|EL| for the sixth-order flow) ≤ this; 0: off.
  double steady_tolerance = 0;
  /// Steady state also when max|V| ≤ this · max|V| of the input; 0: off. Scale-free, so it suits
  /// runs that start far from steady (a flattened hole patch starts ~1e8 above its round-off floor).
  double steady_relative_tolerance = 0;
  /// energy_descent: steady once an accepted step lowers E by less than this fraction of E, or the
  /// Gauss–Newton model's undamped step promises less than it and E still rises (the header); 0: off.
  double steady_energy_tolerance = 0;
  FlowStepKind step_kind = FlowStepKind::implicit_flow;

  // Step control (the header; docs/flow.md).
  /// Judge trial steps as the header says; false: the first rejected trial (a non-finite value, an
  /// inverted face, a failed solve) throws, and of the fields below only accept_factor applies.
  bool step_control = true;
  double max_displacement_ratio = 0.25;  ///< of the local mean edge length
  double max_energy_growth = 2.0;        ///< reject when E' > this · E (plus a round-off floor)
  double reject_factor = 0.25;           ///< τ ← τ · this after a rejection
  double accept_factor = 2.0;            ///< τ ← min(τ · this, tau_max) after an acceptance
  int max_consecutive_rejections = 12;   ///< one more rejection in a row throws NumericalError
  /// Clip each |d_i| to max_displacement_ratio times its local edge length (a per-vertex trust
  /// region) instead of rejecting the step; the other rejections still apply. For rough input.
  bool limit_displacement = false;
  /// Row damping of the step matrix: where J_ii > −jacobian_dominance · Σ_{j≠i} |J_ij| (a row that
  /// is not dissipative: anti-diffusive fitted stencils on irregular scans), the step uses that bound
  /// as the diagonal, i.e. solves (I − τ(J − diag(s))) d = τV with s ≥ 0. Steady states are
  /// unchanged (d = 0 iff V = 0); rows of regular and smooth meshes (ratio ≈ −0.38) are untouched.
  /// Only with step_control; −∞ (the default) disables it, NaN is invalid. `fairsurf smooth`
  /// uses 0.3 for rough scans; it is off elsewhere because it slows convergence to steady states
  /// (a G2 hole fill on a 2562-vertex sphere stalled at 200 steps with it, 145 steps without).
  double jacobian_dominance = -std::numeric_limits<double>::infinity();
  /// Hold back the vertices of faces that a trial would turn over, against their orientation at
  /// x^k or at the input (orientation_guard.h: their moves are halved until no face is turned, at
  /// most 8 times, then undone), instead of rejecting the step; the rest of the mesh moves as
  /// solved. Keeps needle triangles of raw scans from flipping or accumulating turns over steps.
  /// Only with step_control; `fairsurf smooth` turns it on.
  bool hold_back_turned_faces = false;
  /// Reject a trial whose moving faces (those with a free vertex) cross a face of the mesh
  /// (find_face_intersections), as an inverted face is rejected, so that τ shrinks and the flow
  /// stops short of the contact instead of passing through it: a time-stepped flow creeps towards
  /// it in ever smaller steps (and ends at max_steps), the energy descent ends steady there, once
  /// its steps lower E by less than steady_energy_tolerance. Off for a run whose start already
  /// crosses. Only with step_control; costs one crossing search per trial. The energy descent of
  /// blend's tubes turns it on, where a thin part's two sheets meet (docs/blend.md).
  bool reject_crossings = false;
  /// Tangential relaxation of every trial state (tangential_relaxation.h): after the normal step,
  /// each free vertex moves this fraction of the way towards its neighbours' mean within its
  /// tangent plane at x^k; the trial is then checked (faces, energy, finiteness) as a whole. Keeps
  /// needle triangles of raw scans from shearing over; changes the shape only to second order and
  /// steady shapes not at all, but vertex positions of steady states are then those of a relaxed
  /// distribution. 0 (the default): off; `fairsurf smooth` uses 0.5 (docs/flow.md).
  double tangential_relaxation = 0;
  /// An accepted state with energy above this times the initial energy stops the flow.
  double runaway_energy_factor = 1e6;

  /// Frozen Jacobian (method.md §5): one assembly and factorization of I − τJ serves up to this many
  /// accepted steps while τ is unchanged (at tau_max, or with a fixed τ); every step still solves
  /// with the current velocity V, so steady states are those of the exact step. 1: J is assembled
  /// and factorized at every step.
  int refactor_interval = 1;
  LinearSolverOptions solver;
  FitOptions fit;
  /// Fit the fixed vertices over their 2-ring (method.md §3) instead of their 1-ring; free vertices
  /// keep theirs. The boundary data the fixed rings give (tangent planes, curvatures) is then read
  /// at twice the mesh's scale, which averages out noise of the surrounding surface at the scale of
  /// one edge: on bench_real_holes' noisy holes the sixth-order fill comes closer to the surface
  /// with it, on clean real holes it does not (docs/real-holes.md, "Boundary data over two rings").
  bool two_ring_boundary_fits = false;
  /// Asked before every trial step (when set): true ends the run with FlowStopReason::interrupted,
  /// V at the last accepted state. Lets a caller stop from the observer (observers cannot return a
  /// verdict), e.g. the Python bindings' progress callback; fill, fair and blend pass it on with the
  /// rest of the flow options.
  std::function<bool()> interrupted;
};

/// Why a trial step was rejected (none for accepted steps).
enum class StepRejection { none, displacement, energy, non_finite, inverted_face, solver, crossing };
const char* to_string(StepRejection reason);

/// One trial step. Energies and velocities are those of the trial state, in the flow's units.
struct StepRecord {
  int step = 0;          ///< 1-based number of the accepted step being attempted
  int attempt = 0;       ///< 1-based count of trial steps so far (accepted and rejected)
  double time = 0;       ///< flow time after the step if accepted, before it if rejected
  double tau = 0;        ///< time step tried
  double energy = 0;     ///< the flow's energy at the trial state (NaN if not evaluated)
  /// energy_descent: how much the Gauss–Newton model says this trial lowers E (E − model(d) =
  /// −(2gᵀd + dᵀNd), energy_descent.h); NaN for the time-stepped flow or an unsolved trial.
  double predicted_decrease = std::numeric_limits<double>::quiet_NaN();
  double max_displacement = 0;  ///< max_i |d_i|
  double max_velocity = 0;      ///< max over free vertices of |V| at the trial state (|EL|)
  /// Free vertices held back because a face of theirs would have turned over
  /// (FlowOptions::hold_back_turned_faces).
  int held_back_vertices = 0;
  /// Free vertices whose step was clipped to the per-vertex trust region
  /// (FlowOptions::limit_displacement): where the solved step asked for more than
  /// max_displacement_ratio of the local edge length.
  int clipped_vertices = 0;
  bool accepted = false;
  StepRejection rejection = StepRejection::none;
  std::string detail;           ///< what was rejected, e.g. "|d| 0.031 > 0.25 · 0.1 at vertex 17"
  bool refactorized = false;    ///< J assembled and factorized for this step (not reused)
  int solver_iterations = 0;    ///< GMRES iterations (0 for direct solvers)
  double backward_error = 0;    ///< of the linear solve
  // Wall-clock seconds of the step's phases.
  double fit_seconds = 0;       ///< refit + operators + energy at the trial state
  double assembly_seconds = 0;  ///< J and the step matrix
  double factorize_seconds = 0; ///< including the one-off analysis on the first step
  double solve_seconds = 0;
};

/// steady: max|V| under its tolerance, or (energy_descent) E stopped decreasing; interrupted:
/// FlowOptions::interrupted returned true.
enum class FlowStopReason { max_steps, end_time, steady, interrupted };
const char* to_string(FlowStopReason reason);

struct FlowReport {
  std::vector<StepRecord> records;
  FlowStopReason stop_reason = FlowStopReason::max_steps;
  FlowStepKind step_kind = FlowStepKind::implicit_flow;  ///< FlowOptions::step_kind of the run
  int accepted_steps = 0;
  int rejected_steps = 0;
  double time = 0;                 ///< flow time reached, in the flow's units
  double tau = 0;                  ///< the time step the control would try next
  double initial_energy = 0, final_energy = 0;
  double initial_max_velocity = 0, final_max_velocity = 0;
  /// Length of the mesh in the flow's units: 1/diagonal when normalized, else 1.
  double length_scale = 1;
  double curvature_scale = 1;      ///< κ used for ε, in the flow's units
  /// Sixth order: where the chosen functions are not parabolic on the input (method.md §4). The flow
  /// still runs; callers should warn when violating_vertices > 0.
  WellPosedness well_posedness;
  int free_vertices = 0;
  Continuity supported = Continuity::G2;  ///< continuity the region's fixed rings support
};

/// Why a run that stopped without a steady state is not one: "did not settle (200 steps without a
/// steady state, max|V| 1.2e9 -> 3.3e7)", or "diverged (...)" when max|V| ended above its start. The
/// energy descent, whose E only falls and whose max|V| says nothing of it (it may rise), is told by
/// its energy: "did not settle (500 steps without a steady state, E 3.4e5 -> 8.6e4, the last step
/// lowering it by 5.9e-5 of itself)".
std::string unsettled_reason(const FlowReport& report);

using FlowObserver = std::function<void(const StepRecord&)>;

/// Flows the free vertices of `region` (built on F's topology) under `options`, calling `observer`
/// (if set) after each trial step. V (#V by 3) is replaced only by accepted states. Throws
/// InvalidArgument for invalid options or a region/mesh mismatch, InvalidMeshError for non-finite
/// input, NumericalError as the header says; when f is not parabolic on part of the input, that
/// error's message ends with "(f is not parabolic at N of M vertices of the flow's input, method.md §4)".
FlowReport run_flow(Vertices& V, const Faces& F, const Region& region, const FlowOptions& options = {},
                    const FlowObserver& observer = {});
/// The same on `topo`, the connectivity of F (build_topology), instead of building it again.
FlowReport run_flow(Vertices& V, const Faces& F, const Topology& topo, const Region& region,
                    const FlowOptions& options = {}, const FlowObserver& observer = {});

/// The same with every vertex free except the three rings along the mesh border that carry G2 data
/// (region.h interior_vertices; every vertex on a closed mesh). smooth() takes another ring count
/// (SmoothOptions::fixed_rings).
FlowReport run_flow(Vertices& V, const Faces& F, const FlowOptions& options = {},
                    const FlowObserver& observer = {});

}  // namespace fairsurf
