#include <fairsurf/applications/smooth.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include "mesh/validated.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fairsurf {

namespace {

// default_smoothing_time on `topo`, the connectivity of the validated mesh.
double smoothing_time(const Mesh& mesh, const Topology& topo, FlowKind kind) {
  const double diagonal = (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).norm();
  if (topo.edges.rows() == 0 || !(diagonal > 0))
    throw InvalidMeshError("default_smoothing_time: the mesh has no extent");
  const double h = mean_edge_length(mesh.V, topo) / diagonal;
  // (2h)^order / π^(order − 2): every flow damps a feature 4h wide by e^{−π²}, as mean curvature
  // flow does at (2h)² (smooth.h).
  const int order = flow_order(kind);
  return std::pow(2 * h, order) / std::pow(std::numbers::pi, order - 2);
}

// A timed run's first τ: 1/64 of its time, which the control (τ doubling) reaches in about seven
// accepted steps.
double first_timed_tau(const FlowOptions& flow) { return std::min(flow.end_time / 64, flow.tau_max); }

}  // namespace

double default_smoothing_time(const Mesh& mesh, FlowKind kind) {
  // Only what this function reads: faces, well-formed and with finite corners (an empty mesh has
  // no bounding box to take). Validation builds the connectivity: it is kept, not built again.
  const Topology topo =
      detail::validated_topology(mesh, Requirements{false, false, false, false}, "default_smoothing_time");
  return smoothing_time(mesh, topo, kind);
}

SmoothOptions scan_smoothing_options(const Mesh& mesh, FlowKind kind) {
  SmoothOptions o;
  o.flow.kind = kind;
  o.flow.end_time = default_smoothing_time(mesh, kind);
  o.flow.tau = first_timed_tau(o.flow);
  // Raw scans ask for steps of about an edge length at their noise spikes whatever τ is (flow.h):
  // clip those rather than reject every step, and damp the rows that are not dissipative. Needle
  // triangles shear over under the normal motion: relax the vertices tangentially, and hold back the
  // few whose faces would still turn over (against x^k or the input) rather than reject the step.
  o.flow.limit_displacement = true;
  o.flow.jacobian_dominance = 0.3;
  o.flow.hold_back_turned_faces = true;
  o.flow.tangential_relaxation = 0.5;
  return o;
}

void steady_smoothing(FlowOptions& flow, double velocity_tolerance) {
  flow.end_time = std::numeric_limits<double>::infinity();
  flow.steady_tolerance = velocity_tolerance;
  if (flow.kind_to_run() != FlowKind::sixth_order) return;
  flow.step_kind = FlowStepKind::energy_descent;
  flow.steady_energy_tolerance = 1e-7;
  flow.max_consecutive_rejections = 30;
}

void set_smoothing_end(SmoothOptions& options, const SmoothingEnd& end) {
  if (int(end.steps > 0) + int(end.steady) + int(end.time > 0) > 1)
    throw InvalidArgument("set_smoothing_end: give at most one of steps, steady and time");
  FlowOptions& flow = options.flow;
  if (end.steps > 0 || end.steady) {
    flow.end_time = std::numeric_limits<double>::infinity();
    flow.tau = FlowOptions{}.tau;
    options.default_time = false;
  }
  if (end.steps > 0) {
    flow.max_steps = end.steps;
  } else if (end.steady) {
    steady_smoothing(flow, end.steady_tolerance);
  } else if (end.time > 0) {
    flow.end_time = end.time;
    flow.tau = first_timed_tau(flow);
  }
  if (end.tau > 0) flow.tau = end.tau;
}

FlowReport smooth(Mesh& mesh, const SmoothOptions& options, const FlowObserver& observer) {
  // Built once, by the validation, and read by the region, the default time and the flow.
  const Topology topo = detail::validated_topology(mesh, Requirements{}, "smooth");
  std::vector<char> held(mesh.num_vertices(), 0);
  for (int v : options.fixed_vertices) {
    if (v < 0 || v >= mesh.num_vertices())
      throw InvalidArgument("smooth: fixed vertex " + std::to_string(v) + " is outside [0, " +
                            std::to_string(mesh.num_vertices()) + ")");
    held[v] = 1;
  }
  std::vector<int> free;
  for (int v : interior_vertices(topo, options.fixed_rings))
    if (!held[v]) free.push_back(v);
  if (free.empty())
    throw InvalidArgument("smooth: no vertex is left free (" + std::to_string(options.fixed_rings) +
                          " fixed rings along the border, " +
                          std::to_string(options.fixed_vertices.size()) + " fixed vertices)");

  FlowOptions flow = options.flow;
  if (options.default_time && !std::isfinite(flow.end_time) && flow.steady_tolerance <= 0 &&
      flow.steady_relative_tolerance <= 0)
    flow.end_time = smoothing_time(mesh, topo, flow.kind_to_run());
  const Region region = make_region(topo, free, Continuity::G2);
  return run_flow(mesh.V, mesh.F, topo, region, flow, observer);
}

}  // namespace fairsurf
