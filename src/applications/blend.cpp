#include <fairsurf/applications/blend.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/mesh_attributes.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/membrane.h>
#include <fairsurf/patch/tube.h>

#include "border_fold.h"
#include "mesh/crossing_count.h"
#include "stopwatch.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <tuple>

namespace fairsurf {
namespace {

std::string loop_list(const std::vector<std::vector<int>>& loops) {
  std::string out;
  for (std::size_t i = 0; i < loops.size(); ++i)
    out += (i > 0 ? ", " : "") + std::to_string(i) + " (" + std::to_string(loops[i].size()) + " vertices)";
  return out;
}

LoopPair chosen_pair(const Vertices& V, const std::vector<std::vector<int>>& loops, const BlendOptions& o) {
  const int n = static_cast<int>(loops.size());
  if (n < 2)
    throw InvalidMeshError("blend_loops: the mesh has " + std::to_string(n) +
                           (n == 1 ? " boundary loop" : " boundary loops") + "; blending needs two");
  if (o.loop_a < 0 && o.loop_b < 0) return closest_loop_pair(V, loops);
  for (int index : {o.loop_a, o.loop_b})
    if (index < 0 || index >= n)
      throw InvalidArgument("blend_loops: loop " + std::to_string(index) + " is out of range; the mesh has " +
                            std::to_string(n) + " boundary loops: " + loop_list(loops));
  if (o.loop_a == o.loop_b)
    throw InvalidArgument("blend_loops: loop " + std::to_string(o.loop_a) + " given twice; two loops are needed");
  return {o.loop_a, o.loop_b, 0.0};
}

// Two loops through one vertex touch there: a non-manifold vertex, which repair splits in two.
void require_apart(const std::vector<int>& loop_a, const std::vector<int>& loop_b, const LoopPair& pair) {
  for (int v : loop_a)
    if (std::find(loop_b.begin(), loop_b.end(), v) != loop_b.end())
      throw RepairableMeshError("blend_loops: loops " + std::to_string(pair.first) + " and " +
                                std::to_string(pair.second) + " share vertex " + std::to_string(v) +
                                ", a non-manifold vertex where the two borders touch; no tube starts from both");
}

// A loop through one vertex twice pinches there: a non-manifold vertex, which repair splits in two
// (the loop then splits too). A tube from it would use the vertex's border edges twice.
void require_simple(const std::vector<int>& loop, int index) {
  std::vector<int> sorted = loop;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end())
    throw RepairableMeshError("blend_loops: loop " + std::to_string(index) + " passes through vertex " +
                              std::to_string(*twice) +
                              " twice, a non-manifold vertex where its border pinches; no tube starts from it");
}

// Worst 4√3·area / Σ edge² over faces [first_face, #F) of (V, F).
double worst_quality(const Vertices& V, const Faces& F, int first_face) {
  double worst = 1.0;
  for (Eigen::Index f = first_face; f < F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    const double doubled_area = (b - a).cross(c - a).norm();
    worst = std::min(worst, squares > 0 ? 2.0 * std::sqrt(3.0) * doubled_area / squares : 0.0);
  }
  return worst;
}

// The Hermite tube, relaxed to the G0 membrane when asked and when the membrane does not pinch off.
InitialPatch initial_tube(const Mesh& mesh, const Topology& topo, const std::vector<int>& loop_a,
                          const std::vector<int>& loop_b, const BlendOptions& options, BlendReport& report) {
  PatchOptions hermite = options.patch;
  hermite.relax = false;
  InitialPatch patch = tube_patch(mesh, topo, loop_a, loop_b, hermite);
  const Faces& F = patch.mesh.F;
  report.hermite_quality = worst_quality(patch.mesh.V, F, patch.first_patch_face);
  report.membrane_quality = 0;  // this tube's figures only, also when a first tube was built
  report.relaxed = false;
  if (!options.patch.relax || patch.free_vertices.empty()) return patch;
  Vertices relaxed = patch.mesh.V;
  MembraneReport membrane = relax_membrane(relaxed, F, patch.topology, patch.free_vertices, options.patch.membrane,
                                           options.patch.solver);
  report.membrane_quality = worst_quality(relaxed, F, patch.first_patch_face);
  report.relaxed = report.membrane_quality >= options.pinch_quality_ratio * report.hermite_quality;
  if (report.relaxed) {
    patch.mesh.V = std::move(relaxed);
    patch.membrane = std::move(membrane);
  }
  return patch;
}

// measure_continuity on the faces within `rings` rings of `loop`, at the vertices `at` only; `topo`:
// the connectivity of mesh.F, from which the measured part's derives.
ContinuityMeasure measure_near_loop(const Mesh& mesh, const Topology& topo, const std::vector<int>& loop, int rings,
                                    const std::vector<int>& free_vertices, const std::vector<int>& at) {
  const std::vector<int> distance = ring_distances(topo, loop, rings);
  std::vector<int> local(mesh.num_vertices(), -1), to_parent;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (distance[v] >= 0) local[v] = static_cast<int>(to_parent.size()), to_parent.push_back(v);
  Vertices V(static_cast<Eigen::Index>(to_parent.size()), 3);
  for (std::size_t v = 0; v < to_parent.size(); ++v) V.row(static_cast<Eigen::Index>(v)) = mesh.V.row(to_parent[v]);
  std::vector<Eigen::RowVector3i> faces;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::RowVector3i c = mesh.F.row(f);
    if (local[c[0]] >= 0 && local[c[1]] >= 0 && local[c[2]] >= 0)
      faces.emplace_back(local[c[0]], local[c[1]], local[c[2]]);
  }
  Faces F(static_cast<int>(faces.size()), 3);
  for (int f = 0; f < F.rows(); ++f) F.row(f) = faces[f];
  const auto to_local = [&local](const std::vector<int>& vertices) {
    std::vector<int> out;
    for (int v : vertices)
      if (local[v] >= 0) out.push_back(local[v]);
    return out;
  };
  return measure_continuity(V, F, derive_topology(topo, F, to_parent), to_local(free_vertices), to_local(at));
}

