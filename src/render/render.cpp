// render(): validation, the colour range, the panel layout and one shared camera scale; the pixels
// themselves come from render_raster.cpp and the text from render_text.cpp.
#include "render_internal.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fairsurf {
namespace {

using render_detail::PanelCamera;

constexpr double kFill = 0.92;  // fraction of a panel the widest projection spans

void validate(const std::vector<RenderMesh>& meshes, const RenderOptions& options) {
  if (meshes.empty()) throw InvalidArgument("render: no mesh to draw");
  if (options.views.empty()) throw InvalidArgument("render: no view to draw");
  if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
    throw InvalidArgument("render: image size " + std::to_string(options.width) + "x" +
                          std::to_string(options.height) + " is outside 1x1 .. 16384x16384");
  if (options.supersampling < 1 || options.supersampling > 8)
    throw InvalidArgument("render: supersampling " + std::to_string(options.supersampling) +
                          " is outside 1 .. 8");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const std::string which = "render: mesh " + std::to_string(m);
    if (meshes[m].mesh == nullptr) throw InvalidArgument(which + " is null");
    const Mesh& mesh = *meshes[m].mesh;
    const auto n = meshes[m].values.size();
    if (n != 0 && n != mesh.num_vertices())
      throw InvalidArgument(which + " has " + std::to_string(n) + " values for " +
                            std::to_string(mesh.num_vertices()) + " vertices");
    for (int f = 0; f < mesh.num_faces(); ++f)
      for (int k = 0; k < 3; ++k)
        if (mesh.F(f, k) < 0 || mesh.F(f, k) >= mesh.num_vertices())
          throw InvalidMeshError(which + ": face " + std::to_string(f) + " has vertex index " +
                                 std::to_string(mesh.F(f, k)) + " outside [0, " +
                                 std::to_string(mesh.num_vertices()) + ")");
  }
}

/// The nearest-rank q-quantile of `values` (not empty).
double quantile(std::vector<double> values, double q) {
  const auto rank = static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank), values.end());
  return values[rank];
}

/// Projected bounding box of a mesh's finite vertices in camera (x, y); empty if there are none.
struct Extent {
  Eigen::Vector2d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Eigen::Vector2d hi = -lo;
  bool empty() const { return !(lo.x() <= hi.x()); }
};

Extent projected_extent(const Mesh& mesh, const Eigen::Matrix3d& rotation) {
  Extent e;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (!mesh.V.row(v).allFinite()) continue;
    const Eigen::Vector2d c = (rotation * mesh.V.row(v).transpose()).head<2>();
    e.lo = e.lo.cwiseMin(c);
    e.hi = e.hi.cwiseMax(c);
  }
  return e;
}

/// Where things go in the image, in pixels. Meshes go across and views down, except that a single
/// mesh's views go across.
struct Layout {
  int title_h = 0;      ///< band at the top
  int bar_h = 0;        ///< band at the bottom
  int label_h = 0;      ///< band at the top of every panel
  int rows = 0, cols = 0;
  int width = 0, height = 0;
  bool views_across = false;
  int row_of(int mesh, int view) const { return views_across ? mesh : view; }
  int col_of(int mesh, int view) const { return views_across ? view : mesh; }
  int panel_x(int c) const { return c * width / cols; }
  int panel_y(int r) const { return title_h + r * (height - title_h - bar_h) / rows; }
  int panel_w(int c) const { return panel_x(c + 1) - panel_x(c); }
  int panel_h(int r) const { return panel_y(r + 1) - panel_y(r); }
  int draw_h(int r) const { return panel_h(r) - label_h; }
};

bool has_color_bar(const RenderOptions& options) {
  return options.color_bar && options.color_map != ColorMap::none;
}

std::string panel_label(const RenderMesh& mesh, View view, const RenderOptions& options) {
  std::string label = mesh.label;
  if (options.views.size() > 1) label += (label.empty() ? "" : " — ") + view_name(view);
  return label;
}

