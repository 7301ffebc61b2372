#include "held_out.h"

#include "flow/flow_failure.h"

#include <fairsurf/energy/energy_function.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace fairsurf::fair_detail {
namespace {

// #V area-weighted vertex normals (unit; zero where undefined).
Vertices vertex_normals(const Vertices& V, const Faces& F) {
  Vertices normal = Vertices::Zero(V.rows(), 3);
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::RowVector3d area_normal = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) normal.row(F(f, k)) += area_normal;
  }
  for (int v = 0; v < V.rows(); ++v)
    if (const double length = normal.row(v).norm(); length > 0) normal.row(v) /= length;
  return normal;
}

// Mean length of the edges at each of `vertices`.
double mean_edge_length(const Vertices& V, const Topology& topo, const std::vector<int>& vertices) {
  double sum = 0;
  int count = 0;
  for (int v : vertices)
    for (int w : topo.vertex_vertices.row(v)) sum += (V.row(v) - V.row(w)).norm(), ++count;
  return count > 0 ? sum / count : 1.0;
}

// Mean |(x − x0)·n0| over `held_out` of `trial` (`input` faired).
double held_out_distance(const Mesh& trial, const Mesh& input, const std::vector<int>& held_out,
                         const Vertices& normal, double edge) {
  double sum = 0;
  for (int v : held_out) sum += std::abs((trial.V.row(v) - input.V.row(v)).dot(normal.row(v)));
  return sum / static_cast<double>(held_out.size()) / edge;
}

// A ∆^k solution of the enlarged region and how far it puts the held-out vertices. The flow trials
// start from the linear trial's instead of solving it again.
struct LinearTrial {
  Mesh solved;  ///< the trial's start with the free vertices at the ∆^k solution
  HarmonicReport report;
  double error = std::numeric_limits<double>::infinity();  ///< ∞ where the solve failed
  bool ok = false;
};

// Fairs the region `free` of `start` with `harmonic` (the linear method) and measures it against
// `input`. A solve that fails is no candidate (error ∞); a flow trial from the same start meets the
// same failure in its own start and says so.
// `topo`: the connectivity of `input`, shared by the trial (only positions change).
LinearTrial linear_trial(Mesh start, const Mesh& input, const Topology& topo, const std::vector<int>& free,
                         const std::vector<int>& held_out, const Vertices& normal, double edge,
                         const FairRegionOptions& harmonic) {
  LinearTrial trial{std::move(start), {}};
  try {
    trial.report = fair_valid_mesh(trial.solved, topo, free, harmonic, {}, false).harmonic;
    trial.ok = true;
    trial.error = held_out_distance(trial.solved, input, held_out, normal, edge);
  } catch (const Error&) {
  }
  return trial;
}

// Mean |(x − x0)·n0| over `held_out` after fairing the region `free` of a copy of `mesh` with
// `fairing` (the flow), from `start`'s solution where one is given.
// `topo`: the connectivity of `mesh`, shared by the trial copy (only positions change).
double flow_held_out_error(const Mesh& mesh, const Topology& topo, const std::vector<int>& free,
                           const std::vector<int>& held_out, const Vertices& normal, double edge,
                           const FairRegionOptions& fairing, const LinearTrial* start,
                           WellPosedness* well_posedness = nullptr) {
  Mesh trial = start ? start->solved : mesh;
  try {
    // As fair_region(trial, free, fairing) on a mesh held_out_errors validated, without rebuilding
    // the connectivity or measuring the continuity of a result that is discarded.
    const FairRegionReport report = start ? fair_valid_mesh_from(trial, topo, free, fairing, start->report)
                                          : fair_valid_mesh(trial, topo, free, fairing, {}, false);
    if (well_posedness) *well_posedness = report.flow.well_posedness;
    if (report.linear) return std::numeric_limits<double>::infinity();
  } catch (const Error& e) {
    if (const auto* failure = dynamic_cast<const flow_detail::FlowFailure*>(&e); failure && well_posedness)
      *well_posedness = failure->well_posedness;
    return std::numeric_limits<double>::infinity();
  }
  return held_out_distance(trial, mesh, held_out, normal, edge);
}

}  // namespace

