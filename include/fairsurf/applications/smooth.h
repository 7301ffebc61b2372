// fairsurf — smoothing and denoising (method.md §7): a geometric flow run for a short time on every
// vertex except the fixed rings along the mesh border.
//
// Time is in units of the mesh scaled to unit bounding-box diagonal (flow.h). A feature of size L
// decays under a flow of order 2m roughly like exp(−(2π/L)^{2m} t). The default time
// t = (2h̄)^{2m} / π^{2m−2}, h̄ the mean edge length in those units, damps a feature 4h̄ wide by the
// same factor e^{−π²} under every flow, whatever the resolution of the mesh, as mean curvature flow
// does at (2h̄)². Noise two edges wide goes (exponent 4^m π²: 39, 158, 632 for orders 2, 4, 6); the
// higher the order, the less longer features are touched: of a feature ten edges wide mean
// curvature flow keeps 21%, the fourth-order flows 78%, the sixth-order flow 96%. The earlier
// default (2h̄)^{2m} ran the sixth-order flow 97 times longer: on noisy copies of clean meshes it
// ended farther from the clean surface than the noise itself (docs/flow.md, "The default time").
#pragma once

#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/mesh.h>

#include <vector>

namespace fairsurf {

struct SmoothOptions {
  /// The flow and its stopping rule: max_steps, end_time, steady_tolerance (flow.h).
  FlowOptions flow;
  /// When flow.end_time is infinite and no steady tolerance is set, run for
  /// default_smoothing_time(). Set it to false to stop by flow.max_steps alone.
  bool default_time = true;
  /// Rings of vertices held fixed along the mesh border (1 = the border vertices themselves). Three
  /// carry G2 data for the sixth-order flow; 0 lets the border move with one-sided fits.
  int fixed_rings = 3;
  /// Further vertices held fixed (0-based, the input's order).
  std::vector<int> fixed_vertices;
};

/// (2h̄)^order / π^(order − 2) in unit-diagonal units, h̄ = mean edge length / bounding-box
/// diagonal. Throws InvalidMeshError for a mesh without faces, with malformed faces, NaN
/// coordinates or no extent.
double default_smoothing_time(const Mesh& mesh, FlowKind kind);

/// What `fairsurf smooth` runs with by default on `mesh`, for raw scans as well as clean meshes:
/// the flow `kind` to default_smoothing_time(), τ starting at 1/64 of it (the control doubles it
/// after each accepted step), per-vertex displacement clipping, row damping 0.3 and tangential
/// relaxation 0.5 (flow.h; docs/flow.md says what each does on the scans of data/).
SmoothOptions scan_smoothing_options(const Mesh& mesh, FlowKind kind = FlowKind::sixth_order);

/// Makes `flow` run to a steady state: max|V| ≤ velocity_tolerance or, for the sixth-order flow, the
/// energy descent (FlowStepKind::energy_descent) until an accepted step lowers E by less than 1e-7
/// of itself or no step lowers it at all (30 rejections in a row). The energy then never rises
/// between accepted steps; the time-stepped flow at large τ did not settle (its steps could raise E
/// and τ grew without bound) — docs/flow.md. No end time.
void steady_smoothing(FlowOptions& flow, double velocity_tolerance);

/// How a smoothing run ends, as `fairsurf smooth` and Python's `smooth` take it: after `steps`
/// accepted steps, at a steady state (steady_smoothing with `steady_tolerance`), or at `time`; at
/// most one of the three; none keeps the options' own end (scan_smoothing_options: the default time).
struct SmoothingEnd {
  int steps = 0;             ///< > 0: this many accepted steps
  bool steady = false;       ///< run to a steady state
  double steady_tolerance = 1.0;
  double time = 0;           ///< > 0: this end time, unit-diagonal units
  double tau = 0;            ///< > 0: the first τ, overriding the policy below
};

/// Sets `options`' end as `end` says, and τ by the one policy of the library: a timed run starts at
/// 1/64 of its time (at most tau_max), which the control reaches in about seven accepted steps; runs
/// without an end time start at FlowOptions{}.tau. Throws InvalidArgument when more than one end is
/// given.
void set_smoothing_end(SmoothOptions& options, const SmoothingEnd& end);

/// Smooths `mesh.V` in place. Requires a manifold, consistently oriented mesh without degenerate
/// faces (InvalidMeshError naming the problem otherwise); throws InvalidArgument if no vertex is
/// left free, and NumericalError as run_flow does — with mesh.V at the last accepted state.
FlowReport smooth(Mesh& mesh, const SmoothOptions& options = {}, const FlowObserver& observer = {});

}  // namespace fairsurf