Layout make_layout(const std::vector<RenderMesh>& meshes, const RenderOptions& options) {
  Layout l;
  l.width = options.width;
  l.height = options.height;
  l.views_across = meshes.size() == 1;
  l.rows = l.views_across ? 1 : static_cast<int>(options.views.size());
  l.cols = l.views_across ? static_cast<int>(options.views.size()) : static_cast<int>(meshes.size());
  const auto band = [&](double fraction, int lo, int hi) {
    return std::clamp(static_cast<int>(std::lround(fraction * options.height)), lo, hi);
  };
  if (!options.title.empty()) l.title_h = band(0.07, 16, 80);
  if (has_color_bar(options)) l.bar_h = band(0.13, 32, 130);
  const bool labelled = options.views.size() > 1 ||
                        std::any_of(meshes.begin(), meshes.end(), [](const RenderMesh& m) { return !m.label.empty(); });
  if (labelled)
    l.label_h = std::clamp(static_cast<int>(std::lround(0.07 * (options.height - l.title_h - l.bar_h) / l.rows)), 12, 32);
  for (int r = 0; r < l.rows; ++r)
    for (int c = 0; c < l.cols; ++c)
      if (l.panel_w(c) < 4 || l.draw_h(r) < 4)
        throw InvalidArgument("render: image size " + std::to_string(options.width) + "x" +
                              std::to_string(options.height) + " is too small for " +
                              std::to_string(l.rows) + " by " + std::to_string(l.cols) + " panels");
  return l;
}

/// One scale for every panel: the largest that fits every mesh's projection in every view.
double shared_scale(const std::vector<RenderMesh>& meshes, const RenderOptions& options, const Layout& l) {
  double scale = std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (std::size_t v = 0; v < options.views.size(); ++v) {
      const Extent e = projected_extent(*meshes[m].mesh, render_detail::view_rotation(options.views[v]));
      if (e.empty()) continue;
      const Eigen::Vector2d size = e.hi - e.lo;
      const int r = l.row_of(int(m), int(v)), c = l.col_of(int(m), int(v));
      if (size.x() > 0) scale = std::min(scale, kFill * l.panel_w(c) / size.x());
      if (size.y() > 0) scale = std::min(scale, kFill * l.draw_h(r) / size.y());
    }
  return std::isfinite(scale) ? scale : 1.0;
}

/// The faces of a mesh with every vertex inside a ball, over the vertices they use (in order).
struct Cropped {
  Mesh mesh;
  Eigen::VectorXd values;
};

Cropped crop_to_ball(const RenderMesh& item, const RenderFocus& focus) {
  const Mesh& mesh = *item.mesh;
  const double r2 = focus.radius * focus.radius;
  std::vector<int> inside(mesh.num_vertices(), -1);  // new index, or -1 outside the ball
  int kept_vertices = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if ((mesh.V.row(v).transpose() - focus.centre).squaredNorm() <= r2) inside[v] = kept_vertices++;
  std::vector<int> faces;
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (inside[mesh.F(f, 0)] >= 0 && inside[mesh.F(f, 1)] >= 0 && inside[mesh.F(f, 2)] >= 0) faces.push_back(f);
  Cropped out;
  out.mesh.V.resize(kept_vertices, 3);
  if (item.values.size() > 0) out.values.resize(kept_vertices);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (inside[v] < 0) continue;
    out.mesh.V.row(inside[v]) = mesh.V.row(v);
    if (item.values.size() > 0) out.values[inside[v]] = item.values[v];
  }
  out.mesh.F.resize(static_cast<int>(faces.size()), 3);
  for (int i = 0; i < static_cast<int>(faces.size()); ++i)
    for (int k = 0; k < 3; ++k) out.mesh.F(i, k) = inside[mesh.F(faces[i], k)];
  return out;
}

/// The meshes cut to the focus ball (`storage` owns them; the result points into it).
std::vector<RenderMesh> focused(const std::vector<RenderMesh>& meshes, const RenderFocus& focus,
                                std::vector<Cropped>& storage) {
  if (!focus.centre.allFinite() || !std::isfinite(focus.radius) || !(focus.radius > 0))
    throw InvalidArgument("render: the focus ball needs a finite centre and a finite radius > 0");
  storage.clear();
  storage.reserve(meshes.size());
  std::vector<RenderMesh> out;
  bool any_face = false;
  for (const RenderMesh& item : meshes) {
    storage.push_back(crop_to_ball(item, focus));
    any_face = any_face || storage.back().mesh.num_faces() > 0;
    out.push_back({&storage.back().mesh, storage.back().values, item.label});
  }
  if (!any_face) throw InvalidArgument("render: no face has all three vertices inside the focus ball");
  return out;
}

/// With a focus: the scale at which the ball's diameter fits the smallest panel.
double focus_scale(const RenderFocus& focus, const Layout& l) {
  double scale = std::numeric_limits<double>::infinity();
  for (int r = 0; r < l.rows; ++r)
    for (int c = 0; c < l.cols; ++c) scale = std::min(scale, kFill * std::min(l.panel_w(c), l.draw_h(r)) / (2 * focus.radius));
  return scale;
}

