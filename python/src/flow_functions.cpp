// smooth, fill_holes, fair, blend: the flows. Options are set as the CLI's flags set them
// (apps/fairsurf/cmd_smooth.cpp, cmd_fill.cpp, region_fairing_args.cpp, cmd_blend.cpp), so that a
// call and the matching command compute the same result; the GIL is released during the run.
#include "arrays.h"
#include "functions.h"
#include "progress.h"
#include "reports.h"

#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/smooth.h>
#include <fairsurf/energy/energy_function.h>
#include <fairsurf/mesh/errors.h>

#include <pybind11/stl.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fairsurf::python {
namespace {

using namespace pybind11::literals;
using Functions = std::vector<std::string>;

// Runs `call` (a flow on `mesh`) without the GIL. A NumericalError leaves `mesh` at the flow's last
// accepted state (flow.h); it is raised as fairsurf.NumericalError carrying that state as its
// attribute `V`, as the CLI writes it to its output, so nothing computed is lost.
template <class Call>
auto keeping_last_state(Mesh& mesh, Call call) {
  try {
    py::gil_scoped_release release;
    return call();
  } catch (const NumericalError& e) {  // the GIL is held again here
    const py::object type = py::module_::import("fairsurf").attr("NumericalError");
    py::object error = type(e.what());
    error.attr("V") = to_numpy(std::move(mesh.V));
    PyErr_SetObject(type.ptr(), error.ptr());
    throw py::error_already_set();
  }
}

// A keyword given under its field's name or under its alias (the CLI flag's earlier name, kept for
// old scripts: f for functions, fixed for fixed_vertices), not both.
template <class T>
std::optional<T> named_or_alias(const char* call, const char* name, std::optional<T> value, const char* alias,
                                std::optional<T> alias_value) {
  if (value && alias_value)
    throw py::type_error(std::string(call) + "() got both " + name + " and its alias " + alias + "; give one");
  return value ? value : alias_value;
}

// The functions f_l, given as `functions` or `f`; ["H"] when neither is.
Functions functions_kwarg(const char* call, std::optional<Functions> functions, std::optional<Functions> f) {
  return named_or_alias(call, "functions", std::move(functions), "f", std::move(f)).value_or(Functions{"H"});
}

// The CLI's short names (`fairsurf smooth --flow`), then the library's.
FlowKind flow_kind(const std::string& name) {
  static const std::map<std::string, FlowKind> short_names{
      {"sixth", FlowKind::sixth_order}, {"diffusion", FlowKind::surface_diffusion}, {"mean", FlowKind::mean_curvature}};
  const auto found = short_names.find(name);
  return found != short_names.end() ? found->second : parse_flow_kind(name);
}

struct SmoothArgs {
  std::string flow;
  Functions functions;
  std::optional<double> time, tau;
  std::optional<int> steps;
  bool steady;
  double steady_tolerance;
  int max_steps, fixed_rings;
  std::optional<py::object> fixed_vertices;
  std::string solver;
};

// As `fairsurf smooth`: the scan defaults to the default time, or `steps` steps, a steady state, or
// `time` (set_smoothing_end).
SmoothOptions smooth_options(const SmoothArgs& a, const Mesh& mesh) {
  SmoothOptions o = scan_smoothing_options(mesh, flow_kind(a.flow));
  o.flow.functions = a.functions;
  o.flow.solver.kind = parse_linear_solver_kind(a.solver);
  o.flow.max_steps = a.max_steps;
  o.fixed_rings = a.fixed_rings;
  if (a.fixed_vertices) o.fixed_vertices = to_indices(*a.fixed_vertices, "fixed_vertices");
  set_smoothing_end(o, {a.steps.value_or(0), a.steady, a.steady_tolerance, a.time.value_or(0), a.tau.value_or(0)});
  return o;
}

py::tuple smooth_binding(const py::handle& V, const py::handle& F, const SmoothArgs& args, py::object callback) {
  if (int(args.steps.has_value()) + int(args.time.has_value()) + int(args.steady) > 1)
    throw InvalidArgument("smooth: give at most one of steps, time and steady");
  if (args.steps && *args.steps < 1) throw InvalidArgument("smooth: steps must be >= 1");
  if ((args.time && !(*args.time > 0)) || (args.tau && !(*args.tau > 0)))
    throw InvalidArgument("smooth: time and tau must be positive");
  Mesh mesh = to_mesh(V, F);
  SmoothOptions options = smooth_options(args, mesh);
  Progress progress(std::move(callback));
  progress.attach(options.flow);
  const FlowReport report = keeping_last_state(mesh, [&] { return smooth(mesh, options, progress.flow_observer()); });
  progress.rethrow();
  py::dict d("flow"_a = to_string(options.flow.kind_to_run()), "functions"_a = options.flow.functions);
  for (const auto item : to_dict(report)) d[item.first] = item.second;
  return py::make_tuple(to_numpy(std::move(mesh.V)), d);
}

// As the CLI's --keep-flow (apply_keep_flow): keep_settled_flow where asked (BlendOptions take their
// own overload), refused with the harmonic method, which runs no flow to keep.
template <class Options>
void apply_keep_flow(bool keep_flow, const char* call, Options& o) {
  if (!keep_flow) return;
  if (o.method == FairMethod::harmonic)
    throw InvalidArgument(std::string(call) + ": keep_flow keeps the flow's result; method 'harmonic' runs no flow");
  keep_settled_flow(o);
}

// As the CLI's --other-functions (apply_other_functions): weighed on the held-out rings, so refused
// where there are none (start 'flat') or no flow (method 'harmonic').
void apply_other_functions(const std::optional<Functions>& functions, const char* call, FairRegionOptions& o) {
  if (!functions || functions->empty()) return;
  if (o.method == FairMethod::harmonic)
    throw InvalidArgument(std::string(call) + ": other_functions weighs another flow; method 'harmonic' runs no flow");
  if (o.held_out_rings <= 0)
    throw InvalidArgument(std::string(call) +
                          ": other_functions is weighed on the held-out rings, which only start 'harmonic' has");
  parse_energy_functions(*functions);
  o.held_out_other_functions = *functions;
}

py::tuple fill_binding(const py::handle& V, const py::handle& F, const std::string& continuity,
                       const std::optional<py::object>& holes, const Functions& functions, const std::string& method,
                       int max_hole_edges, bool skip_largest, std::optional<int> max_steps, bool keep_flow,
                       const std::optional<Functions>& other_functions, py::object callback) {
  Mesh mesh = to_mesh(V, F);
  FillOptions o;
  o.continuity = parse_continuity(continuity);
  o.method = parse_fair_method(method);
  o.flow.functions = functions;
  if (max_steps) o.flow.max_steps = *max_steps;
  if (holes) o.holes = to_indices(*holes, "holes");
  o.max_hole_edges = max_hole_edges;
  o.skip_largest = skip_largest;
  apply_keep_flow(keep_flow, "fill_holes", o);
  apply_other_functions(other_functions, "fill_holes", o);
  Progress progress(std::move(callback));
  progress.attach(o.flow);
  FillReport report;
  {
    py::gil_scoped_release release;
    report = fill_holes(mesh, o, progress.fill_observer());
  }
  progress.rethrow();
  py::dict d("continuity"_a = continuity, "method"_a = method, "keep_flow"_a = keep_flow, "functions"_a = functions,
             "other_functions"_a = o.held_out_other_functions);
  for (const auto item : to_dict(report, progress.fill_steps())) d[item.first] = item.second;
  return py::make_tuple(to_numpy(std::move(mesh.V)), to_numpy(std::move(mesh.F)), d);
}

// A boolean mask of length #V, or vertex indices.
std::vector<int> region_vertices(const py::handle& region, int num_vertices) {
  const py::array a = py::array::ensure(region);
  if (!a || a.dtype().kind() != 'b') return to_indices(region, "region");
  if (a.ndim() != 1 || a.shape(0) != num_vertices)
    throw py::value_error("region: a boolean mask must have one entry per vertex (" + std::to_string(num_vertices) +
                          "), got " + (a.ndim() == 1 ? std::to_string(a.shape(0)) : std::to_string(a.ndim()) + "-D"));
  const auto mask = py::array_t<bool, py::array::c_style>::ensure(a);
  std::vector<int> indices;
  for (int i = 0; i < num_vertices; ++i)
    if (mask.data()[i]) indices.push_back(i);
  return indices;
}

struct FairingArgs {
  std::string continuity;
  Functions functions;
  std::string method;
  std::optional<int> max_steps;  ///< unset: the options' own limit
};

// As apply_region_fairing_args in the CLI: continuity, method, f and the step limit, where given,
// on `o` (a FairRegionOptions, or the BlendOptions that derive from it).
void set_fairing(const FairingArgs& a, FairRegionOptions& o) {
  o.continuity = parse_continuity(a.continuity);
  o.method = parse_fair_method(a.method);
  o.flow.functions = a.functions;
  if (a.max_steps) o.flow.max_steps = *a.max_steps;
}

py::tuple fair_binding(const py::handle& V, const py::handle& F, const py::handle& region, const FairingArgs& args,
                       const std::string& start, bool keep_flow, const std::optional<Functions>& other_functions,
                       py::object callback) {
  // 'flat' as the CLI's --start names it; 'input', this keyword's former value, stays as its alias.
  if (start != "harmonic" && start != "flat" && start != "input")
    throw InvalidArgument("fair: start must be 'harmonic' or 'flat' (alias 'input'), got '" + start + "'");
  Mesh mesh = to_mesh(V, F);
  const std::vector<int> free = region_vertices(region, mesh.num_vertices());
  FairRegionOptions options =
      start == "harmonic" ? FairRegionOptions::harmonic_started() : FairRegionOptions{};
  set_fairing(args, options);
  apply_keep_flow(keep_flow, "fair", options);
  apply_other_functions(other_functions, "fair", options);
  Progress progress(std::move(callback));
  progress.attach(options.flow);
  const FairRegionReport report =
      keeping_last_state(mesh, [&] { return fair_region(mesh, free, options, progress.flow_observer()); });
  progress.rethrow();
  py::dict d("functions"_a = args.functions, "other_functions"_a = options.held_out_other_functions,
             "keep_flow"_a = keep_flow);
  for (const auto item : to_dict(report)) d[item.first] = item.second;
  return py::make_tuple(to_numpy(std::move(mesh.V)), d);
}

// `all_pairs`: blend_all_loops, each blend's report in the list "blends", the pairs that could not be
// joined in "unjoined" (the `--log` of `blend --all`).
py::tuple blend_binding(const py::handle& V, const py::handle& F, const std::optional<std::pair<int, int>>& loops,
                        const FairingArgs& args, bool relax, bool keep_flow, bool all_pairs, py::object callback) {
  Mesh mesh = to_mesh(V, F);
  BlendOptions options;
  set_fairing(args, options);
  options.patch.relax = relax;
  apply_keep_flow(keep_flow, "blend", options);
  if (loops && all_pairs) throw InvalidArgument("blend: all_pairs chooses each pair itself; leave loops None");
  if (loops) std::tie(options.loop_a, options.loop_b) = *loops;
  Progress progress(std::move(callback));
  progress.attach(options.flow);
  py::dict d("functions"_a = args.functions, "keep_flow"_a = keep_flow, "all"_a = all_pairs);
  if (all_pairs) {
    const BlendAllReport all =
        keeping_last_state(mesh, [&] { return blend_all_loops(mesh, options, progress.flow_observer()); });
    progress.rethrow();
    py::list blends, unjoined;
    for (const BlendReport& report : all.blends) blends.append(to_dict(report));
    for (const UnjoinedLoops& pair : all.unjoined)
      unjoined.append(py::dict("loop_a"_a = pair.loop_a, "loop_b"_a = pair.loop_b, "length_a"_a = pair.length_a,
                               "length_b"_a = pair.length_b, "why"_a = pair.why, "repairable"_a = pair.repairable));
    d["blends"] = blends;
    d["unjoined"] = unjoined;
    d["loops_left"] = all.loops_left;
    d["seconds"] = all.seconds;
  } else {
    const BlendReport report =
        keeping_last_state(mesh, [&] { return blend_loops(mesh, options, progress.flow_observer()); });
    progress.rethrow();
    for (const auto item : to_dict(report)) d[item.first] = item.second;
  }
  return py::make_tuple(to_numpy(std::move(mesh.V)), to_numpy(std::move(mesh.F)), d);
}

}  // namespace

