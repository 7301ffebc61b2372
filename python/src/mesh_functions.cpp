#include "arrays.h"
#include "functions.h"
#include "reports.h"

#include <fairsurf/applications/scenes.h>
#include <fairsurf/geometry/curvatures.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/mesh_summary.h>
#include <fairsurf/mesh/validate.h>

#include <pybind11/stl/filesystem.h>

#include <filesystem>

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
  m.def("scene", &scene, "name"_a, py::kw_only(), "edge_length"_a = SceneOptions{}.edge_length,
        "The paper's test scenes (fig3, fig4, fig7, fig8, sphere-cap) as (V, F).");
}

}  // namespace fairsurf::python