// The measurement on the untouched input (`topo`: its connectivity): the vertices fewer than
// `offset` rings from the loop play the free region, those at `offset` rings are measured.
ContinuityMeasure reference_at_loop(const Mesh& input, const Topology& topo, const std::vector<int>& loop, int offset,
                                    int rings) {
  const std::vector<int> distance = ring_distances(topo, loop, offset);
  std::vector<int> inner, line;
  for (int v = 0; v < input.num_vertices(); ++v)
    if (distance[v] >= 0) (distance[v] < offset ? inner : line).push_back(v);
  return measure_near_loop(input, topo, loop, offset + rings, inner, line);
}

// The time-stepped flow's options turned into the energy descent's (flow.md, "Energy descent").
FairRegionOptions descent_options(const FairRegionOptions& fair) {
  FairRegionOptions o = fair;
  o.flow.step_kind = FlowStepKind::energy_descent;
  o.flow.steady_energy_tolerance = 1e-5;
  o.flow.max_consecutive_rejections = 30;
  o.flow.reject_crossings = true;
  o.harmonic_start_iterations = 0;  // from the time-stepped flow's last state
  return o;
}

// A faired tube that still crosses the mesh (fair_tube): blend_loops builds the tube again with
// straight rings before it gives up.
class TubeCrossing : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

// Crossings of the tube's faces (from `first_tube_face` on) with the faces of `mesh`, the first
// kCrossingsSought.
std::vector<FaceIntersection> tube_crossings(const Mesh& mesh, int first_tube_face) {
  std::vector<int> tube(mesh.num_faces() - first_tube_face);
  std::iota(tube.begin(), tube.end(), first_tube_face);
  return find_face_intersections(mesh.V, mesh.F, tube, detail::kCrossingsSought);
}

bool tube_crosses(const Mesh& mesh, int first_tube_face) { return !tube_crossings(mesh, first_tube_face).empty(); }

// Why a faired tube is not delivered: its first crossing and how many (`also`: what else crossed).
std::string crossing_message(const std::vector<FaceIntersection>& crossings, int first_tube_face,
                             const std::string& also) {
  const FaceIntersection& c = crossings.front();
  return "blend_loops: the faired tube crosses the mesh (tube face " + std::to_string(c.query_face) + " crosses " +
         (c.other_face >= first_tube_face ? "tube" : "input") + " face " + std::to_string(c.other_face) + ", " +
         detail::crossing_count(crossings) + ")" + also;
}

// The linear ∆^k tube: the tube `tube` of mesh faired by the options' cotangent solve.
struct LinearTube {
  Mesh mesh;
  FairRegionReport report;
  int order() const { return static_cast<int>(report.supported) + 1; }
};

// Nothing where the solve throws.
std::optional<LinearTube> linear_tube(const Mesh& mesh, const Topology& topo, const std::vector<int>& free,
                                      const Vertices& tube, const BlendOptions& options) {
  LinearTube linear{mesh, {}};
  linear.mesh.V = tube;
  FairRegionOptions harmonic = options;
  harmonic.method = FairMethod::harmonic;
  try {
    linear.report = fair_region(linear.mesh, topo, free, harmonic);
  } catch (const NumericalError&) {
    return std::nullopt;
  }
  return linear;
}

// The linear ∆^k tube from the tube as built, solved at most once: flow_tube's descent starts from
// it and fair_tube falls back to it where the flow's tube crosses the mesh. Of `mesh` only its
// faces are read (linear_tube replaces its positions by `tube`), so the flow may move it meanwhile.
class LinearTubeOnce {
 public:
  LinearTubeOnce(const Mesh& mesh, const Topology& topo, const std::vector<int>& free, const Vertices& tube,
                 const BlendOptions& options)
      : mesh_(mesh), topo_(topo), free_(free), tube_(tube), options_(options) {}
  // Empty where the solve threw.
  std::optional<LinearTube>& get() {
    if (!solved_) linear_ = linear_tube(mesh_, topo_, free_, tube_, options_);
    solved_ = true;
    return linear_;
  }

