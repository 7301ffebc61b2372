#include "border_fold.h"
#include "fair_region_parts.h"
#include "flow/flow_failure.h"
#include "held_out.h"
#include "mesh/crossing_count.h"
#include "mesh/validated.h"
#include "stopwatch.h"

#include <fairsurf/applications/fair_region.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/mesh_quality.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/mesh/submesh.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>

namespace fairsurf {

const char* to_string(FairMethod method) { return method == FairMethod::flow ? "flow" : "harmonic"; }

FairMethod parse_fair_method(const std::string& name) {
  if (name == "flow") return FairMethod::flow;
  if (name == "harmonic") return FairMethod::harmonic;
  throw InvalidArgument("parse_fair_method: '" + name + "' is not a method (expected flow or harmonic)");
}

FlowKind flow_for(Continuity c) {
  switch (c) {
    case Continuity::G0: return FlowKind::mean_curvature;
    case Continuity::G1: return FlowKind::willmore;
    case Continuity::G2: return FlowKind::sixth_order;
  }
  return FlowKind::sixth_order;
}

FlowOptions FairRegionOptions::default_fair_flow_options() {
  FlowOptions o;
  o.tau = 1e-9;              // unit-diagonal units; the step control doubles it every acceptance
  o.max_steps = 200;
  // Patches start far from steady (a flattened cap: max|V| ~1e8 above the round-off floor) and
  // their geometry has converged once max|V| has fallen by ~1e-9 (method.md §8.6 cap: max|r−1| within
  // 2% of its final value).
  o.steady_relative_tolerance = 1e-9;
  return o;
}

FairRegionOptions FairRegionOptions::harmonic_started() {
  FairRegionOptions o;
  // One solve with the region's own cotangent operator: on a real surface that is the classical
  // C2 fairing (CGAL's fair), and re-evaluating it drifts from the surface (docs/blend.md,
  // "Region fairing"). Fill re-evaluates: its patch starts as a membrane (FillOptions).
  o.harmonic_start_iterations = 1;
  o.flow.tau = 1e-2;
  o.harmonic_solver.ordering = o.flow.solver.ordering = FillOrdering::minimum_degree;
  o.flow.step_kind = FlowStepKind::energy_descent;
  o.flow.steady_energy_tolerance = 1e-5;
  o.flow.max_consecutive_rejections = 30;
  // The descent crawls on some real regions, its Gauss-Newton model misjudging E (steps of 1e-6 at
  // τ ≈ 1e-15, each lowering E by about 6e-5 of itself): blub 813 8h settles at step 212, spot 317
  // 8h with noise at 217 (docs/fill.md). A run that settles sooner is not touched.
  o.flow.max_steps = 500;
  o.linear_floor = true;
  o.held_out_rings = 2;
  o.held_out_two_ring_fits = true;
  o.max_border_angle_ratio = 1.5;
  o.retry_other_boundary_fits = true;
  // Within 1.5% the held-out rings do not tell a region's two fairings apart: on 31 regions of
  // bench_real_holes where they preferred ∆³ by less, the flow lands at 0.98 of its distance
  // (docs/real-holes.md, "Ties go to the flow, for regions too"). Fill's margin, 1.05, costs regions
  // distance.
  o.held_out_margin = 1.015;
  return o;
}

void keep_settled_flow(FairRegionOptions& options) {
  options.held_out_may_choose_linear = false;
  options.max_border_angle_ratio = std::numeric_limits<double>::infinity();
}

namespace {

// The region's border vertices (fixed, with a free neighbour), one group per component of the
// border along the mesh's edges: one per loop of a group of holes, so that a fold at one window of
// a row is not averaged away over the row's other windows.
std::vector<std::vector<int>> border_components(const Topology& local, std::span<const int> free_vertices) {
  std::vector<char> is_free(local.num_vertices, 0), on_border(local.num_vertices, 0);
  for (int v : free_vertices) is_free[v] = 1;
  for (int v : free_vertices)
    for (int w : local.vertex_vertices.row(v)) on_border[w] = !is_free[w];
  std::vector<std::vector<int>> components;
  for (int seed = 0; seed < local.num_vertices; ++seed) {
    if (!on_border[seed]) continue;
    std::vector<int>& component = components.emplace_back(1, seed);
    on_border[seed] = 0;
    for (std::size_t k = 0; k < component.size(); ++k)
      for (int w : local.vertex_vertices.row(component[k]))
        if (on_border[w]) on_border[w] = 0, component.push_back(w);
  }
  return components;
}

// Empty, or why the flow's steady state folds against the ∆^k solution `start` it started from:
// its largest normal angle across the region's border exceeds both
// FairRegionOptions::max_border_angle_ratio times the linear solution's and kSmallestFoldAngle
// (`by_ratio` says so), or it folds back (more than a right angle) where the linear solution does
// not (FairRegionOptions::refuse_folding_back; `back` says so). Around a `rough` region, where the
// largest angle is one border vertex's reading of the noise, the ratio must be exceeded on average
// too, along one component of the border (border_folds_against, border_fold.h).
std::string border_fold_reason(const Submesh& sub, const Topology& local, const Vertices& start,
                               const FairRegionOptions& options, bool rough, bool& by_ratio, bool& back) {
  by_ratio = back = false;
  if (std::isinf(options.max_border_angle_ratio) && !options.refuse_folding_back) return "";
  // An empty list measures at every border vertex.
  const std::vector<std::vector<int>> parts =
      rough ? border_components(local, sub.free_local) : std::vector<std::vector<int>>(1);
  ContinuityMeasure flowed, linear;  // of the first part that folds, for the note
  for (const std::vector<int>& part : parts) {
    const ContinuityMeasure f = measure_continuity(sub.mesh.V, sub.mesh.F, local, sub.free_local, part);
    const ContinuityMeasure l = measure_continuity(start, sub.mesh.F, local, sub.free_local, part);
    const bool folds = rough ? detail::border_folds_against(f, l, options.max_border_angle_ratio)
                             : detail::folds_against(f.max_normal_angle, l.max_normal_angle,
                                                     options.max_border_angle_ratio);
    const bool folds_back = options.refuse_folding_back && detail::turns_back(f.max_normal_angle) &&
                            !detail::turns_back(l.max_normal_angle);
    if ((folds || folds_back) && !by_ratio && !back) flowed = f, linear = l;
    by_ratio = by_ratio || folds;
    back = back || folds_back;
  }
  if (!by_ratio && !back) return "";
  constexpr double kDegrees = 180 / std::numbers::pi;
  char text[240];
  std::snprintf(text, sizeof text,
                "settled, but turns the normal across the border by %.1f deg (%.1f on average) where the linear "
                "solution it started from turns it by %.1f deg (%.1f)",
                flowed.max_normal_angle * kDegrees, flowed.mean_normal_angle * kDegrees,
                linear.max_normal_angle * kDegrees, linear.mean_normal_angle * kDegrees);
  return text;
}

// Runs the flow on the submesh. With the linear floor (and a ∆^k start), a flow that throws or does
// not settle leaves the ∆^k solution in place, reported linear; without it, a throw leaves the last
// accepted state in the caller's mesh and propagates. Returns why the floor was kept ("settled, but
// turns ...", "did not settle ..."), empty where the flow is delivered.
std::string run_flow_with_floor(Submesh& sub, const Topology& local, const Region& region, const FairRegionOptions& options,
                         const FlowObserver& observer, FairRegionReport& report, Vertices& caller) {
  FlowOptions flow = options.flow;
  flow.kind = report.flow_kind = flow_for(region.supported);
  const bool floor = options.linear_floor && options.harmonic_start_iterations > 0;
  const Vertices start = floor ? sub.mesh.V : Vertices();
  std::string failure;
  bool folded = false, folded_back = false;
  try {
    report.flow = run_flow(sub.mesh.V, sub.mesh.F, local, region, flow, observer);
    if (report.flow.stop_reason != FlowStopReason::steady) failure = unsettled_reason(report.flow);
    else if (floor) {
      const bool rough = report.held_out_roughness > options.held_out_max_roughness;  // NaN: not measured
      failure = border_fold_reason(sub, local, start, options, rough, folded, folded_back);
    }
  } catch (const NumericalError& e) {
    if (const auto* failure = dynamic_cast<const flow_detail::FlowFailure*>(&e))
      report.flow.well_posedness = failure->well_posedness;  // what the lost report held
    if (!floor) {
      write_back_free(sub, caller);  // the last accepted state: nothing is lost
      throw;
    }
    failure = std::string("failed (") + e.what() + ")";
  }
  if (!floor) return "";
  if (failure.empty()) {
    report.floor_positions.resize(static_cast<Eigen::Index>(sub.free_local.size()), 3);
    for (std::size_t k = 0; k < sub.free_local.size(); ++k)
      report.floor_positions.row(static_cast<Eigen::Index>(k)) = start.row(sub.free_local[k]);
    return "";
  }
  sub.mesh.V = start;
  report.linear = true;
  report.checks_chose_linear = folded;
  report.flow_folded_back = folded_back;
  // What the held-out rings said (rough surroundings, 2-ring fits) stays in front of why the floor
  // was kept.
  const std::string chosen = report.note.empty() ? "" : report.note + "; ";
  report.note = chosen + "the " + to_string(report.flow_kind) + " flow " + failure + "; kept the linear ∆" +
                std::to_string(static_cast<int>(region.supported) + 1) + " solution it started from";
  return failure;
}

// roughness() of the surface around the region: over the vertices 3 and 4 rings out, whose 2-rings
// hold no free vertex (the submesh keeps FairRegionOptions::submesh_rings = 6 rings).
double surroundings_roughness(const Submesh& sub, const Topology& local) {
  constexpr int kFirstRing = 3, kLastRing = 4;
  const std::vector<int> distance = ring_distances(local, sub.free_local, kLastRing);
  std::vector<int> surroundings;
  for (int v = 0; v < static_cast<int>(distance.size()); ++v)
    if (distance[v] >= kFirstRing) surroundings.push_back(v);
  return roughness(sub.mesh.V, sub.mesh.F, local, surroundings);
}

// The fairing the held-out rings choose (FairRegionOptions::held_out_rings).
enum class HeldOutChoice { flow, two_ring_flow, linear, refined_linear };

// What choose_by_held_out decided: the fairing, and, for a flow, whether it starts from (and falls
// back to) fill's solve from before the membrane instead of the re-evaluated linear solution.
struct HeldOutVerdict {
  HeldOutChoice choice = HeldOutChoice::flow;
  bool flow_from_refined = false;
  bool other_functions = false;  // the flow runs with FairRegionOptions::held_out_other_functions
};

// "{H, K/kappa}": energy functions as the notes name them.
std::string function_list(const std::vector<std::string>& functions) {
  std::string text;
  for (const std::string& f : functions) text += (text.empty() ? "" : ", ") + f;
  return "{" + text + "}";
}

// The parts of a note that are not empty, in order, joined by "; ".
std::string joined(const std::string& first, const std::string& second) {
  return first.empty() ? second : second.empty() ? first : first + "; " + second;
}

// The better of a flow's held-out errors on 1-ring and on 2-ring boundary fits (NaN: not weighed).
double better_fits(double one_ring, double two_ring) {
  return std::isnan(two_ring) ? one_ring : std::min(one_ring, two_ring);
}

// Whether the flow with FairRegionOptions::held_out_other_functions re-predicts the held-out rings
// better than the flow with its own functions, each on its better boundary fits (false where the
// other was not weighed); `note` then says so.
bool other_functions_win(const fair_detail::HeldOutErrors& errors, const FairRegionOptions& options,
                         std::string& note) {
  const double own = better_fits(errors.flow, errors.two_ring_flow);
  const double other = better_fits(errors.other_flow, errors.other_two_ring_flow);
  if (!(other < own)) return false;
  char text[240];
  std::snprintf(text, sizeof text,
                "with f = %s the flow re-predicts the %d rings around the region better (%.3g against %.3g mean "
                "edges off the input with f = %s)",
                function_list(options.held_out_other_functions).c_str(), options.held_out_rings, other, own,
                function_list(options.flow.functions).c_str());
  note = text;
  return true;
}

// FairRegionOptions::held_out_rings: whichever of the flow as given, the flow with its boundary data
// fitted over 2-rings (held_out_two_ring_fits) and the linear ∆^k solution re-predicts the held-out
// rings best, with the reason in report.note where it is not the flow as given. The linear solution
// must win by FairRegionOptions::held_out_margin; ties keep the flow. Around a region rougher than
// FairRegionOptions::held_out_max_roughness it does not win at all.
// `refined` (fill): one ∆^k solve from these positions of the free vertices is weighed first, and
// taken where it beats the re-evaluated solution by kRefinedStartMargin (the flows are then not tried).
// The linear method (method = harmonic) weighs only these two: with `refined` and held-out rings it
// returns refined_linear or linear, else linear. Without held_out_may_choose_linear the flow weighs
// only its two boundary fits.
// Around a region rougher than held_out_max_roughness, with `refined`, that solve is the linear
// solution: the linear method's result without weighing, and the flows' start and floor (their
// trials start there too). On noisy borders it lies closer to the surface than the re-evaluated
// solution (docs/real-holes.md, "The refined solve on rough surroundings").
HeldOutVerdict choose_by_held_out(const Submesh& sub, const Topology& local, const FairRegionOptions& options,
                                  FairRegionReport& report, const Vertices* refined) {
  const bool linear_method = options.method == FairMethod::harmonic;
  if (options.held_out_rings <= 0) return {linear_method ? HeldOutChoice::linear : HeldOutChoice::flow};
  if (linear_method && !refined) return {HeldOutChoice::linear};
  if (!linear_method && (!options.linear_floor || options.harmonic_start_iterations <= 0)) return {HeldOutChoice::flow};
  const bool may_choose_linear = linear_method || options.held_out_may_choose_linear;
  if (!may_choose_linear && !fair_detail::weighs_two_ring_fits(options)) return {HeldOutChoice::flow};
  // The re-evaluated solution may win by held_out_margin and fill's solve from before its membrane
  // by kRefinedStartMargin, unless the surroundings are rough: there that solve is the flows' start
  // and floor instead, and the flows are weighed only against each other.
  bool floor_may_win = may_choose_linear;
  bool from_refined = false;
  std::string rough;  // why it may not, if it otherwise could
  const int order = static_cast<int>(report.supported) + 1;
  if (may_choose_linear && std::isfinite(options.held_out_max_roughness)) {
    report.held_out_roughness = surroundings_roughness(sub, local);
    if (report.held_out_roughness > options.held_out_max_roughness) {
      floor_may_win = false;
      from_refined = refined != nullptr;
      const std::string refined_fill = "one linear ∆" + std::to_string(order) +
                                       " solve from the patch before its membrane, the closer linear fill on noisy "
                                       "borders";
      char text[240];
      std::snprintf(text, sizeof text, "the surface around the region is rough (%.3g edges, above %.3g): ",
                    report.held_out_roughness, options.held_out_max_roughness);
      rough = text;
      if (linear_method) {
        report.note = rough + refined_fill;
        return {HeldOutChoice::refined_linear};
      }
      std::snprintf(text, sizeof text,
                    "the held-out rings, which reward a linear solution held by noisy rings for following the "
                    "noise, did not weigh the linear ∆%d solution against the flow",
                    order);
      rough += text;
      if (from_refined) rough += ", and the flow starts from " + refined_fill;
    }
  }
  const fair_detail::HeldOutErrors errors =
      fair_detail::held_out_errors(sub, local, options.held_out_rings, options, may_choose_linear ? refined : nullptr,
                                   !linear_method, from_refined);
  report.held_out_flow_error = errors.flow;
  report.held_out_two_ring_flow_error = errors.two_ring_flow;
  report.held_out_linear_error = errors.linear;
  report.held_out_refined_linear_error = errors.refined_linear;
  const char* flow_name = to_string(flow_for(report.supported));
  char text[320];
  if (errors.refined_start_wins() && !from_refined) {
    const std::string flow_start = linear_method ? "" : std::string(" the ") + flow_name + " flow starts from";
    std::snprintf(text, sizeof text,
                  "one linear ∆%d solve from the patch before its membrane re-predicts the %d rings around the "
                  "region more than twice as well as the re-evaluated ∆%d solution%s (%.3g against %.3g mean edges "
                  "off the input)%s",
                  order, options.held_out_rings, order, flow_start.c_str(), errors.refined_linear, errors.linear,
                  linear_method ? "" : "; the flow was not tried");
    report.note = text;
    return {HeldOutChoice::refined_linear};
  }
  if (linear_method) return {HeldOutChoice::linear};
  report.held_out_other_flow_error = errors.other_flow;
  report.held_out_other_two_ring_flow_error = errors.other_two_ring_flow;
  std::string other_note;
  const bool other = other_functions_win(errors, options, other_note);
  const double flow_error = other ? errors.other_flow : errors.flow;
  const double two_ring_error = other ? errors.other_two_ring_flow : errors.two_ring_flow;
  const bool two_ring = two_ring_error < flow_error;  // false for NaN (not weighed)
  const double best_flow = two_ring ? two_ring_error : flow_error;
  if (floor_may_win && errors.linear * options.held_out_margin < best_flow) {
    report.flow.well_posedness = errors.flow_well_posedness;  // the flow that was weighed, not run here
    std::snprintf(text, sizeof text,
                  "the linear ∆%d solution re-predicts the %d rings around the region better than the %s "
                  "flow (%.3g against %.3g mean edges off the input)",
                  order, options.held_out_rings, flow_name, errors.linear, best_flow);
    report.note = text;
    return {HeldOutChoice::linear};
  }
  if (!two_ring) {
    report.note = joined(rough, other_note);
    return {HeldOutChoice::flow, from_refined, other};
  }
  std::snprintf(text, sizeof text,
                "boundary data fitted over 2-rings: with them the %s flow re-predicts the %d rings around the "
                "region better (%.3g against %.3g mean edges off the input with 1-ring fits, %.3g for the "
                "linear ∆%d solution)",
                flow_name, options.held_out_rings, two_ring_error, flow_error, errors.linear, order);
  report.note = joined(rough, joined(other_note, text));
  return {HeldOutChoice::two_ring_flow, from_refined, other};
}

// Whether the neighbourhood extract_neighbourhood would cut around `free_vertices` is all of `mesh`
// (every face within reach, every vertex referenced or free), as for a mesh that already is one
// (fill cuts the patch's): fairing then works on the mesh as it is, and its connectivity `topo` is
// reused instead of built again for an identical copy.
bool whole_neighbourhood(const Mesh& mesh, const Topology& topo, std::span<const int> free_vertices, int rings) {
  const std::vector<int> dist = ring_distances(topo, free_vertices, rings);
  std::vector<char> referenced(mesh.num_vertices(), 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    bool reached = false;
    for (int k = 0; k < 3; ++k) reached |= dist[mesh.F(f, k)] >= 0, referenced[mesh.F(f, k)] = 1;
    if (!reached) return false;
  }
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (!referenced[v] && dist[v] != 0) return false;
  return true;
}

// What extract_neighbourhood returns when it keeps the whole mesh.
Submesh whole_submesh(const Mesh& mesh, std::span<const int> free_vertices) {
  Submesh sub;
  sub.mesh.V = mesh.V;
  sub.mesh.F = mesh.F;
  sub.to_global.resize(mesh.num_vertices());
  std::iota(sub.to_global.begin(), sub.to_global.end(), 0);
  sub.free_local.assign(free_vertices.begin(), free_vertices.end());
  std::sort(sub.free_local.begin(), sub.free_local.end());
  sub.free_local.erase(std::unique(sub.free_local.begin(), sub.free_local.end()), sub.free_local.end());
  return sub;
}

// FairRegionOptions::retry_other_boundary_fits: after the flow chosen by the held-out rings (run
// with `ran`) folded against its start and the floor was kept (`report`; `fold`: why, as
// run_flow_with_floor returned it; `held_out_note`: the note before that run), the flow with the
// other boundary fits runs from that start, where its held-out error was below the linear
// solution's. Delivered where it settles without folding; otherwise run_flow_with_floor has put the
// floor back, and its report is restored as it was.
void retry_other_boundary_fits(Submesh& sub, const Topology& local, const Region& region, const FairRegionOptions& ran,
                               const std::string& held_out_note, const std::string& fold,
                               const FlowObserver& observer, FairRegionReport& report, Vertices& caller) {
  if (!ran.retry_other_boundary_fits || !ran.held_out_two_ring_fits || !report.linear || report.held_out_linear ||
      !(report.checks_chose_linear || report.flow_folded_back))
    return;
  const bool two_ring = !ran.flow.two_ring_boundary_fits;
  const double error = two_ring ? report.held_out_two_ring_flow_error : report.held_out_flow_error;
  if (!(error < report.held_out_linear_error)) return;  // not weighed (NaN), or no better than the floor
  const FairRegionReport folded = report;
  FairRegionOptions other = ran;
  other.flow.two_ring_boundary_fits = report.two_ring_boundary_fits = two_ring;
  report.linear = report.checks_chose_linear = report.flow_folded_back = false;
  run_flow_with_floor(sub, local, region, other, observer, report, caller);
  if (report.linear) {
    report = folded;
    return;
  }
  // Which fits folded, and what was delivered instead.
  const std::string why = (held_out_note.empty() ? "" : held_out_note + "; ") + "the " +
                          to_string(report.flow_kind) + " flow with its boundary data fitted over " +
                          (two_ring ? "1" : "2") + "-rings " + fold;
  char text[320];
  std::snprintf(text, sizeof text,
                "; fitted over %d-rings instead it settles without folding, and re-predicts the %d rings around "
                "the region better than the linear solution (%.3g against %.3g mean edges off the input)",
                two_ring ? 2 : 1, ran.held_out_rings, error, report.held_out_linear_error);
  report.note = why + text;
}

// The linear solve alone, or the flow from it (FairRegionOptions::harmonic_start_iterations).
// `solved_start`: the free vertices already hold that solve's result, which this reports.
// `refined`: choose_by_held_out's.
void fair_submesh(Submesh& sub, const Topology& local, const Region& region, const FairRegionOptions& options,
                  const FlowObserver& observer, FairRegionReport& report, Vertices& caller,
                  const HarmonicReport* solved_start, const Vertices* refined) {
  HarmonicOptions harmonic;
  harmonic.order = static_cast<int>(region.supported) + 1;
  harmonic.solver = options.harmonic_solver;
  harmonic.iterations = std::max(1, options.harmonic_start_iterations);
  harmonic.tolerance = options.harmonic_start_tolerance;
  const HeldOutVerdict verdict = choose_by_held_out(sub, local, options, report, refined);
  HeldOutChoice choice = verdict.choice;
  report.held_out_linear = options.method == FairMethod::flow &&
                           (choice == HeldOutChoice::linear || choice == HeldOutChoice::refined_linear);
  report.checks_chose_linear = report.held_out_linear;
  // One ∆^k solve from the refined positions into sub.mesh.V. It was weighed on the enlarged region,
  // not on this one: where it fails here, the re-evaluated solution stands in, and the note says so.
  const auto solve_from_refined = [&] {
    HarmonicOptions once = harmonic;
    once.iterations = 1;
    Vertices V = *refined;
    try {
      report.harmonic = harmonic_fair(V, sub.mesh.F, local, region, once);
      sub.mesh.V = std::move(V);
      return true;
    } catch (const NumericalError& e) {
      report.note += std::string("; that solve failed on the region (") + e.what() + "): kept the re-evaluated one";
      return false;
    }
  };
  if (choice == HeldOutChoice::refined_linear) {
    if (solve_from_refined()) {
      report.linear = report.refined_start = true;
      return;
    }
    choice = HeldOutChoice::linear;
  }
  if (choice == HeldOutChoice::linear) {
    report.harmonic = harmonic_fair(sub.mesh.V, sub.mesh.F, local, region, harmonic);
    report.linear = true;
    return;
  }
  FairRegionOptions flow_options = options;
  if (choice == HeldOutChoice::two_ring_flow) flow_options.flow.two_ring_boundary_fits = true;
  if (verdict.other_functions) flow_options.flow.functions = options.held_out_other_functions;
  report.two_ring_boundary_fits = flow_options.flow.two_ring_boundary_fits;
  report.other_functions = verdict.other_functions;
  const bool from_refined = verdict.flow_from_refined && solve_from_refined();
  if (!from_refined && solved_start) {
    report.harmonic = *solved_start;
  } else if (!from_refined && options.harmonic_start_iterations > 0) {
    try {
      report.harmonic = harmonic_fair(sub.mesh.V, sub.mesh.F, local, region, harmonic);
    } catch (const NumericalError& e) {
      // No linear solution to start from or to fall back to: flow from the given positions.
      report.note = std::string("the ∆") + std::to_string(harmonic.order) + " start failed (" + e.what() +
                    "): flowed from the given positions";
      flow_options.harmonic_start_iterations = 0;
    }
  }
  const std::string held_out_note = report.note;
  const std::string fold = run_flow_with_floor(sub, local, region, flow_options, observer, report, caller);
  retry_other_boundary_fits(sub, local, region, flow_options, held_out_note, fold, observer, report, caller);
  report.refined_start = from_refined && report.linear;  // the floor kept is that solve
}

}  // namespace

namespace fair_detail {

namespace {

FairRegionReport fair_valid(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                            const FairRegionOptions& options, const FlowObserver& observer, bool measure,
                            bool* whole, const HarmonicReport* solved_start, const Vertices* refined) {
  const auto start = detail::Clock::now();
  if (free_vertices.empty()) throw InvalidArgument("fair_region: the free region is empty");
  fair_detail::require_valid_held_out_options(options, "fair_region");
  const FlowKind wanted = flow_for(options.continuity);
  if (options.flow.kind && *options.flow.kind != wanted)
    throw InvalidArgument(std::string("fair_region: flow.kind ") + to_string(*options.flow.kind) + " cannot reach " +
                          to_string(options.continuity) + ", which needs the " + to_string(wanted) +
                          " flow; leave flow.kind unset");
  const bool uncut = whole_neighbourhood(mesh, topo, free_vertices, options.submesh_rings);
  if (whole) *whole = uncut;
  Submesh sub = uncut ? whole_submesh(mesh, free_vertices)
                      : extract_neighbourhood(mesh.V, mesh.F, topo, free_vertices, options.submesh_rings);
  std::optional<Topology> cut;
  if (!uncut) cut = derive_topology(topo, sub.mesh.F, sub.to_global);
  const Topology& local = uncut ? topo : *cut;
  const Region region = make_region(local, sub.free_local, options.continuity);

  FairRegionReport report;
  report.free_vertices = region.num_free();
  report.requested = options.continuity;
  report.supported = region.supported;
  report.method = options.method;
  // `refined` on the submesh's vertices: itself where the submesh is the whole mesh (fill's case).
  const Vertices* refined_on_sub = uncut ? refined : nullptr;
  Vertices refined_sub;
  if (refined && refined->rows() != mesh.V.rows())
    throw InvalidArgument("fair_region: the refined positions are not one row per vertex");
  if (refined && !uncut) {
    refined_sub.resize(sub.mesh.num_vertices(), 3);
    for (int v = 0; v < sub.mesh.num_vertices(); ++v) refined_sub.row(v) = refined->row(sub.to_global[v]);
    refined_on_sub = &refined_sub;
  }
  fair_submesh(sub, local, region, options, observer, report, mesh.V, solved_start, refined_on_sub);
  write_back_free(sub, mesh.V);
  if (measure) report.continuity = measure_continuity(sub.mesh.V, sub.mesh.F, local, sub.free_local);
  report.seconds = detail::seconds_since(start);
  return report;
}

}  // namespace

FairRegionReport fair_valid_mesh(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                 const FairRegionOptions& options, const FlowObserver& observer, bool measure,
                                 bool* whole) {
  return fair_valid(mesh, topo, free_vertices, options, observer, measure, whole, nullptr, nullptr);
}

FairRegionReport fair_valid_mesh_from(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                      const FairRegionOptions& options, const HarmonicReport& start) {
  if (options.method != FairMethod::flow || options.harmonic_start_iterations <= 0)
    throw InvalidArgument("fair_valid_mesh_from: only the flow from a harmonic start has one to reuse");
  return fair_valid(mesh, topo, free_vertices, options, {}, false, nullptr, &start, nullptr);
}

FairRegionReport fair_checked_mesh(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                   const FairRegionOptions& options, const FlowObserver& observer, bool measure,
                                   bool* whole, const Vertices* refined) {
  ValidationReport report = validate(mesh, topo);
  detail::allow_border_pinches(report, topo);
  require_valid(report, Requirements{}, "fair_region");
  return fair_valid(mesh, topo, free_vertices, options, observer, measure, whole, nullptr, refined);
}

}  // namespace fair_detail

namespace {

// "face a crosses face b, N crossings" for the first of `crossings`.
std::string crossing_text(const std::vector<FaceIntersection>& crossings) {
  const FaceIntersection& c = crossings.front();
  return "face " + std::to_string(c.query_face) + " crosses face " + std::to_string(c.other_face) + ", " +
         detail::crossing_count(crossings);
}

// The crossings the given region had (find_face_intersections of its faces): the faces in them,
// per face of the mesh (empty where there were none), and how many.
struct GivenCrossings {
  std::vector<char> faces;
  std::size_t count = 0;
};

GivenCrossings given_crossings(const Mesh& mesh, const std::vector<int>& faces) {
  const std::vector<FaceIntersection> crossings = find_face_intersections(mesh.V, mesh.F, faces, 0);
  GivenCrossings given{{}, crossings.size()};
  if (crossings.empty()) return given;
  given.faces.assign(mesh.num_faces(), 0);
  for (const FaceIntersection& c : crossings) given.faces[c.query_face] = given.faces[c.other_face] = 1;
  return given;
}

// The crossings of `faces` on (V, F) that the given region did not have, at most kCrossingsSought.
// A region that already crosses itself, as a noisy scan's may, is held to no more than that: the
// crossings of the faces that crossed may change partners once those faces move (a pierced face
// that moves is crossed elsewhere), but may not grow in number, and any other crossing is new.
std::vector<FaceIntersection> new_crossings(const Vertices& V, const Faces& F, const std::vector<int>& faces,
                                            const GivenCrossings& given) {
  if (given.count == 0) return find_face_intersections(V, F, faces, detail::kCrossingsSought);
  std::vector<FaceIntersection> fresh, at_given;
  for (const FaceIntersection& c : find_face_intersections(V, F, faces, 0))
    (given.faces[c.query_face] || given.faces[c.other_face] ? at_given : fresh).push_back(c);
  if (at_given.size() > given.count) fresh.insert(fresh.end(), at_given.begin(), at_given.end());
  if (fresh.size() > static_cast<std::size_t>(detail::kCrossingsSought)) fresh.resize(detail::kCrossingsSought);
  return fresh;
}

// Where the flow's result crossed the mesh (`crossings`, with `report`) and its linear floor does
// not: the fairing once more from the `given` positions, each flow trial that crosses the mesh
// rejected (FairRegionOptions::retry_rejecting_crossings), whose result replaces the crossing one in
// `mesh` and `report` where it settles as a flow clear of the mesh. Returns whether it did. (The flow
// starts from that floor; a start that crosses would turn the rejection off.)
template <class Fair>
bool retry_rejecting_crossings(Mesh& mesh, const Vertices& given, const std::vector<int>& faces,
                               const GivenCrossings& given_crossed, const FairRegionOptions& options, Fair& fair,
                               const std::vector<FaceIntersection>& crossings, FairRegionReport& report) {
  if (!options.retry_rejecting_crossings || report.linear || options.method != FairMethod::flow ||
      options.flow.reject_crossings)
    return false;
  FairRegionOptions rejecting = options;
  rejecting.flow.reject_crossings = true;
  Mesh retried = mesh;
  retried.V = given;
  FairRegionReport retried_report;
  try {
    retried_report = fair(retried, rejecting);
  } catch (const NumericalError&) {
    return false;
  }
  if (retried_report.linear || retried_report.flow.stop_reason != FlowStopReason::steady ||
      !new_crossings(retried.V, retried.F, faces, given_crossed).empty())
    return false;
  retried_report.note = "the " + std::string(to_string(report.flow_kind)) + " flow's result crossed the mesh (" +
                        crossing_text(crossings) + "); flowed again, each trial that crosses the mesh rejected" +
                        (retried_report.note.empty() ? "" : "; " + retried_report.note);
  mesh.V = std::move(retried.V);
  report = std::move(retried_report);
  return true;
}

// With the linear floor, a faired region that crosses the mesh where the given one did not
// (new_crossings) is replaced by the first linear solution from the given positions that does not,
// at the continuity reached and then at each lower one (as fill's fallback: C2 → C1 → C0), reported
// linear with the reason; otherwise NumericalError, with mesh.V at the crossing result. Where that
// solution is the crossing flow's own floor, the flow is first tried again from it
// (retry_rejecting_crossings). `fair(mesh, options)`: the fairing itself.
template <class Fair>
FairRegionReport fair_uncrossed(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                const FairRegionOptions& options, Fair&& fair) {
  const bool floor = options.linear_floor && options.harmonic_start_iterations > 0;
  if (!floor) return fair(mesh, options);
  const std::vector<int> faces = region_faces(mesh.F, mesh.num_vertices(), free_vertices);
  const GivenCrossings given_crossed = given_crossings(mesh, faces);
  const auto start = detail::Clock::now();
  const Vertices given = mesh.V;
  FairRegionReport report = fair(mesh, options);
  const std::vector<FaceIntersection> crossings = new_crossings(mesh.V, mesh.F, faces, given_crossed);
  if (crossings.empty()) return report;
  const int order = static_cast<int>(report.supported) + 1;
  const std::string what = report.linear ? "the linear ∆" + std::to_string(order) + " solution"
                                         : std::string("the ") + to_string(report.flow_kind) + " flow's result";
  const int highest = static_cast<int>(report.supported) - (report.linear ? 1 : 0);
  for (int c = highest; c >= 0; --c) {
    Mesh linear = mesh;
    linear.V = given;
    FairRegionOptions harmonic = options;
    harmonic.method = FairMethod::harmonic;
    harmonic.continuity = static_cast<Continuity>(c);
    try {
      FairRegionReport floor_report = fair_detail::fair_valid_mesh(linear, topo, free_vertices, harmonic, {});
      if (!new_crossings(linear.V, linear.F, faces, given_crossed).empty()) continue;
      if (c == static_cast<int>(report.supported) &&
          retry_rejecting_crossings(mesh, given, faces, given_crossed, options, fair, crossings, report)) {
        report.seconds = detail::seconds_since(start);  // the crossing fairing's and the floor's too
        return report;
      }
      floor_report.requested = report.requested;
      floor_report.crossing_fallback = true;
      floor_report.seconds = detail::seconds_since(start);  // the crossing fairing's too
      floor_report.note = what + " crosses the mesh (" + crossing_text(crossings) + "); kept the linear ∆" +
                          std::to_string(c + 1) + " solution, the first that does not";
      mesh.V = std::move(linear.V);
      return floor_report;
    } catch (const NumericalError&) {  // no linear solution at this continuity
    }
  }
  // Too few fixed rings are the likely cause where they support less than was asked.
  const std::string rings = report.supported < report.requested
                                ? "; its fixed rings support only " + std::string(to_string(report.supported)) +
                                      ", not the " + to_string(report.requested) +
                                      " requested: too few fixed rings around it (the region takes nearly all "
                                      "of the mesh, or comes close to its border)"
                                : "";
  throw NumericalError("fair_region: the faired region crosses the mesh where the given one did not (" +
                       crossing_text(crossings) + "), and so does every linear solution down to ∆1" + rings);
}

}  // namespace

namespace {

// fair_region on a validated mesh: part by part (fair_in_parts), each part with its crossing check.
FairRegionReport fair_validated(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                                const FairRegionOptions& options, const FlowObserver& observer) {
  return fair_detail::fair_in_parts(mesh, topo, free_vertices, options, [&](std::span<const int> part) {
    return fair_uncrossed(mesh, topo, part, options, [&](Mesh& faired, const FairRegionOptions& o) {
      return fair_detail::fair_valid_mesh(faired, topo, part, o, observer);
    });
  });
}

}  // namespace

FairRegionReport fair_region(Mesh& mesh, std::span<const int> free_vertices,
                             const FairRegionOptions& options, const FlowObserver& observer) {
  // validate builds the mesh's connectivity: kept, not built again.
  const Topology topo = detail::validated_topology(mesh, Requirements{}, "fair_region");
  return fair_validated(mesh, topo, free_vertices, options, observer);
}

FairRegionReport fair_region(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                             const FairRegionOptions& options, const FlowObserver& observer) {
  require_valid(validate(mesh, topo), Requirements{}, "fair_region");
  return fair_validated(mesh, topo, free_vertices, options, observer);
}

}  // namespace fairsurf
