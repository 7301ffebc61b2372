// The library's reports as dicts with the fields, names and nesting of the CLI's JSON logs
// (apps/fairsurf: flow_log.cpp, cmd_fill.cpp, region_fairing_args.cpp, cmd_blend.cpp, cmd_info.cpp,
// cmd_repair.cpp),
// without the fields that name files or the command (input, output, command, repair).
// tests/python/test_reports.py compares the keys with the CLI's logs.
#pragma once

#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/repair.h>
#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/mesh_summary.h>
#include <fairsurf/mesh/validate.h>

#include <pybind11/pybind11.h>

#include <map>
#include <vector>

namespace fairsurf::python {

namespace py = pybind11;

py::dict to_dict(const StepRecord& record);
py::dict to_dict(const FlowReport& report);
py::dict to_dict(const ContinuityMeasure& measure);
py::dict to_dict(const FairRegionReport& report);
py::dict to_dict(const BlendReport& report);
/// `steps` holds each jointly faired group's step dicts, by the group's first hole.
py::dict to_dict(const FillReport& report, const std::map<int, py::list>& steps);
py::dict to_dict(const MeshSummary& summary, const ValidationReport& validation);
/// The fields of `fairsurf repair --json` (`remaining`: the repaired mesh's findings), and
/// "vertex_origin" and "vertex_destination" (RepairReport's, as int32 arrays).
py::dict to_dict(const RepairReport& report, const ValidationReport& remaining);

}  // namespace fairsurf::python