 private:
  const Mesh& mesh_;
  const Topology& topo_;
  const std::vector<int>& free_;
  const Vertices& tube_;
  const BlendOptions& options_;
  bool solved_ = false;
  std::optional<LinearTube> linear_;
};

// One energy descent of the tube: its result, report and steps, and whether it crosses the mesh.
struct TubeDescent {
  Vertices V;
  FairRegionReport report;
  std::vector<StepRecord> steps;
  bool crosses = false;
  std::string start;  ///< where it started, for the note
};

// Whether an unsettled time-stepped flow is continued by the energy descent (descent_fallback).
bool descended(const BlendOptions& options) {
  return options.descent_fallback && options.method == FairMethod::flow &&
         options.flow.step_kind == FlowStepKind::implicit_flow;
}

// The energy descent from the positions `start` of mesh's tube; nothing where it throws.
std::optional<TubeDescent> descend_tube(const Mesh& mesh, const Topology& topo, const std::vector<int>& free,
                                        int first_tube_face, Vertices start, const FairRegionOptions& descent,
                                        std::string name) {
  Mesh from = mesh;
  from.V = std::move(start);
  TubeDescent d;
  try {
    d.report = fair_region(from, topo, free, descent, [&](const StepRecord& r) { d.steps.push_back(r); });
  } catch (const NumericalError&) {
    return std::nullopt;
  }
  d.crosses = tube_crosses(from, first_tube_face);
  d.V = std::move(from.V);
  d.start = std::move(name);
  return d;
}

// The descent kept: one whose tube does not cross the mesh, then one that settled, then one that
// does not fold against the linear tube (whose largest border normal angle is `linear_angle`;
// fill's rule, border_fold.h), then the one of lowest energy. Null where every descent threw.
const TubeDescent* kept_descent(const std::vector<std::optional<TubeDescent>>& descents, double linear_angle) {
  const double fold_ratio = FairRegionOptions::harmonic_started().max_border_angle_ratio;
  auto rank = [&](const TubeDescent& d) {
    return std::tuple(d.crosses, d.report.flow.stop_reason != FlowStopReason::steady,
                      detail::folds_against(d.report.continuity.max_normal_angle, linear_angle, fold_ratio),
                      d.report.flow.final_energy);
  };
  const TubeDescent* best = nullptr;
  for (const std::optional<TubeDescent>& d : descents)
    if (d && (!best || rank(*d) < rank(*best))) best = &*d;
  return best;
}

// Fairs the tube as the options' FairRegionOptions base says; where that sixth-order flow steps in
// time and ends unsettled or throws (a real mesh's irregular rings: the fitted EL is not the
// gradient of the discrete energy there, flow.md), the energy descent takes over and runs until E
// stops decreasing, from three starts: the time-stepped flow's last accepted state, the tube it
// started from and the linear ∆^k tube from that. A diverging time-stepped flow can leave a state
// tangled through the mesh that the descent only settles; the tube as built is often clear of it,
// and the linear tube is the classical fairing the descent lowers E from in fill and fair. The
// descent kept is one that does not cross the mesh, then one that does not fold against the linear
// tube (fill's rule, border_fold.h), then the one of lowest energy. `tube`: mesh.V as the tube was
// built; `linear`: the linear tube from it. `topo`: the connectivity of mesh.F, validated by each
// fair_region.
FairRegionReport flow_tube(Mesh& mesh, const Topology& topo, const std::vector<int>& free, int first_tube_face,
                           const Vertices& tube, LinearTubeOnce& linear, const BlendOptions& options,
                           const FlowObserver& observer) {
  const bool may_descend = descended(options);
  std::string failure;
  try {
    FairRegionReport report = fair_region(mesh, topo, free, options, observer);
    if (!may_descend || report.linear || report.flow_kind != FlowKind::sixth_order ||
        report.flow.stop_reason == FlowStopReason::steady)
      return report;
    failure = unsettled_reason(report.flow);
  } catch (const NumericalError& e) {
    if (!may_descend || options.continuity != Continuity::G2) throw;
    failure = std::string("failed (") + e.what() + ")";  // mesh holds the last accepted state
  }
  const FairRegionOptions descent = descent_options(options);
  std::vector<std::optional<TubeDescent>> descents;
  descents.push_back(descend_tube(mesh, topo, free, first_tube_face, mesh.V, descent, "its last state"));
  if (mesh.V != tube)  // the time-stepped flow moved
    descents.push_back(descend_tube(mesh, topo, free, first_tube_face, tube, descent, "the tube it started from"));
  double linear_angle = std::numeric_limits<double>::infinity();  // no fold without a linear tube
  if (const std::optional<LinearTube>& solved = linear.get()) {
    linear_angle = solved->report.continuity.max_normal_angle;
    descents.push_back(descend_tube(mesh, topo, free, first_tube_face, solved->mesh.V, descent,
                                    "the linear ∆" + std::to_string(solved->order()) + " tube"));
  }
  const TubeDescent* best = kept_descent(descents, linear_angle);
  if (!best)
    throw NumericalError("blend_loops: the time-stepped flow " + failure +
                         ", and the energy descent failed from its last state, the tube and the linear tube");
  if (observer)
    for (const StepRecord& r : best->steps) observer(r);
  mesh.V = best->V;
  FairRegionReport report = best->report;
  report.note = "the time-stepped flow " + failure + "; the energy descent continued from " + best->start +
                (report.note.empty() ? "" : "; " + report.note);
  return report;
}

