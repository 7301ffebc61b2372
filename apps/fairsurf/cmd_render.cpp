// `fairsurf render MESH -o OUT.png [--color Q] [--range a,b] [--view V | --views V1,V2]
// [--size WxH] [--wire] [--title T] [--map M] [--focus x,y,z,r] [--compare MESH2 ...] [--force]`: draws the mesh (and
// the --compare meshes beside it, on one scale and one colour range) coloured by a per-vertex scalar.
#include "command.h"

#include <fairsurf/geometry/curvatures.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/render/render.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>

namespace fairsurf::cli {
namespace {

struct RenderArgs {
  std::string input;
  std::string output;
  std::string color = "H";
  std::string range;
  std::string view;
  std::string views;
  std::string size = "1200x900";
  std::string map = "auto";
  std::string title;
  std::string focus;
  std::vector<std::string> compare;
  bool wire = false;
  bool force = false;
};

constexpr std::array<const char*, 4> kCurvatures{"H", "K", "k1", "k2"};

bool is_curvature(const std::string& name) {
  return std::find(kCurvatures.begin(), kCurvatures.end(), name) != kCurvatures.end();
}

/// Splits "a,b,c" at commas.
std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
  return parts;
}

void parse_size(const std::string& text, RenderOptions& options) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,5})x(\d{1,5}))")))
    throw InvalidArgument("render: --size '" + text + "' is not WIDTHxHEIGHT (e.g. 1200x900)");
  options.width = std::stoi(m[1]);
  options.height = std::stoi(m[2]);
}

// The comma-separated numbers of `text` if there are exactly `count` of them, all finite.
std::optional<std::vector<double>> finite_numbers(const std::string& text, std::size_t count) {
  const std::vector<std::string> parts = split(text);
  if (parts.size() != count) return std::nullopt;
  std::vector<double> values;
  for (const std::string& part : parts) {
    const std::optional<double> value = number_in(part);
    if (!value || !std::isfinite(*value)) return std::nullopt;
    values.push_back(*value);
  }
  return values;
}

ColorRange parse_range(const std::string& text) {
  const auto ends = finite_numbers(text, 2);
  if (ends && (*ends)[0] < (*ends)[1]) return {(*ends)[0], (*ends)[1]};
  throw InvalidArgument("render: --range '" + text + "' is not two finite numbers a,b with a < b");
}

RenderFocus parse_focus(const std::string& text) {
  const auto xyzr = finite_numbers(text, 4);
  if (xyzr && (*xyzr)[3] > 0) return {Eigen::Vector3d((*xyzr)[0], (*xyzr)[1], (*xyzr)[2]), (*xyzr)[3]};
  throw InvalidArgument("render: --focus '" + text + "' is not x,y,z,r with finite numbers and r > 0");
}

std::vector<View> parse_views(const RenderArgs& args) {
  if (!args.view.empty() && !args.views.empty())
    throw InvalidArgument("render: give either --view or --views, not both");
  if (args.view.empty() && args.views.empty()) return {View::iso};
  std::vector<View> views;
  for (const std::string& name : split(args.view.empty() ? args.views : args.view))
    views.push_back(view_from_name(name));
  return views;
}

/// H, K, k1, k2 from the quadratic fits (curvatures.h; same sign convention as `fairsurf curvature`).
Eigen::VectorXd computed_curvature(const Mesh& mesh, const std::string& name) {
  SurfaceGeometry g = curvatures(mesh).geometry;
  return name == "H" ? g.H : name == "K" ? g.K : name == "k1" ? g.k1 : g.k2;
}

/// The per-vertex quantity `name` of `mesh`: a stored vertex property, else (H, K, k1, k2) computed;
/// empty for "none".
Eigen::VectorXd quantity_of(const Mesh& mesh, const std::string& name, const std::string& path) {
  if (name == "none") return {};
  if (const auto stored = mesh.vertex_scalars.find(name); stored != mesh.vertex_scalars.end()) return stored->second;
  if (is_curvature(name)) return computed_curvature(mesh, name);
  std::string available = "H, K, k1, k2, none";
  for (const auto& [stored_name, values] : mesh.vertex_scalars)
    if (!is_curvature(stored_name)) available += ", " + stored_name;
  throw InvalidArgument("render: unknown quantity '" + name + "' for '" + path + "' (available: " + available + ")");
}

