// Text and the colour bar. Glyphs come from a TrueType font rasterized by stb_truetype (Debian
// libstb-dev, header only, compiled here with static linkage) — DejaVu Sans from fonts-dejavu-core by
// default. stb_truetype's rasterizer is plain sequential float arithmetic, so text is deterministic.
#include "render_internal.h"

#include <fairsurf/mesh/errors.h>

#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace fairsurf::render_detail {
namespace {

/// Code points of UTF-8 `text`; malformed bytes become U+FFFD.
std::vector<int> decode_utf8(const std::string& text) {
  std::vector<int> points;
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || i + length > text.size()) {
      points.push_back(0xFFFD);
      ++i;
      continue;
    }
    int point = length == 1 ? lead : lead & (0x7F >> length);
    for (int k = 1; k < length; ++k) point = (point << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
    points.push_back(point);
    i += length;
  }
  return points;
}

void blend(Image& image, int x, int y, Rgb8 color, int alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || alpha == 0) return;
  std::uint8_t* p = &image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x)];
  const std::array<int, 3> c{color.r, color.g, color.b};
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>((p[k] * (255 - alpha) + c[k] * alpha + 127) / 255);
}

void fill_rect(Image& image, int x, int y, int w, int h, Rgb8 color) {
  for (int j = y; j < y + h; ++j)
    for (int i = x; i < x + w; ++i) blend(image, i, j, color, 255);
}

std::string tick_label(double value) {
  if (value == 0.0) return "0";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

}  // namespace

struct Font::Impl {
  std::vector<unsigned char> data;
  stbtt_fontinfo info{};
};

Font::Font(const std::filesystem::path& path) : impl_(std::make_unique<Impl>()) {
  std::ifstream in(path, std::ios::binary);
  impl_->data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) impl_->data.clear();
  if (impl_->data.empty() || stbtt_InitFont(&impl_->info, impl_->data.data(), stbtt_GetFontOffsetForIndex(impl_->data.data(), 0)) == 0)
    throw IoError("render: cannot load the TrueType font '" + path.string() +
                  "' (install fonts-dejavu-core or set RenderOptions::font)");
}

Font::~Font() = default;

double Font::text_width(const std::string& text, double pixel_height) const {
  const float scale = stbtt_ScaleForPixelHeight(&impl_->info, static_cast<float>(pixel_height));
  const std::vector<int> points = decode_utf8(text);
  double width = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&impl_->info, points[k], &advance, &bearing);
    width += scale * advance;
    if (k + 1 < points.size()) width += scale * stbtt_GetCodepointKernAdvance(&impl_->info, points[k], points[k + 1]);
  }
  return width;
}

void Font::draw(Image& image, const std::string& text, double x, double baseline_y, double pixel_height,
                Rgb8 color, Align align) const {
  const float scale = stbtt_ScaleForPixelHeight(&impl_->info, static_cast<float>(pixel_height));
  const double width = text_width(text, pixel_height);
  double pen = align == Align::left ? x : align == Align::center ? x - 0.5 * width : x - width;
  const int baseline = static_cast<int>(std::lround(baseline_y));
  const std::vector<int> points = decode_utf8(text);
  std::vector<unsigned char> bitmap;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double origin = std::floor(pen);
    const float shift = static_cast<float>(pen - origin);
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBitmapBoxSubpixel(&impl_->info, points[k], scale, scale, shift, 0.0f, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      bitmap.assign(static_cast<std::size_t>(w) * h, 0);
      stbtt_MakeCodepointBitmapSubpixel(&impl_->info, bitmap.data(), w, h, w, scale, scale, shift, 0.0f, points[k]);
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
          blend(image, static_cast<int>(origin) + x0 + i, baseline + y0 + j, color, bitmap[static_cast<std::size_t>(j) * w + i]);
    }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&impl_->info, points[k], &advance, &bearing);
    pen += scale * advance;
    if (k + 1 < points.size()) pen += scale * stbtt_GetCodepointKernAdvance(&impl_->info, points[k], points[k + 1]);
  }
}

void draw_color_bar(Image& image, const Font& font, ColorMap map, const ColorRange& range,
                    const std::string& caption, int x, int y, int w, int h) {
  constexpr Rgb8 kInk{20, 20, 20};
  const int bar_w = static_cast<int>(0.6 * w), bar_h = std::max(4, static_cast<int>(0.28 * h));
  const int bar_x = x + (w - bar_w) / 2, bar_y = y + static_cast<int>(0.1 * h);
  const std::vector<Rgb8>& table = color_table(map);
  for (int i = 0; i < bar_w; ++i) {
    const double t = (i + 0.5) / bar_w;
    const Rgb8 c = table[static_cast<std::size_t>(std::lround(t * (table.size() - 1)))];
    fill_rect(image, bar_x + i, bar_y, 1, bar_h, c);
  }
  // Outline, then five ticks with their values.
  fill_rect(image, bar_x - 1, bar_y - 1, bar_w + 2, 1, kInk);
  fill_rect(image, bar_x - 1, bar_y + bar_h, bar_w + 2, 1, kInk);
  fill_rect(image, bar_x - 1, bar_y, 1, bar_h, kInk);
  fill_rect(image, bar_x + bar_w, bar_y, 1, bar_h, kInk);
  const int tick_h = std::max(2, static_cast<int>(0.08 * h));
  const double label_px = std::max(8.0, 0.22 * h);
  for (int k = 0; k <= 4; ++k) {
    const int tx = bar_x + static_cast<int>(std::lround(k * (bar_w - 1) / 4.0));
    fill_rect(image, tx, bar_y + bar_h, 1, tick_h, kInk);
    // lo*(1-t) + hi*t is exactly 0 at the middle of a symmetric range; residues of cancellation
    // elsewhere are snapped to 0 too.
    double value = range.lo * (1.0 - k / 4.0) + range.hi * (k / 4.0);
    if (std::abs(value) < 1e-12 * (range.hi - range.lo)) value = 0.0;
    font.draw(image, tick_label(value), tx, bar_y + bar_h + tick_h + label_px, label_px, kInk, Align::center);
  }
  if (!caption.empty())
    font.draw(image, caption, bar_x - 0.5 * label_px, bar_y + 0.5 * bar_h + 0.35 * label_px * 1.2,
              1.2 * label_px, kInk, Align::right);
}

}  // namespace fairsurf::render_detail