// Edges with a tube face (from `first_tube_face` on) whose two faces' normals are more than 90°
// apart: creases, which no fair surface has. `topo`: the connectivity of F.
int tube_creases(const Vertices& V, const Faces& F, const Topology& topo, int first_tube_face) {
  const auto area_normal = [&](int f) -> Eigen::RowVector3d {
    const Eigen::RowVector3d a = V.row(F(f, 0));
    return (V.row(F(f, 1)) - a).cross(V.row(F(f, 2)) - a);
  };
  int creases = 0;
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e) {
    const std::span<const int> faces = topo.edge_faces.row(static_cast<int>(e));
    if (faces.size() == 2 && std::max(faces[0], faces[1]) >= first_tube_face)
      creases += area_normal(faces[0]).dot(area_normal(faces[1])) < 0;
  }
  return creases;
}

// The flow's tube creases against the linear one where it has more creased edges (tube_creases)
// than twice the linear tube's and than the linear tube's plus kCreaseSlack: a fold of the tube into
// itself that its border angles need not show (bench_real_holes' spot 1519 z: a fin out of the neck,
// 68 creased edges where the linear tube has 16; docs/blend.md, "Creased tubes").
constexpr int kCreaseSlack = 4;
bool creases_against(int flow_creases, int linear_creases) {
  return flow_creases > std::max(2 * linear_creases, linear_creases + kCreaseSlack);
}

// The linear tube `linear` delivered instead of the flow's (whose report is `flow`) for `reason`:
// reported as fair_region reports its floor, the flow's method and kind with `linear` set, and of
// the flow's report only its well_posedness (what `fairsurf blend` warns from).
FairRegionReport keep_linear_tube(Mesh& mesh, LinearTube& linear, const FairRegionReport& flow,
                                  const std::string& reason) {
  FairRegionReport report = std::move(linear.report);
  report.note = std::string("the ") + to_string(flow.flow_kind) + " flow's tube " + reason +
                (flow.note.empty() ? "" : " (" + flow.note + ")") + "; kept the linear ∆" +
                std::to_string(linear.order()) + " tube";
  report.method = flow.method;
  report.flow_kind = flow.flow_kind;
  report.flow.well_posedness = flow.flow.well_posedness;
  mesh.V = std::move(linear.mesh.V);
  return report;
}

// A flow's tube turns more than the linear one across the loops where its largest border normal
// angle exceeds the linear tube's this many times: within 5% the one-sided fits cannot tell the two
// apart, and such a tie goes to the G2 asked for (as FillOptions::held_out_margin's).
constexpr double kBorderAngleMargin = 1.05;

// Why the flow's tube (in `mesh`, reported by `report`; `creases`: its tube_creases) is no gain over
// the linear tube `linear` from the same start, or empty. Either it turns the normal across the
// loops by more than the linear tube does (kBorderAngleMargin) and by more than
// kSmallestFoldAngle: a G2 tube less smooth at its borders than the C2 one, which on the real slabs
// of bench_real_holes --all-slabs lies farther from the surface than the linear tube on average
// (docs/blend.md, "A G2 tube that turns more than the linear one"). Or it creases against it
// (creases_against).
std::string loses_to_linear(const Mesh& mesh, const FairRegionReport& report, int creases, const LinearTube& linear,
                            const Topology& topo, int first_tube_face) {
  const double angle = report.continuity.max_normal_angle, linear_angle = linear.report.continuity.max_normal_angle;
  if (detail::folds_against(angle, linear_angle, kBorderAngleMargin)) {
    char text[160];
    std::snprintf(text, sizeof text, "turns the normal across the loops by %.3g°, more than the linear tube (%.3g°)",
                  angle * 180 / std::numbers::pi, linear_angle * 180 / std::numbers::pi);
    return text;
  }
  const int linear_creases = tube_creases(linear.mesh.V, mesh.F, topo, first_tube_face);
  if (creases_against(creases, linear_creases))
    return "creases (" + std::to_string(creases) + " of its edges turn by more than 90°, " +
           std::to_string(linear_creases) + " of the linear tube's)";
  return "";
}

