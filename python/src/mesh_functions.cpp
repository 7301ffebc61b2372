#include "arrays.h"
#include "functions.h"
#include "reports.h"

#include <fairsurf/applications/repair.h>
#include <fairsurf/applications/scenes.h>
#include <fairsurf/geometry/curvatures.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_summary.h>
#include <fairsurf/mesh/validate.h>

#include <pybind11/stl/filesystem.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

namespace fairsurf::python {
namespace {

using namespace pybind11::literals;

py::tuple read(const std::filesystem::path& path) {
  Mesh mesh;
  {
    py::gil_scoped_release release;
    mesh = read_mesh(path);
  }
  return to_tuple(std::move(mesh));
}

void write(const std::filesystem::path& path, const py::handle& V, const py::handle& F, bool binary) {
  const Mesh mesh = to_mesh(V, F);
  py::gil_scoped_release release;
  write_mesh(path, mesh, WriteOptions{binary});
}

py::dict info(const py::handle& V, const py::handle& F) {
  const Mesh mesh = to_mesh(V, F);
  ValidationReport report;
  MeshSummary summary;
  {
    py::gil_scoped_release release;
    report = validate(mesh);
    summary = summarize(mesh, report);
  }
  return to_dict(summary, report);
}

py::dict curvature(const py::handle& V, const py::handle& F) {
  const Mesh mesh = to_mesh(V, F);
  Curvatures c;
  {
    py::gil_scoped_release release;
    c = curvatures(mesh);
  }
  py::array_t<bool> well_posed(static_cast<py::ssize_t>(c.status.size()));
  bool* ok = well_posed.mutable_data();
  for (std::size_t i = 0; i < c.status.size(); ++i) ok[i] = c.status[i] == FitStatus::kOk;
  SurfaceGeometry& g = c.geometry;
  return py::dict("H"_a = to_numpy(std::move(g.H)), "K"_a = to_numpy(std::move(g.K)),
                  "k1"_a = to_numpy(std::move(g.k1)), "k2"_a = to_numpy(std::move(g.k2)),
                  "normal"_a = to_numpy(std::move(g.normal)), "area"_a = to_numpy(std::move(g.area)),
                  "well_posed"_a = well_posed);
}

// Refuses the negative values `fairsurf repair`'s flags refuse.
void require_repair_values(const RepairOptions& o) {
  const std::pair<const char*, double> values[] = {{"merge_tolerance", o.merge_tolerance},
                                                   {"stitch_tolerance", o.stitch_tolerance},
                                                   {"needle_tolerance", o.needle_tolerance},
                                                   {"min_component_faces", o.min_component_faces}};
  for (const auto& [name, value] : values) {
    if (value >= 0) continue;
    char text[120];
    std::snprintf(text, sizeof text, "repair: %s must be at least 0, not %g", name, value);
    throw InvalidArgument(text);
  }
}

py::tuple repair_binding(const py::handle& V, const py::handle& F, const RepairOptions& options) {
  Mesh mesh = to_mesh(V, F);
  RepairReport report;
  ValidationReport remaining;
  {
    py::gil_scoped_release release;
    report = repair(mesh, options);
    remaining = validate(mesh);
  }
  py::dict d = to_dict(report, remaining);
  py::tuple VF = to_tuple(std::move(mesh));
  return py::make_tuple(VF[0], VF[1], d);
}

py::tuple scene(const std::string& name, double edge_length) {
  Scene s;
  {
    py::gil_scoped_release release;
    s = make_scene(name, SceneOptions{edge_length});
  }
  return to_tuple(std::move(s.mesh));
}

}  // namespace

void register_mesh_functions(py::module_& m) {
  m.def("read_mesh", &read, "path"_a,
        "Reads OBJ, OFF, PLY or STL (by extension) into (V float64 #V×3, F int32 #F×3), file order kept.");
  m.def("write_mesh", &write, "path"_a, "V"_a, "F"_a, py::kw_only(), "binary"_a = true,
        "Writes V, F atomically in the format of the extension (PLY and STL binary unless binary=False).");
  m.def("info", &info, "V"_a, "F"_a,
        "Counts, topology, extent and validation findings: the fields of `fairsurf info --json`.");
  m.def("curvature", &curvature, "V"_a, "F"_a,
        "Per-vertex H (= -1/R on a sphere with outward normals), K, k1 >= k2, unit normal, area and "
        "well_posed (the fit's status) from the local quadratic fits.");
  m.def(
      "repair",
      [](const py::handle& V, const py::handle& F, bool merge_duplicate_vertices, double merge_tolerance,
         bool stitch_borders, double stitch_tolerance, bool remove_duplicate_faces, bool fix_degenerate_faces,
         double needle_tolerance, bool split_non_manifold_vertices, bool keep_border_pinches,
         bool resolve_non_manifold_edges, bool orient, int min_component_faces, bool remove_loose_fins,
         bool remove_unreferenced_vertices) {
        RepairOptions o;
        o.merge_duplicate_vertices = merge_duplicate_vertices;
        o.merge_tolerance = merge_tolerance;
        o.stitch_borders = stitch_borders;
        o.stitch_tolerance = stitch_tolerance;
        o.remove_duplicate_faces = remove_duplicate_faces;
        o.fix_degenerate_faces = fix_degenerate_faces;
        o.needle_tolerance = needle_tolerance;
        o.split_non_manifold_vertices = split_non_manifold_vertices;
        o.keep_border_pinches = keep_border_pinches;
        o.resolve_non_manifold_edges = resolve_non_manifold_edges;
        o.orient = orient;
        o.remove_small_components = min_component_faces > 0;  // as --min-component-faces 0
        o.min_component_faces = min_component_faces;
        o.remove_loose_fins = remove_loose_fins;
        o.remove_unreferenced_vertices = remove_unreferenced_vertices;
        require_repair_values(o);
        return repair_binding(V, F, o);
      },
      "V"_a, "F"_a, py::kw_only(), "merge_duplicate_vertices"_a = true, "merge_tolerance"_a = 0.0,
      "stitch_borders"_a = true, "stitch_tolerance"_a = 0.0, "remove_duplicate_faces"_a = true,
      "fix_degenerate_faces"_a = true, "needle_tolerance"_a = RepairOptions{}.needle_tolerance,
      "split_non_manifold_vertices"_a = true, "keep_border_pinches"_a = false, "resolve_non_manifold_edges"_a = true,
      "orient"_a = true, "min_component_faces"_a = RepairOptions{}.min_component_faces,
      "remove_loose_fins"_a = true, "remove_unreferenced_vertices"_a = true,
      "Repairs the mesh as `fairsurf repair` (keep_border_pinches=True: as `fairsurf fill --repair`); "
      "returns (V, F, report): the fields of `repair --json`, vertex_origin (each output vertex's input "
      "row) and vertex_destination (each input vertex's output row, -1 where removed).");
  m.def("scene", &scene, "name"_a, py::kw_only(), "edge_length"_a = SceneOptions{}.edge_length,
        "The paper's test scenes (fig3, fig4, fig7, fig8, sphere-cap) as (V, F).");
}

}  // namespace fairsurf::python
