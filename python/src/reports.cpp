#include "reports.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace fairsurf::python {

using namespace pybind11::literals;

py::dict to_dict(const StepRecord& r) {
  py::dict d("step"_a = r.step, "attempt"_a = r.attempt, "time"_a = r.time, "tau"_a = r.tau,
             "energy"_a = r.energy,
             // None, not NaN, where there is no model (the time-stepped flow): NaN != NaN in a dict.
             "predicted_decrease"_a = std::isnan(r.predicted_decrease) ? py::object(py::none())
                                                                       : py::object(py::float_(r.predicted_decrease)),
             "max_displacement"_a = r.max_displacement,
             "held_back_vertices"_a = r.held_back_vertices, "clipped_vertices"_a = r.clipped_vertices,
             "max_velocity"_a = r.max_velocity,
             "accepted"_a = r.accepted, "solver_iterations"_a = r.solver_iterations,
             "backward_error"_a = r.backward_error,
             "seconds"_a = py::dict("fit"_a = r.fit_seconds, "assembly"_a = r.assembly_seconds,
                                    "factorize"_a = r.factorize_seconds, "solve"_a = r.solve_seconds));
  if (!r.accepted) d["rejection"] = py::dict("reason"_a = to_string(r.rejection), "detail"_a = r.detail);
  return d;
}

py::dict to_dict(const FlowReport& r) {
  py::list steps;
  for (const StepRecord& record : r.records) steps.append(to_dict(record));
  return py::dict("stop_reason"_a = to_string(r.stop_reason), "accepted_steps"_a = r.accepted_steps,
                  "rejected_steps"_a = r.rejected_steps, "time"_a = r.time, "next_tau"_a = r.tau,
                  "initial_energy"_a = r.initial_energy, "final_energy"_a = r.final_energy,
                  "initial_max_velocity"_a = r.initial_max_velocity,
                  "final_max_velocity"_a = r.final_max_velocity, "length_scale"_a = r.length_scale,
                  "curvature_scale"_a = r.curvature_scale, "free_vertices"_a = r.free_vertices,
                  "supported_continuity"_a = to_string(r.supported),
                  "well_posedness"_a = py::dict("vertices"_a = r.well_posedness.vertices,
                                                "violating_vertices"_a = r.well_posedness.violating_vertices),
                  "steps"_a = steps);
}

py::dict to_dict(const ContinuityMeasure& m) {
  return py::dict("border_vertices"_a = m.border_vertices, "max_normal_angle"_a = m.max_normal_angle,
                  "mean_normal_angle"_a = m.mean_normal_angle,
                  "max_mean_curvature_jump"_a = m.max_mean_curvature_jump,
                  "mean_mean_curvature_jump"_a = m.mean_mean_curvature_jump);
}

py::dict to_dict(const FairRegionReport& r) {
  py::dict d("free_vertices"_a = r.free_vertices, "method"_a = to_string(r.method),
             "continuity_requested"_a = to_string(r.requested),
             "continuity_supported"_a = to_string(r.supported),
             "delivered"_a = delivered_label(r.supported, r.linear), "note"_a = r.note,
             "continuity_measured"_a = to_dict(r.continuity), "seconds"_a = r.seconds);
  if (r.method == FairMethod::flow) {
    d["flow"] = to_string(r.flow_kind);
    d["harmonic_start_solves"] = r.harmonic.iterations;
    d["held_out_flow_error"] = r.held_out_flow_error;
    d["held_out_linear_error"] = r.held_out_linear_error;
    d["held_out_two_ring_flow_error"] = r.held_out_two_ring_flow_error;
    d["two_ring_boundary_fits"] = r.two_ring_boundary_fits;
    d["held_out_other_flow_error"] = r.held_out_other_flow_error;
    d["held_out_other_two_ring_flow_error"] = r.held_out_other_two_ring_flow_error;
    d["other_functions_chosen"] = r.other_functions;
    d["checks_chose_linear"] = r.checks_chose_linear;
    d["flow_folded_back"] = r.flow_folded_back;
  }
  if (!r.parts.empty()) {
    py::list parts;
    for (const FairRegionReport& part : r.parts) parts.append(to_dict(part));
    d["parts"] = parts;
  }
  if (r.has_flow_report()) {
    for (const auto item : to_dict(r.flow)) d[item.first] = item.second;
  } else {
    d["harmonic"] = py::dict("order"_a = r.harmonic.order, "backward_error"_a = r.harmonic.backward_error);
    if (r.method == FairMethod::flow)  // of the flow that was weighed or tried, as the CLI's log
      d["well_posedness"] = py::dict("vertices"_a = r.flow.well_posedness.vertices,
                                     "violating_vertices"_a = r.flow.well_posedness.violating_vertices);
  }
  return d;
}