// The flow's tube in `mesh` (reported by `report`), which does not cross the mesh, against the linear
// ∆^k tube from the same start `tube`: where the method is the flow and its tube is no gain over the
// linear one (loses_to_linear), or did not settle after the descent fallback, the linear tube takes
// its place if it does not cross the mesh (labelled linear, with the reason).
FairRegionReport weigh_uncrossed_tube(Mesh& mesh, const Topology& topo, const std::vector<int>& free,
                                      int first_tube_face, const Vertices& tube, LinearTubeOnce& linear_once,
                                      const BlendOptions& options, FairRegionReport report) {
  if (options.method != FairMethod::flow || report.linear) return report;
  if (report.flow.stop_reason != FlowStopReason::steady) {
    // The flow the user asked for is delivered as it stands, NOT steady (descent_fallback off, or
    // the descent asked for as the step); where the descent fallback ran and no descent settled,
    // the linear tube takes its place, as fill and fair_region keep their floor.
    if (!descended(options)) return report;
    std::optional<LinearTube>& linear = linear_once.get();
    if (!linear || tube_crosses(linear->mesh, first_tube_face)) return report;
    return keep_linear_tube(mesh, *linear, report, "did not settle");
  }
  if (!options.weigh_against_linear_tube) return report;
  const int creases = tube_creases(mesh.V, mesh.F, topo, first_tube_face);
  // Neither rule of loses_to_linear can hold, whatever the linear tube: no solve.
  if (report.continuity.max_normal_angle <= detail::kSmallestFoldAngle && !creases_against(creases, 0))
    return report;
  std::optional<LinearTube>& linear = linear_once.get();
  if (!linear) return report;
  if (!tube_crosses(linear->mesh, first_tube_face)) {
    const std::string reason = loses_to_linear(mesh, report, creases, *linear, topo, first_tube_face);
    if (reason.empty()) return report;
    FairRegionReport kept = keep_linear_tube(mesh, *linear, report, reason);
    kept.checks_chose_linear = true;
    // The linear tube from the same start may turn nearly as far: blend_loops builds both again from
    // the Hermite tube (BlendOptions::rebuild_without_membrane).
    kept.flow_folded_back = detail::turns_back(report.continuity.max_normal_angle);
    return kept;
  }
  // The linear tube crosses the mesh: the flow's is weighed against the first lower one that does
  // not, the floor blend_lower_linear_tube would deliver.
  for (int c = static_cast<int>(linear->report.supported) - 1; c >= 0; --c) {
    BlendOptions lower_options = options;
    lower_options.continuity = static_cast<Continuity>(c);
    std::optional<LinearTube> lower = linear_tube(mesh, topo, free, tube, lower_options);
    if (!lower || tube_crosses(lower->mesh, first_tube_face)) continue;
    const std::string reason = loses_to_linear(mesh, report, creases, *lower, topo, first_tube_face);
    if (reason.empty()) return report;
    FairRegionReport kept = keep_linear_tube(mesh, *lower, report, reason + " (the linear ∆" +
                                                                      std::to_string(linear->order()) +
                                                                      " tube crosses the mesh)");
    kept.requested = options.continuity;
    kept.crossing_fallback = true;
    kept.checks_chose_linear = true;
    return kept;
  }
  return report;
}

// Where the flow's tube crosses the mesh: the flow once more from the tube, its trial states relaxed
// tangentially by options.crossing_retry_relaxation (fill's retry, docs/real-holes.md "A crossing flow,
// relaxed"), whose result replaces the crossing one in `mesh` and `report` where it settles clear
// of the mesh. Returns the crossings left.
std::vector<FaceIntersection> retry_relaxed(Mesh& mesh, const Topology& topo, const std::vector<int>& free,
                                            int first_tube_face, const Vertices& tube, LinearTubeOnce& linear_once,
                                            const BlendOptions& options, const FlowObserver& observer,
                                            FairRegionReport& report, std::vector<FaceIntersection> crossings) {
  if (crossings.empty() || options.method != FairMethod::flow ||
      !(options.flow.tangential_relaxation < options.crossing_retry_relaxation))
    return crossings;
  BlendOptions relaxed = options;
  relaxed.flow.tangential_relaxation = options.crossing_retry_relaxation;
  Mesh retried = mesh;
  retried.V = tube;
  FairRegionReport retried_report;
  try {
    retried_report = flow_tube(retried, topo, free, first_tube_face, tube, linear_once, relaxed, observer);
  } catch (const NumericalError&) {
    return crossings;
  }
  // Only a settled tube is a gain: an unsettled one, clear of the mesh, would be delivered NOT steady
  // where descent_fallback is off, and otherwise give way to the linear tube all the same.
  if (retried_report.linear || retried_report.flow.stop_reason != FlowStopReason::steady ||
      tube_crosses(retried, first_tube_face))
    return crossings;
  mesh.V = std::move(retried.V);
  char text[160];
  std::snprintf(text, sizeof text,
                "the %s flow's tube crossed the mesh; flowed again with its trial states relaxed tangentially (%.2g)",
                to_string(retried_report.flow_kind), options.crossing_retry_relaxation);
  retried_report.note = text + (retried_report.note.empty() ? "" : "; " + retried_report.note);
  report = std::move(retried_report);
  return {};
}

