// render: meshes coloured by H, K, k1, k2 or given per-vertex values, side by side on one scale and
// one colour range, as `fairsurf render` (apps/fairsurf/cmd_render.cpp) draws them.
#include "arrays.h"
#include "functions.h"

#include <fairsurf/geometry/curvatures.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/render/render.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fairsurf::python {
namespace {

using namespace pybind11::literals;

bool is_curvature(const std::string& name) { return name == "H" || name == "K" || name == "k1" || name == "k2"; }

Eigen::VectorXd curvature_values(const Mesh& mesh, const std::string& name) {
  SurfaceGeometry g = curvatures(mesh).geometry;
  return name == "H" ? g.H : name == "K" ? g.K : name == "k1" ? g.k1 : g.k2;
}

Eigen::VectorXd array_values(const py::handle& values) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!a || a.ndim() != 1) throw py::value_error("color: per-vertex values must be a 1-D array");
  return Eigen::Map<const Eigen::VectorXd>(a.data(), a.shape(0));
}

// The values of mesh k of `count`: a named curvature, none, or the caller's array (one array for a
// single mesh, else a sequence of one per mesh). render() checks their length.
Eigen::VectorXd values_for(const Mesh& mesh, std::size_t k, std::size_t count, const py::handle& color) {
  if (py::isinstance<py::str>(color)) {
    const std::string name = color.cast<std::string>();
    if (name == "none") return {};
    if (!is_curvature(name))
      throw InvalidArgument("render: color must be H, K, k1, k2, none or per-vertex values, got '" + name + "'");
    return curvature_values(mesh, name);
  }
  if (count == 1 && py::isinstance<py::array>(color)) return array_values(color);
  const py::sequence per_mesh = py::reinterpret_borrow<py::sequence>(color);
  if (per_mesh.size() != count)
    throw py::value_error("color: give one array of values per mesh (" + std::to_string(count) + "), got " +
                          std::to_string(per_mesh.size()));
  return array_values(per_mesh[k]);
}

// As the CLI's --map auto: none for "none", diverging for curvatures and values with a negative one,
// sequential otherwise.
ColorMap choose_map(const std::string& map, const py::handle& color, const std::vector<RenderMesh>& items) {
  if (map != "auto") return color_map_from_name(map);
  if (py::isinstance<py::str>(color)) return color.cast<std::string>() == "none" ? ColorMap::none : ColorMap::diverging;
  for (const RenderMesh& item : items)
    if ((item.values.array() < 0).any()) return ColorMap::diverging;
  return ColorMap::sequential;
}

struct RenderArgs {
  py::object compare, color, range, path, focus;
  std::vector<std::string> views, labels;
  std::pair<int, int> size;
  std::string color_map, title;
  bool wireframe;
};

py::array render_binding(const py::handle& V, const py::handle& F, const RenderArgs& a) {
  std::vector<Mesh> meshes{to_mesh(V, F)};
  if (!a.compare.is_none())
    for (const py::handle pair : a.compare) meshes.push_back(to_mesh(pair[py::int_(0)], pair[py::int_(1)]));
  if (!a.labels.empty() && a.labels.size() != meshes.size())
    throw py::value_error("labels: give one label per mesh (" + std::to_string(meshes.size()) + ")");
  RenderOptions options;
  std::tie(options.width, options.height) = a.size;
  options.views.clear();
  for (const std::string& view : a.views) options.views.push_back(view_from_name(view));
  if (!a.range.is_none()) options.range = ColorRange{a.range[py::int_(0)].cast<double>(), a.range[py::int_(1)].cast<double>()};
  options.wireframe = a.wireframe;
  options.title = a.title;
  if (!a.focus.is_none()) {
    const auto xyzr = a.focus.cast<std::array<double, 4>>();
    options.focus = RenderFocus{Eigen::Vector3d(xyzr[0], xyzr[1], xyzr[2]), xyzr[3]};
  }
  options.quantity = py::isinstance<py::str>(a.color) && a.color.cast<std::string>() != "none" ? a.color.cast<std::string>() : "";
  std::vector<RenderMesh> items;
  for (std::size_t k = 0; k < meshes.size(); ++k)
    items.push_back({&meshes[k], values_for(meshes[k], k, meshes.size(), a.color), a.labels.empty() ? "" : a.labels[k]});
  options.color_map = choose_map(a.color_map, a.color, items);
  const std::optional<std::filesystem::path> path =
      a.path.is_none() ? std::nullopt : std::optional(a.path.cast<std::filesystem::path>());
  Image image;
  {
    py::gil_scoped_release release;
    image = render(items, options);
    if (path) write_png(*path, image);
  }
  py::array_t<std::uint8_t> pixels({image.height, image.width, 3});
  std::copy(image.rgb.begin(), image.rgb.end(), pixels.mutable_data());
  return pixels;
}

}  // namespace

void register_render_functions(py::module_& m) {
  m.def(
      "render",
      [](const py::handle& V, const py::handle& F, py::object color, std::vector<std::string> views,
         std::pair<int, int> size, py::object path, py::object range, std::string color_map, std::string title,
         bool wireframe, py::object compare, std::vector<std::string> labels, py::object focus) {
        return render_binding(V, F,
                              {compare, color, range, path, focus, views, labels, size, color_map, title, wireframe});
      },
      "V"_a, "F"_a, py::kw_only(), "color"_a = "H", "views"_a = std::vector<std::string>{"iso"},
      "size"_a = std::pair<int, int>{1200, 900}, "path"_a = py::none(), "range"_a = py::none(),
      "color_map"_a = "auto", "title"_a = "", "wireframe"_a = false, "compare"_a = py::none(),
      "labels"_a = std::vector<std::string>{}, "focus"_a = py::none(),
      "Draws the mesh (and the `compare` meshes beside it, one scale, one colour range) coloured by H, K, "
      "k1, k2, none or per-vertex values; returns the (height, width, 3) uint8 image and writes a PNG to "
      "`path` if given. `focus=(x, y, z, r)` draws only the faces inside that ball, framed on it.");
}

}  // namespace fairsurf::python