namespace {

py::dict loop_dict(const BlendLoop& loop) {
  return py::dict("index"_a = loop.index, "length"_a = loop.length,
                  "continuity_measured"_a = to_dict(loop.border),
                  "continuity_reference"_a = to_dict(loop.reference));
}

py::dict hole_dict(const HoleReport& r) {
  return py::dict("index"_a = r.index, "border_edges"_a = r.border_edges, "status"_a = to_string(r.status),
                  "reason"_a = r.reason, "filled_with"_a = r.filled_with, "vertices_added"_a = r.vertices_added,
                  "faces_added"_a = r.faces_added, "patch_shared_with"_a = r.patch_shared_with,
                  "pinched_by"_a = r.pinched_by, "around_a_face"_a = r.around_a_face,
                  "hanging_piece_at"_a = r.hanging_piece_at,
                  "lone_triangle"_a = r.lone_triangle,
                  "requested_continuity"_a = to_string(r.requested),
                  "supported_continuity"_a = to_string(r.supported),
                  "delivered"_a = delivered_label(r.supported, r.linear), "linear"_a = r.linear,
                  "held_out_flow_error"_a = r.held_out_flow_error,
                  "held_out_linear_error"_a = r.held_out_linear_error,
                  "held_out_two_ring_flow_error"_a = r.held_out_two_ring_flow_error,
                  "held_out_other_flow_error"_a = r.held_out_other_flow_error,
                  "held_out_other_two_ring_flow_error"_a = r.held_out_other_two_ring_flow_error,
                  "other_functions_chosen"_a = r.other_functions,
                  "held_out_refined_linear_error"_a = r.held_out_refined_linear_error,
                  "held_out_roughness"_a = r.held_out_roughness,
                  "refined_start"_a = r.refined_start, "unfaired"_a = r.unfaired,
                  "checks_chose_linear"_a = r.checks_chose_linear,
                  "flow_folded_back"_a = r.flow_folded_back,
                  "two_ring_boundary_fits"_a = r.two_ring_boundary_fits, "note"_a = r.note, "steps"_a = r.steps,
                  "harmonic_solves"_a = r.harmonic_solves, "seconds"_a = r.seconds,
                  "final_max_velocity"_a = r.final_max_velocity,
                  "well_posedness"_a = py::dict("vertices"_a = r.well_posedness.vertices,
                                                "violating_vertices"_a = r.well_posedness.violating_vertices),
                  "continuity"_a = to_dict(r.continuity));
}

}  // namespace

py::dict to_dict(const BlendReport& r) {
  return py::dict("loops_found"_a = r.loops_found, "automatic"_a = r.automatic,
                  "loop_distance"_a = r.loop_distance, "loop_a"_a = loop_dict(r.a), "loop_b"_a = loop_dict(r.b),
                  "tube_vertices"_a = r.tube_vertices, "tube_faces"_a = r.tube_faces,
                  "tube_rings"_a = r.tube_rings, "hermite_quality"_a = r.hermite_quality,
                  "membrane_quality"_a = r.membrane_quality, "relaxed"_a = r.relaxed,
                  "straight_rings"_a = r.straight_rings,
                  "rebuilt_without_membrane"_a = r.rebuilt_without_membrane,
                  "fair"_a = to_dict(r.fair), "seconds"_a = r.seconds);
}

py::dict to_dict(const FillReport& report, const std::map<int, py::list>& steps) {
  py::list holes;
  for (const HoleReport& r : report.holes) {
    py::dict d = hole_dict(r);
    // The steps of a joint fill are logged under its first hole, as the CLI's log does.
    const int group = r.filled_with.empty() ? r.index : std::min(r.index, r.filled_with.front());
    if (const auto found = steps.find(group); found != steps.end()) d["steps_log"] = found->second;
    holes.append(d);
  }
  return py::dict("filled"_a = report.filled, "skipped"_a = report.skipped, "failed"_a = report.failed,
                  "seconds"_a = report.seconds, "holes"_a = holes);
}

namespace {

py::object examples(const Finding& f) {
  if (f.element != Element::edge) return py::cast(f.examples);
  py::list pairs;
  for (std::size_t i = 0; i + 1 < f.examples.size(); i += 2) pairs.append(py::make_tuple(f.examples[i], f.examples[i + 1]));
  return pairs;
}

py::object bounding_box(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return py::none();
  const Eigen::Vector3d lo = box.min(), hi = box.max();
  return py::dict("min"_a = py::make_tuple(lo.x(), lo.y(), lo.z()), "max"_a = py::make_tuple(hi.x(), hi.y(), hi.z()));
}

}  // namespace

py::dict to_dict(const MeshSummary& s, const ValidationReport& report) {
  py::dict d("vertices"_a = s.vertices, "referenced_vertices"_a = s.referenced_vertices, "faces"_a = s.faces,
             "edges"_a = s.edges, "boundary_edges"_a = s.boundary_edges,
             "boundary_loops"_a = s.boundary_loop_lengths, "lone_triangles"_a = s.lone_triangles,
             "components"_a = s.components,
             "euler_characteristic"_a = s.euler_characteristic,
             "genus"_a = s.genus ? py::object(py::int_(*s.genus)) : py::none(),
             "bounding_box"_a = bounding_box(s.bounding_box), "mean_edge_length"_a = s.mean_edge_length,
             "manifold"_a = report.manifold(), "orientable"_a = report.orientable(),
             "no_faces"_a = report.no_faces, "valid"_a = report.is_valid());
  py::dict example_dict;
  for (const auto& named : named_findings(report)) {
    d[py::str(named.key)] = named.finding->count;
    if (named.finding->count > 0) example_dict[py::str(named.key)] = examples(*named.finding);
  }
  d["examples"] = example_dict;
  return d;
}

py::dict to_dict(const RepairReport& report, const ValidationReport& remaining) {
  py::dict d;
  for (const NamedCount& count : named_counts(report)) d[py::str(count.key)] = count.value;
  d["changed"] = report.changed();
  py::dict findings;  // as the CLI: only those left
  for (const auto& named : named_findings(remaining))
    if (named.finding->count > 0) findings[py::str(named.key)] = named.finding->count;
  d["remaining_findings"] = findings;
  const auto int_array = [](const std::vector<int>& values) {
    py::array_t<int> array(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
  };
  d["vertex_origin"] = int_array(report.vertex_origin);
  d["vertex_destination"] = int_array(report.vertex_destination);
  return d;
}

}  // namespace fairsurf::python