// Fairs the tube as the options' FairRegionOptions base says (flow_tube), once more relaxed where
// the flow's tube crosses the mesh (retry_relaxed); a tube clear of the mesh is weighed against the
// linear ∆^k tube from the same start (weigh_uncrossed_tube); where the flow's tube still crosses
// the mesh, that linear tube takes its place if it does not (labelled linear, with the reason).
// Throws NumericalError where the tube delivered would still cross the mesh (`mesh` then holds it).
FairRegionReport fair_tube(Mesh& mesh, const Topology& topo, const std::vector<int>& free, int first_tube_face,
                           const BlendOptions& options, const FlowObserver& observer) {
  const Vertices tube = mesh.V;
  LinearTubeOnce linear_once(mesh, topo, free, tube, options);
  FairRegionReport report = flow_tube(mesh, topo, free, first_tube_face, tube, linear_once, options, observer);
  const std::vector<FaceIntersection> crossings =
      retry_relaxed(mesh, topo, free, first_tube_face, tube, linear_once, options, observer, report,
                    tube_crossings(mesh, first_tube_face));
  if (crossings.empty())
    return weigh_uncrossed_tube(mesh, topo, free, first_tube_face, tube, linear_once, options, std::move(report));
  if (options.method != FairMethod::flow) throw TubeCrossing(crossing_message(crossings, first_tube_face, ""));
  std::optional<LinearTube>& linear = linear_once.get();
  if (linear && !tube_crosses(linear->mesh, first_tube_face))
    return keep_linear_tube(mesh, *linear, report, "crosses the mesh");
  const std::string linear_order = "∆" + std::to_string(static_cast<int>(report.supported) + 1);
  throw TubeCrossing(crossing_message(crossings, first_tube_face,
                                      linear ? ", and so does the linear " + linear_order + " tube from the same start"
                                             : ", and the linear " + linear_order +
                                                   " tube from the same start could not be solved"));
}

// Builds the tube between the loops of `mesh` (connectivity `topo`) as the options say, appends it
// to `mesh` and fairs it (fair_tube), filling the tube's and the fairing's fields of `report` and
// both borders' measurements. Throws TubeCrossing with `mesh` holding the crossing tube.
void blend_tube(Mesh& mesh, const Topology& topo, const std::vector<int>& loop_a, const std::vector<int>& loop_b,
                const BlendOptions& options, const FlowObserver& observer, BlendReport& report) {
  InitialPatch patch = initial_tube(mesh, topo, loop_a, loop_b, options, report);
  report.tube_vertices = patch.mesh.num_vertices() - mesh.num_vertices();
  report.tube_faces = patch.mesh.num_faces() - patch.first_patch_face;
  report.tube_rings = patch.tube.rings;
  // The input's faces come first, unchanged: they keep their texture coordinates, normals and
  // polygons, the tube's faces have none; vertex values are dropped, the tube's vertices have none.
  mesh.V = std::move(patch.mesh.V);
  mesh.F = std::move(patch.mesh.F);
  mesh.vertex_scalars.clear();
  mesh.vertex_colors.resize(0, 3);
  pad_face_attributes(mesh);

  // The tubed mesh's connectivity, built once by tube_patch: the fairing and the measures read it.
  const Topology& tubed = patch.topology;
  report.fair = fair_tube(mesh, tubed, patch.free_vertices, patch.first_patch_face, options, observer);
  report.a.border = measure_near_loop(mesh, tubed, loop_a, options.measure_rings, patch.free_vertices, loop_a);
  report.b.border = measure_near_loop(mesh, tubed, loop_b, options.measure_rings, patch.free_vertices, loop_b);
}

// blend_tube from Hermite rings (patch.tube.hermite), and where that tube crosses the mesh again
// from straight rings: Hermite rings between unlike loops, or loops a slab grazes, can pass through
// each other before any fairing; straight rings between the same points do not twist. Throws
// TubeCrossing naming both first crossings (`mesh` then holds the straight tube).
void blend_tube_either_rings(Mesh& mesh, const Mesh& input, const Topology& topo, const std::vector<int>& loop_a,
                             const std::vector<int>& loop_b, const BlendOptions& options,
                             const FlowObserver& observer, BlendReport& report) {
  try {
    blend_tube(mesh, topo, loop_a, loop_b, options, observer, report);
  } catch (const TubeCrossing& hermite) {
    if (!options.patch.tube.hermite) throw;
    mesh = input;
    BlendOptions straight = options;
    straight.patch.tube.hermite = false;
    try {
      blend_tube(mesh, topo, loop_a, loop_b, straight, observer, report);
    } catch (const TubeCrossing& e) {
      throw TubeCrossing(std::string(hermite.what()) + "; built again with straight rings: " + e.what());
    }
    report.straight_rings = true;
    report.fair.note = std::string("the tube from Hermite rings crossed the mesh (") + hermite.what() +
                       "); built again with straight rings" +
                       (report.fair.note.empty() ? "" : "; " + report.fair.note);
  }
}