void require_valid_held_out_options(const FairRegionOptions& options, const char* caller) {
  if (!(options.held_out_margin >= 1))
    throw InvalidArgument(std::string(caller) + ": held_out_margin must be at least 1, not " +
                          std::to_string(options.held_out_margin));
  if (!(options.held_out_max_roughness >= 0))
    throw InvalidArgument(std::string(caller) + ": held_out_max_roughness must be at least 0, not " +
                          std::to_string(options.held_out_max_roughness));
  if (options.held_out_other_functions.empty()) return;
  // Here, before any fairing: inside the held-out trials a bad name would read as a failed flow.
  try {
    parse_energy_functions(options.held_out_other_functions);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string(caller) + ": held_out_other_functions: " + e.what());
  }
}

HeldOutErrors held_out_errors(const Submesh& sub, const Topology& topo, int rings, const FairRegionOptions& fairing,
                              const Vertices* refined, bool weigh_flows, bool flows_from_refined) {
  const std::vector<int> free = k_ring(topo, sub.free_local, rings);
  std::vector<int> held_out;
  std::set_difference(free.begin(), free.end(), sub.free_local.begin(), sub.free_local.end(),
                      std::back_inserter(held_out));
  HeldOutErrors errors;
  if (held_out.empty()) return errors;
  const bool weigh_two_ring = weighs_two_ring_fits(fairing);
  try {  // once for every trial, each fairing a copy of this mesh: a mesh that fails fails them all
    require_valid(validate(sub.mesh, topo), Requirements{}, "fair_region");
  } catch (const Error&) {
    errors.flow = errors.linear = std::numeric_limits<double>::infinity();
    if (weigh_two_ring) errors.two_ring_flow = errors.flow;
    if (refined) errors.refined_linear = errors.flow;
    return errors;
  }
  const Vertices normal = vertex_normals(sub.mesh.V, sub.mesh.F);
  const double edge = mean_edge_length(sub.mesh.V, topo, held_out);
  FairRegionOptions flow = fairing;
  flow.held_out_rings = 0;
  // The trials are weighed by the held-out rings alone; the fold check is the delivered flow's.
  flow.max_border_angle_ratio = std::numeric_limits<double>::infinity();
  FairRegionOptions harmonic = flow;
  harmonic.method = FairMethod::harmonic;
  // A trial at its step budget keeps its state (no floor) and is weighed as it stands.
  flow.flow.max_steps = std::min(flow.flow.max_steps, kHeldOutTrialSteps);
  flow.linear_floor = false;
  const LinearTrial linear = linear_trial(sub.mesh, sub.mesh, topo, free, held_out, normal, edge, harmonic);
  errors.linear = linear.error;
  LinearTrial refined_linear;
  if (refined) {
    FairRegionOptions once = harmonic;
    once.harmonic_start_iterations = 1;
    Mesh from;
    from.V = *refined;
    from.F = sub.mesh.F;
    refined_linear = linear_trial(std::move(from), sub.mesh, topo, free, held_out, normal, edge, once);
    errors.refined_linear = refined_linear.error;
  }
  // Where the refined solve wins, the flows would start from the solution it beats (unless they
  // start from the refined solve itself).
  if ((errors.refined_start_wins() && !flows_from_refined) || !weigh_flows) {
    errors.flow = std::numeric_limits<double>::quiet_NaN();
    if (weigh_two_ring) errors.two_ring_flow = errors.flow;
    return errors;
  }
  // The flow trials start from it, or from the refined solve, as the delivered flow does (without a
  // harmonic start, from the input).
  const LinearTrial& from = flows_from_refined && refined_linear.ok ? refined_linear : linear;
  const LinearTrial* start = from.ok && flow.harmonic_start_iterations > 0 ? &from : nullptr;
  // One flow's trials: on its 1-ring boundary fits and, where weighed, on 2-ring fits.
  const auto weigh_flow = [&](FairRegionOptions trial, double& one_ring, double& two_ring,
                              WellPosedness* well_posedness) {
    one_ring = flow_held_out_error(sub.mesh, topo, free, held_out, normal, edge, trial, start, well_posedness);
    if (!weigh_two_ring) return;
    trial.flow.two_ring_boundary_fits = true;
    two_ring = flow_held_out_error(sub.mesh, topo, free, held_out, normal, edge, trial, start);
  };
  weigh_flow(flow, errors.flow, errors.two_ring_flow, &errors.flow_well_posedness);
  if (!fairing.held_out_other_functions.empty()) {
    FairRegionOptions other = flow;
    other.flow.functions = fairing.held_out_other_functions;
    weigh_flow(other, errors.other_flow, errors.other_two_ring_flow, nullptr);
  }
  return errors;
}

}  // namespace fairsurf::fair_detail