void register_flow_functions(py::module_& m) {
  // `functions` and `fixed_vertices` also answer to their aliases `f` and `fixed` (named_or_alias).
  m.def(
      "smooth",
      [](const py::handle& V, const py::handle& F, std::string flow, std::optional<Functions> functions,
         std::optional<Functions> f, std::optional<double> time, std::optional<int> steps, bool steady,
         double steady_tolerance, std::optional<double> tau, int max_steps, std::optional<py::object> fixed_vertices,
         std::optional<py::object> fixed, int fixed_rings, std::string solver, py::object progress) {
        return smooth_binding(V, F,
                              {flow, functions_kwarg("smooth", functions, f), time, tau, steps, steady,
                               steady_tolerance, max_steps, fixed_rings,
                               named_or_alias("smooth", "fixed_vertices", fixed_vertices, "fixed", fixed), solver},
                              std::move(progress));
      },
      "V"_a, "F"_a, py::kw_only(), "flow"_a = "sixth", "functions"_a = py::none(), "f"_a = py::none(),
      "time"_a = py::none(), "steps"_a = py::none(), "steady"_a = false, "steady_tolerance"_a = 1.0,
      "tau"_a = py::none(), "max_steps"_a = 1000, "fixed_vertices"_a = py::none(), "fixed"_a = py::none(),
      "fixed_rings"_a = 3, "solver"_a = "mumps", "progress"_a = py::none(),
      "Smooths the whole mesh with a geometric flow, as `fairsurf smooth`; returns (V, report).");
  m.def(
      "fill_holes",
      [](const py::handle& V, const py::handle& F, const std::string& continuity,
         const std::optional<py::object>& holes, std::optional<Functions> functions, std::optional<Functions> f,
         const std::string& method, int max_hole_edges, bool skip_largest, std::optional<int> max_steps,
         bool keep_flow, std::optional<Functions> other_functions, py::object progress) {
        return fill_binding(V, F, continuity, holes, functions_kwarg("fill_holes", functions, f), method,
                            max_hole_edges, skip_largest, max_steps, keep_flow, other_functions, std::move(progress));
      },
      "V"_a, "F"_a, py::kw_only(), "continuity"_a = "G2", "holes"_a = py::none(), "functions"_a = py::none(),
      "f"_a = py::none(), "method"_a = "flow", "max_hole_edges"_a = 0, "skip_largest"_a = false,
      "max_steps"_a = py::none(), "keep_flow"_a = false, "other_functions"_a = py::none(), "progress"_a = py::none(),
      "Fills boundary loops with G2 (G1, G0) boundary data, as `fairsurf fill`; returns (V, F, report).");
  m.def(
      "fair",
      [](const py::handle& V, const py::handle& F, const py::handle& region, std::string continuity,
         std::optional<Functions> functions, std::optional<Functions> f, std::string method,
         std::optional<int> max_steps, std::string start, bool keep_flow, std::optional<Functions> other_functions,
         py::object progress) {
        return fair_binding(V, F, region, {continuity, functions_kwarg("fair", functions, f), method, max_steps},
                            start, keep_flow, other_functions, std::move(progress));
      },
      "V"_a, "F"_a, "region"_a, py::kw_only(), "continuity"_a = "G2", "functions"_a = py::none(),
      "f"_a = py::none(), "method"_a = "flow", "max_steps"_a = py::none(), "start"_a = "harmonic",
      "keep_flow"_a = false, "other_functions"_a = py::none(), "progress"_a = py::none(),
      "Fairs a region (boolean mask or vertex indices), as `fairsurf fair`; returns (V, report).");
  m.def(
      "blend",
      [](const py::handle& V, const py::handle& F, std::optional<std::pair<int, int>> loops, std::string continuity,
         std::optional<Functions> functions, std::optional<Functions> f, std::string method,
         std::optional<int> max_steps, bool relax, bool keep_flow, bool all_pairs, py::object progress) {
        return blend_binding(V, F, loops, {continuity, functions_kwarg("blend", functions, f), method, max_steps},
                             relax, keep_flow, all_pairs, std::move(progress));
      },
      "V"_a, "F"_a, py::kw_only(), "loops"_a = py::none(), "continuity"_a = "G2", "functions"_a = py::none(),
      "f"_a = py::none(), "method"_a = "flow", "max_steps"_a = py::none(), "relax"_a = true,
      "keep_flow"_a = false, "all_pairs"_a = false, "progress"_a = py::none(),
      "Joins two boundary loops by a fair tube, as `fairsurf blend`; returns (V, F, report). all_pairs=True "
      "joins the closest pair, then the closest pair left, ..., as `fairsurf blend --all` (report['blends']).");
}

}  // namespace fairsurf::python