// Where every tube at the requested continuity crosses the mesh (`why`): the linear tubes of the
// lower ones (∆², then ∆), from either rings, the first that does not cross, as fill and
// fair_region fall back (C2 → C1 → C0). Throws TubeCrossing where every one crosses (`mesh` then
// holds the last).
void blend_lower_linear_tube(Mesh& mesh, const Mesh& input, const Topology& topo, const std::vector<int>& loop_a,
                             const std::vector<int>& loop_b, const BlendOptions& options,
                             const FlowObserver& observer, BlendReport& report, const std::string& why) {
  for (int c = static_cast<int>(options.continuity) - 1; c >= 0; --c) {
    BlendOptions lower = options;
    lower.method = FairMethod::harmonic;
    lower.continuity = static_cast<Continuity>(c);
    mesh = input;
    report.straight_rings = false;
    try {
      blend_tube_either_rings(mesh, input, topo, loop_a, loop_b, lower, observer, report);
    } catch (const TubeCrossing&) {
      continue;
    }
    report.fair.requested = options.continuity;
    report.fair.crossing_fallback = true;
    report.fair.note = why + "; kept the linear ∆" + std::to_string(c + 1) + " tube, the first that does not cross" +
                       (report.fair.note.empty() ? "" : " (" + report.fair.note + ")");
    return;
  }
  throw TubeCrossing(why + "; and so does every linear tube down to ∆1");
}

// blend_tube_either_rings, and where that tube crosses the mesh, blend_lower_linear_tube.
void blend_any_tube(Mesh& mesh, const Mesh& input, const Topology& topo, const std::vector<int>& loop_a,
                    const std::vector<int>& loop_b, const BlendOptions& options, const FlowObserver& observer,
                    BlendReport& report) {
  try {
    blend_tube_either_rings(mesh, input, topo, loop_a, loop_b, options, observer, report);
  } catch (const TubeCrossing& crossing) {
    blend_lower_linear_tube(mesh, input, topo, loop_a, loop_b, options, observer, report, crossing.what());
  }
}

// Whether the G0 membrane of the tube, from Hermite rings or from straight ones, is dropped as
// pinched (initial_tube, BlendOptions::pinch_quality_ratio).
bool membrane_pinches(const Mesh& mesh, const Topology& topo, const std::vector<int>& loop_a,
                      const std::vector<int>& loop_b, const BlendOptions& options) {
  if (!options.patch.relax || options.pinch_quality_ratio <= 0) return false;
  for (bool hermite : {true, false}) {
    BlendOptions rings = options;
    rings.patch.tube.hermite = hermite;
    BlendReport tube;
    initial_tube(mesh, topo, loop_a, loop_b, rings, tube);
    if (tube.membrane_quality > 0 && !tube.relaxed) return true;
  }
  return false;
}

// Every tube, at the requested continuity and at the lower ones, crosses the mesh (`why`) and the
// membrane was dropped as pinched: the whole of blend_tube_either_rings and blend_lower_linear_tube
// again from the membrane. Its slivers are a poor start, but between loops a slab cut across a
// curved part the Hermite and straight rings run through the mesh where the membrane, which
// spans the loops by the shortest way, does not (docs/blend.md, "A pinched membrane as the last
// start"). Throws NumericalError naming both failures.
void blend_from_pinched_membrane(Mesh& mesh, const Mesh& input, const Topology& topo, const std::vector<int>& loop_a,
                                 const std::vector<int>& loop_b, const BlendOptions& options,
                                 const FlowObserver& observer, BlendReport& report, const std::string& why) {
  BlendOptions pinched = options;
  pinched.pinch_quality_ratio = 0;
  mesh = input;
  report.straight_rings = false;
  try {
    blend_any_tube(mesh, input, topo, loop_a, loop_b, pinched, observer, report);
  } catch (const NumericalError& e) {
    throw NumericalError(why + "; started from the pinched G0 membrane: " + e.what());
  }
  report.fair.note = "every tube without the G0 membrane, which pinches off, crosses the mesh (" + why +
                     "); started from the membrane" + (report.fair.note.empty() ? "" : "; " + report.fair.note);
}

// The larger of the two loops' normal angles across the tube's border (radians).
double largest_loop_angle(const BlendReport& report) {
  return std::max(report.a.border.max_normal_angle, report.b.border.max_normal_angle);
}

// Whether the tube in `report` folds back at either loop.
bool tube_folds_back(const BlendReport& report) { return folds_back(report.a) || folds_back(report.b); }

// Why the blend from the Hermite tube (`other`) replaces the delivered one from the membrane
// (`report`), or empty where it does not: where the membrane's tube folds back, or is the linear
// tube kept in place of a flow's that did (fair.flow_folded_back), the tube that turns the normal
// across the loops less; where the membrane's fell to a lower linear tube because the
// tubes above it crossed the mesh (crossing_fallback), one of a higher continuity that does not fold
// back.
std::string rebuilt_tube_gain(const BlendReport& report, const BlendReport& other) {
  constexpr double kDegrees = 180 / std::numbers::pi;
  const double folded = largest_loop_angle(report), angle = largest_loop_angle(other);
  char text[320];
  const bool tube_folded = tube_folds_back(report);
  if (tube_folded || report.fair.flow_folded_back) {
    if (!(angle < folded)) return "";
    std::snprintf(text, sizeof text,
                  "the %s from the G0 membrane folds back (%s the normal across the loops by %.1f deg); built again "
                  "from the Hermite tube, which turns it by %.1f deg",
                  tube_folded ? "tube" : "flow's tube",
                  tube_folded ? "it turns" : "the linear tube kept in its place turns", folded * kDegrees,
                  angle * kDegrees);
    return text;
  }
  if (!(other.fair.supported > report.fair.supported) || tube_folds_back(other)) return "";
  std::snprintf(text, sizeof text,
                "from the G0 membrane the tube fell to %s, the first lower linear tube that does not cross the "
                "mesh; built again from the Hermite tube, which gives %s",
                delivered_label(report.fair.supported, report.fair.linear).c_str(),
                delivered_label(other.fair.supported, other.fair.linear).c_str());
  return text;
}

