// fairsurf — headless images of meshes coloured by a per-vertex scalar (mean curvature, energy, ...).
//
// A small software rasterizer (docs/render.md): no display, no GPU, no threads whose scheduling can
// change a pixel. Every image is a grid of panels, one per mesh and view: meshes side by side and
// views one under another, except that a single mesh's views go side by side. All panels share
// ONE camera scale and ONE colour range, so that panels compare like with like.
//
// Camera: orthographic. Each view looks at the origin of its panel from a fixed direction (table in
// docs/render.md); the world's +y is "up" for every view but top/bottom. The scale is chosen so that
// the projected vertices of every mesh in every view fit their panels with a margin; each mesh is
// centred in its panel.
//
// Colour maps (docs/render.md):
//  - diverging: Moreland's cool-warm (2009), interpolated in his Msh space; blue < 0 < red, with the
//    neutral light grey (221,221,221) at 0. The range is symmetric about 0 unless one is given.
//  - sequential: viridis-like, piecewise linear in CIELAB through viridis's five anchor colours;
//    dark violet at the low end, yellow at the high end.
//  - none: uniform grey; no colour bar.
// Values outside the range are clamped to its ends; non-finite values are drawn in dark grey.
//
// Determinism: the same inputs and options give the same bytes on every run and for every thread
// count. Depth ties are broken by (mesh-local) face index, so the visible face of every sample is a
// pure function of the scene, whatever order the faces are rasterized in.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fairsurf {

/// The fixed viewing directions. "front" looks along -z (camera on +z), "left" has the camera on -x,
/// "top" on +y (with -z up in the image), "iso" on (1,1,1) with +y up.
enum class View { front, back, left, right, top, bottom, iso };

/// "front", "back", ... for each View.
std::string view_name(View view);
/// Inverse of view_name; throws InvalidArgument naming the valid views.
View view_from_name(const std::string& name);

enum class ColorMap { diverging, sequential, none };

/// "diverging", "sequential", "none".
std::string color_map_name(ColorMap map);
/// Inverse of color_map_name; throws InvalidArgument naming the valid maps.
ColorMap color_map_from_name(const std::string& name);

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

/// The values that map to the two ends of a colour map; lo < hi.
struct ColorRange {
  double lo = -1.0;
  double hi = 1.0;
};

/// The colour of `value` under `map` on `range` (clamped to the ends; dark grey if not finite).
Rgb8 map_color(ColorMap map, double value, const ColorRange& range);

/// One mesh to draw (a column of panels when several are drawn).
struct RenderMesh {
  const Mesh* mesh = nullptr;  ///< not owned; must outlive the call
  Eigen::VectorXd values;      ///< #V scalars, or empty for uniform grey
  std::string label;           ///< written above each of the mesh's panels; may be empty
};

/// A ball to look into instead of the whole mesh (RenderOptions::focus).
struct RenderFocus {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 1.0;  ///< > 0, in the mesh's units
};

struct RenderOptions {
  int width = 1200;                 ///< whole image, pixels
  int height = 900;                 ///< whole image, pixels
  std::vector<View> views{View::iso};  ///< one panel per view and mesh
  ColorMap color_map = ColorMap::diverging;
  /// Values mapped to the ends of the colour map. Unset: automatic from robust percentiles of all
  /// meshes' values together (auto_range).
  std::optional<ColorRange> range;
  /// Automatic range: the quantile of |value| (diverging: [-q, q]) or of value (sequential:
  /// [min(0, q_low), q] with q_low the complementary quantile), over every finite value of every mesh.
  double robust_quantile = 0.95;
  bool shading = true;              ///< Phong-lit (headlight); false: flat colour of the scalar
  bool wireframe = false;           ///< overlay the visible edges
  int supersampling = 3;            ///< samples per pixel along each axis (anti-aliasing)
  std::string title;                ///< drawn centred at the top; empty: no title band
  std::string quantity;             ///< colour bar caption ("H", "energy density", ...)
  bool color_bar = true;            ///< ignored for ColorMap::none
  Rgb8 background{255, 255, 255};
  /// Set: draw only the faces with all three vertices inside this ball (a cut-away: what lies in
  /// front of a filled hole on a large model is not drawn), centre every panel on the ball's centre
  /// and scale it so that the ball's diameter fits, and take the automatic colour range from the
  /// drawn vertices. Unset: every face, each mesh fitted and centred as above.
  std::optional<RenderFocus> focus;
  /// TrueType font for title, labels and ticks (Debian: fonts-dejavu-core).
  std::filesystem::path font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
};

/// An RGB image, 8 bits per channel, rows top to bottom, pixels left to right.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width*height*3 bytes

  Rgb8 pixel(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

/// The colour range render() uses for `meshes` under `options` (given, or automatic: over the
/// vertices inside the focus ball when there is one). Degenerate
/// automatic ranges (all values 0, or all equal) widen to a unit interval around them.
ColorRange resolve_color_range(const std::vector<RenderMesh>& meshes, const RenderOptions& options);

/// Renders every mesh in every view into one image (panel grid as above), with the title
/// above and a horizontal colour bar below. Throws InvalidArgument (bad size, no views, values of
/// the wrong length, a null mesh, a focus ball that is not finite with radius > 0 or holds no face
/// of any mesh), InvalidMeshError (face index out of range) or IoError (font file
/// unreadable, only when text is drawn).
Image render(const std::vector<RenderMesh>& meshes, const RenderOptions& options = {});

/// Writes `image` as an 8-bit RGB PNG (no timestamp or other varying chunk) atomically: a temporary
/// file beside `path` is renamed into place. Throws IoError; the target is then left untouched.
void write_png(const std::filesystem::path& path, const Image& image);

}  // namespace fairsurf
