// Internal pieces of render.h, one file each: views (render_view.cpp), colour maps
// (render_colormap.cpp), the rasterizer (render_raster.cpp), text and the colour bar
// (render_text.cpp), PNG encoding (render_png.cpp). render.cpp lays out panels and composes them.
#pragma once

#include <fairsurf/render/render.h>

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fairsurf::render_detail {

/// Rows: the camera's right, up and toward-the-viewer axes in world coordinates (orthonormal, right-
/// handed), so that R * p is p in camera coordinates with +z pointing at the viewer.
Eigen::Matrix3d view_rotation(View view);

/// A 1025-entry table of `map` (odd, so that t = 0.5 is an exact entry: the diverging neutral).
const std::vector<Rgb8>& color_table(ColorMap map);
/// The colour for a non-finite value.
constexpr Rgb8 kNoDataColor{80, 80, 80};
/// The uniform colour of ColorMap::none.
constexpr Rgb8 kGrey{200, 200, 200};

/// Where one mesh lands in one panel: world -> sample coordinates (x right, y down, in samples).
struct PanelCamera {
  Eigen::Matrix3d rotation;  ///< view_rotation(view)
  double scale = 1.0;        ///< samples per world unit
  Eigen::Vector2d center_world = Eigen::Vector2d::Zero();  ///< camera (x, y) shown at the centre
  int width = 0;             ///< panel width in samples
  int height = 0;            ///< panel height in samples
};

/// How each sample is shaded.
struct ShadeOptions {
  ColorMap color_map = ColorMap::diverging;
  ColorRange range;
  bool shading = true;
  bool wireframe = false;
  double wire_half_width = 1.0;  ///< samples
  Rgb8 background;
};

/// Renders `mesh` coloured by `values` (#V or empty) and box-filters it down by `supersampling`
/// into `image` at pixel (x0, y0); the panel is camera.width/supersampling pixels wide.
void draw_panel(const Mesh& mesh, const Eigen::VectorXd& values, const PanelCamera& camera,
                const ShadeOptions& shade, int supersampling, Image& image, int x0, int y0);

enum class Align { left, center, right };

/// A TrueType font (stb_truetype) drawing UTF-8 text into images.
class Font {
 public:
  explicit Font(const std::filesystem::path& path);  ///< throws IoError
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;
  /// Width in pixels of `text` at `pixel_height`.
  double text_width(const std::string& text, double pixel_height) const;
  /// Draws `text` with its baseline at `baseline_y`, anchored at `x` per `align`.
  void draw(Image& image, const std::string& text, double x, double baseline_y, double pixel_height,
            Rgb8 color, Align align) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Draws a horizontal colour bar in the box (x, y, w, h) of `image`: the bar, tick marks and labels
/// at five evenly spaced values, and `caption` to its left.
void draw_color_bar(Image& image, const Font& font, ColorMap map, const ColorRange& range,
                    const std::string& caption, int x, int y, int w, int h);

}  // namespace fairsurf::render_detail