// A delivered tube from the membrane that folds back at a loop, or that fell below the requested
// continuity because every tube above crossed the mesh (BlendOptions::rebuild_without_membrane):
// the blend again from the Hermite tube, which replaces `mesh` and `report` where it is the gain
// rebuilt_tube_gain names.
void blend_again_without_membrane(Mesh& mesh, const Mesh& input, const Topology& topo,
                                  const std::vector<int>& loop_a, const std::vector<int>& loop_b,
                                  const BlendOptions& options, const FlowObserver& observer, BlendReport& report) {
  BlendOptions hermite = options;
  hermite.patch.relax = false;
  Mesh again = input;
  BlendReport other = report;
  other.straight_rings = false;
  try {
    blend_any_tube(again, input, topo, loop_a, loop_b, hermite, observer, other);
  } catch (const TubeCrossing&) {
    return;
  }
  const std::string gain = rebuilt_tube_gain(report, other);
  if (gain.empty()) return;
  other.rebuilt_without_membrane = true;
  other.fair.note = gain + (other.fair.note.empty() ? "" : "; " + other.fair.note);
  mesh = std::move(again);
  report = std::move(other);
}

}  // namespace

bool folds_back(const BlendLoop& loop) {
  return detail::turns_back(loop.border.max_normal_angle) &&
         loop.border.max_normal_angle > 2 * loop.reference.max_normal_angle;
}

ContinuityMeasure measure_continuity_at_loop(const Mesh& mesh, const std::vector<int>& loop,
                                             const std::vector<int>& free_vertices, int rings) {
  return measure_near_loop(mesh, build_topology(mesh.F, mesh.num_vertices()), loop, rings, free_vertices, loop);
}

BlendReport blend_loops(Mesh& mesh, const BlendOptions& options, const FlowObserver& observer) {
  const auto start = detail::Clock::now();
  if (!(options.crossing_retry_relaxation >= 0 && options.crossing_retry_relaxation <= 1))
    throw InvalidArgument("blend_loops: crossing_retry_relaxation must lie in [0, 1], got " +
                          std::to_string(options.crossing_retry_relaxation));
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const std::vector<std::vector<int>> loops = boundary_loops(mesh.F, topo);
  const LoopPair pair = chosen_pair(mesh.V, loops, options);

  BlendReport report;
  report.loops_found = static_cast<int>(loops.size());
  report.automatic = options.loop_a < 0 && options.loop_b < 0;
  report.loop_distance = pair.distance;
  const std::vector<int>& loop_a = loops[pair.first];
  const std::vector<int>& loop_b = loops[pair.second];
  require_simple(loop_a, pair.first);
  require_simple(loop_b, pair.second);
  require_apart(loop_a, loop_b, pair);
  report.a.index = pair.first;
  report.a.length = static_cast<int>(loop_a.size());
  report.b.index = pair.second;
  report.b.length = static_cast<int>(loop_b.size());

  if (options.reference_ring > 0) {
    report.a.reference = reference_at_loop(mesh, topo, loop_a, options.reference_ring, options.measure_rings);
    report.b.reference = reference_at_loop(mesh, topo, loop_b, options.reference_ring, options.measure_rings);
  }
  const Mesh input = mesh;  // for another tube
  bool pinched_start = false;
  try {
    blend_any_tube(mesh, input, topo, loop_a, loop_b, options, observer, report);
  } catch (const TubeCrossing& e) {
    if (!membrane_pinches(input, topo, loop_a, loop_b, options)) throw;
    blend_from_pinched_membrane(mesh, input, topo, loop_a, loop_b, options, observer, report, e.what());
    pinched_start = true;  // every tube without the membrane crossed the mesh: none to build again
  }
  if (options.rebuild_without_membrane && report.relaxed && !pinched_start &&
      (tube_folds_back(report) || report.fair.flow_folded_back || report.fair.crossing_fallback))
    blend_again_without_membrane(mesh, input, topo, loop_a, loop_b, options, observer, report);
  report.seconds = detail::seconds_since(start);
  return report;
}

void keep_settled_flow(BlendOptions& options) {
  keep_settled_flow(static_cast<FairRegionOptions&>(options));
  options.weigh_against_linear_tube = false;
}

}  // namespace fairsurf