/// auto: none for "none"; diverging for curvatures and for quantities with negative values;
/// sequential otherwise (non-negative quantities such as an energy density).
ColorMap choose_map(const std::string& map, const std::string& quantity, const std::vector<RenderMesh>& meshes) {
  if (map != "auto") return color_map_from_name(map);
  if (quantity == "none") return ColorMap::none;
  if (is_curvature(quantity)) return ColorMap::diverging;
  const bool negative = std::any_of(meshes.begin(), meshes.end(), [](const RenderMesh& m) {
    return (m.values.array() < 0).any();
  });
  return negative ? ColorMap::diverging : ColorMap::sequential;
}

void run_render(const RenderArgs& args) {
  RenderOptions options;
  parse_size(args.size, options);
  if (!args.range.empty()) options.range = parse_range(args.range);
  options.views = parse_views(args);
  if (!args.focus.empty()) options.focus = parse_focus(args.focus);
  options.wireframe = args.wire;
  options.title = args.title;
  options.quantity = args.color == "none" ? "" : args.color;

  std::vector<std::string> paths{args.input};
  paths.insert(paths.end(), args.compare.begin(), args.compare.end());
  check_outputs("render", {{"-o", args.output, OutputKind::png}}, {paths.begin(), paths.end()}, args.force);

  std::vector<Mesh> meshes;
  meshes.reserve(paths.size());
  for (const std::string& path : paths) {
    meshes.push_back(read_input(path));
    if (meshes.back().num_faces() == 0) throw InvalidMeshError("render: '" + path + "' has no faces: nothing to draw");
  }
  std::vector<RenderMesh> items;
  for (std::size_t k = 0; k < meshes.size(); ++k)
    items.push_back({&meshes[k], quantity_of(meshes[k], args.color, paths[k]),
                     paths.size() > 1 ? std::filesystem::path(paths[k]).filename().string() : ""});
  options.color_map = choose_map(args.map, args.color, items);

  const Image image = render(items, options);
  write_output([&] { write_png(args.output, image); });
  std::cout << "wrote " << args.output << ": " << image.width << "x" << image.height << ", " << args.color;
  if (options.color_map != ColorMap::none) {
    const ColorRange range = resolve_color_range(items, options);
    std::cout << " on [" << range.lo << ", " << range.hi << "] (" << color_map_name(options.color_map) << ")";
  }
  std::cout << "\n";
}

void setup_render(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Draw a mesh coloured by a per-vertex quantity into a PNG image");
  cmd->add_option("input", args->input, "Input mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("-o,--output", args->output, "Output image (.png)")->required();
  cmd->add_option("--color", args->color,
                  "Quantity: H, K, k1, k2 (stored, else computed), none, or any per-vertex property of the file")
      ->capture_default_str();
  cmd->add_option("--range", args->range, "Colour range a,b (default: automatic, robust 95% quantile)");
  cmd->add_option("--view", args->view, "One view: front, back, left, right, top, bottom, iso (default iso)");
  cmd->add_option("--views", args->views, "Several views side by side, comma-separated");
  cmd->add_option("--size", args->size, "Image size WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd->add_option("--map", args->map, "Colour map: auto, diverging, sequential, none")->capture_default_str();
  cmd->add_flag("--wire", args->wire, "Overlay the visible edges");
  cmd->add_option("--title", args->title, "Title drawn above the image");
  cmd->add_option("--focus", args->focus,
                  "x,y,z,r: draw only the faces inside this ball, centred and scaled to it (a filled hole up close)");
  cmd->add_option("--compare", args->compare,
                  "A further mesh drawn beside the first, same scale and colour range; one per --compare")
      ->allow_extra_args(false);
  cmd->add_flag("--force", args->force, "Allow the output to overwrite an input");
  cmd->callback([args] { run_render(*args); });
}

const CommandRegistration registration(80, setup_render);

}  // namespace
}  // namespace fairsurf::cli