/// The given range, or the automatic one over every finite value of `meshes`.
ColorRange color_range_of(const std::vector<RenderMesh>& meshes, const RenderOptions& options) {
  if (options.range) {
    const ColorRange r = *options.range;
    if (!(std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo < r.hi))
      throw InvalidArgument("resolve_color_range: range [" + std::to_string(r.lo) + ", " +
                            std::to_string(r.hi) + "] must be finite with lo < hi");
    return r;
  }
  if (!(options.robust_quantile > 0.5 && options.robust_quantile <= 1.0))
    throw InvalidArgument("resolve_color_range: robust_quantile " + std::to_string(options.robust_quantile) +
                          " is outside (0.5, 1]");
  std::vector<double> finite;
  for (const RenderMesh& m : meshes)
    for (const double v : m.values)
      if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty()) return options.color_map == ColorMap::sequential ? ColorRange{0.0, 1.0} : ColorRange{-1.0, 1.0};
  if (options.color_map == ColorMap::sequential) {
    const double lo = std::min(0.0, quantile(finite, 1.0 - options.robust_quantile));
    const double hi = quantile(finite, options.robust_quantile);
    return hi > lo ? ColorRange{lo, hi} : ColorRange{lo, lo + 1.0};
  }
  for (double& v : finite) v = std::abs(v);
  const double m = quantile(finite, options.robust_quantile);
  return m > 0 ? ColorRange{-m, m} : ColorRange{-1.0, 1.0};
}

}  // namespace

ColorRange resolve_color_range(const std::vector<RenderMesh>& meshes, const RenderOptions& options) {
  if (options.focus && !options.range) {
    std::vector<Cropped> cropped;
    return color_range_of(focused(meshes, *options.focus, cropped), options);
  }
  return color_range_of(meshes, options);
}

Image render(const std::vector<RenderMesh>& given, const RenderOptions& options) {
  validate(given, options);
  std::vector<Cropped> cropped;
  const std::vector<RenderMesh> meshes = options.focus ? focused(given, *options.focus, cropped) : given;
  const Layout layout = make_layout(meshes, options);
  const int ss = options.supersampling;
  const double scale = options.focus ? focus_scale(*options.focus, layout) : shared_scale(meshes, options, layout);

  Image image{options.width, options.height, {}};
  image.rgb.resize(3 * static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    image.rgb[i] = options.background.r;
    image.rgb[i + 1] = options.background.g;
    image.rgb[i + 2] = options.background.b;
  }

  render_detail::ShadeOptions shade;
  shade.color_map = options.color_map;
  shade.range = color_range_of(meshes, options);
  shade.shading = options.shading;
  shade.wireframe = options.wireframe;
  shade.wire_half_width = 0.4 * ss;  // 0.8 pixel wide
  shade.background = options.background;

  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (std::size_t v = 0; v < options.views.size(); ++v) {
      const int r = layout.row_of(int(m), int(v)), c = layout.col_of(int(m), int(v));
      PanelCamera camera;
      camera.rotation = render_detail::view_rotation(options.views[v]);
      camera.scale = scale * ss;
      camera.width = layout.panel_w(c) * ss;
      camera.height = layout.draw_h(r) * ss;
      if (options.focus) {
        camera.center_world = (camera.rotation * options.focus->centre).head<2>();
      } else {
        const Extent e = projected_extent(*meshes[m].mesh, camera.rotation);
        if (!e.empty()) camera.center_world = 0.5 * (e.lo + e.hi);
      }
      render_detail::draw_panel(*meshes[m].mesh, meshes[m].values, camera, shade, ss, image,
                                layout.panel_x(c), layout.panel_y(r) + layout.label_h);
    }

  const bool any_text = layout.title_h > 0 || layout.bar_h > 0 || layout.label_h > 0;
  if (!any_text) return image;
  const render_detail::Font font(options.font);
  constexpr Rgb8 kInk{20, 20, 20};
  if (layout.title_h > 0)
    font.draw(image, options.title, 0.5 * image.width, 0.75 * layout.title_h, 0.62 * layout.title_h, kInk,
              render_detail::Align::center);
  if (layout.label_h > 0)
    for (std::size_t m = 0; m < meshes.size(); ++m)
      for (std::size_t v = 0; v < options.views.size(); ++v) {
        const int r = layout.row_of(int(m), int(v)), c = layout.col_of(int(m), int(v));
        font.draw(image, panel_label(meshes[m], options.views[v], options), layout.panel_x(c) + 0.5 * layout.panel_w(c),
                  layout.panel_y(r) + 0.78 * layout.label_h, 0.7 * layout.label_h, kInk, render_detail::Align::center);
      }
  if (layout.bar_h > 0)
    render_detail::draw_color_bar(image, font, options.color_map, shade.range, options.quantity, 0,
                                  image.height - layout.bar_h, image.width, layout.bar_h);
  return image;
}

}  // namespace fairsurf
