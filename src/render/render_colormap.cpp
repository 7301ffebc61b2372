// Colour maps: Moreland's diverging cool-warm and a viridis-like sequential map, both built in
// CIELAB (D65) once into a lookup table, so a pixel's colour costs one table read.
//
// Moreland, "Diverging Color Maps for Scientific Visualization" (ISVC 2009): the two end colours are
// interpolated in his Msh space (polar CIELAB) through an unsaturated neutral of magnitude 88,
// which keeps lightness symmetric about the midpoint and the midpoint free of hue.
#include "render_internal.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fairsurf {
namespace {

using render_detail::kGrey;
using render_detail::kNoDataColor;

constexpr int kTableSize = 1025;
constexpr double kPi = std::numbers::pi;
// D65 reference white in XYZ.
constexpr double kWhiteX = 0.95047, kWhiteY = 1.0, kWhiteZ = 1.08883;

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double linear_to_srgb(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
double lab_f(double t) { return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0; }
double lab_f_inverse(double f) {
  return f * f * f > 216.0 / 24389.0 ? f * f * f : (116.0 * f - 16.0) * 27.0 / 24389.0;
}

struct Lab {
  double L, a, b;
};

Lab rgb_to_lab(Rgb8 c) {
  const double r = srgb_to_linear(c.r / 255.0), g = srgb_to_linear(c.g / 255.0),
               b = srgb_to_linear(c.b / 255.0);
  const double x = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
  const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
  const double fx = lab_f(x / kWhiteX), fy = lab_f(y / kWhiteY), fz = lab_f(z / kWhiteZ);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

std::uint8_t to_byte(double linear) {
  const double s = std::clamp(linear_to_srgb(std::clamp(linear, 0.0, 1.0)), 0.0, 1.0);
  return static_cast<std::uint8_t>(std::lround(255.0 * s));
}

Rgb8 lab_to_rgb(const Lab& lab) {
  const double fy = (lab.L + 16.0) / 116.0, fx = fy + lab.a / 500.0, fz = fy - lab.b / 200.0;
  const double x = kWhiteX * lab_f_inverse(fx), y = kWhiteY * lab_f_inverse(fy),
               z = kWhiteZ * lab_f_inverse(fz);
  const double r = 3.2404542 * x - 1.5371385 * y - 0.4985314 * z;
  const double g = -0.9692660 * x + 1.8760108 * y + 0.0415560 * z;
  const double b = 0.0556434 * x - 0.2040259 * y + 1.0572252 * z;
  return {to_byte(r), to_byte(g), to_byte(b)};
}

struct Msh {
  double M, s, h;
};

Msh lab_to_msh(const Lab& lab) {
  const double M = std::sqrt(lab.L * lab.L + lab.a * lab.a + lab.b * lab.b);
  return {M, M > 0 ? std::acos(lab.L / M) : 0.0, std::atan2(lab.b, lab.a)};
}
Lab msh_to_lab(const Msh& c) {
  return {c.M * std::cos(c.s), c.M * std::sin(c.s) * std::cos(c.h), c.M * std::sin(c.s) * std::sin(c.h)};
}

// Moreland's hue spin: an unsaturated colour takes a hue that keeps the blend perceptually even.
double adjust_hue(const Msh& saturated, double unsaturated_m) {
  if (saturated.M >= unsaturated_m) return saturated.h;
  const double spin = saturated.s * std::sqrt(unsaturated_m * unsaturated_m - saturated.M * saturated.M) /
                      (saturated.M * std::sin(saturated.s));
  return saturated.h > -kPi / 3.0 ? saturated.h + spin : saturated.h - spin;
}

Rgb8 moreland_interpolate(Rgb8 from, Rgb8 to, double t) {
  Msh a = lab_to_msh(rgb_to_lab(from)), b = lab_to_msh(rgb_to_lab(to));
  const auto saturated = [](const Msh& c) { return c.s > 0.05; };
  if (saturated(a) && saturated(b) && std::abs(a.h - b.h) > kPi / 3.0) {
    const double middle = std::max({a.M, b.M, 88.0});
    if (t < 0.5) {
      b = {middle, 0.0, 0.0};
      t = 2.0 * t;
    } else {
      a = {middle, 0.0, 0.0};
      t = 2.0 * t - 1.0;
    }
  }
  if (!saturated(a) && saturated(b)) a.h = adjust_hue(b, a.M);
  if (saturated(a) && !saturated(b)) b.h = adjust_hue(a, b.M);
  return lab_to_rgb(msh_to_lab({(1 - t) * a.M + t * b.M, (1 - t) * a.s + t * b.s, (1 - t) * a.h + t * b.h}));
}

std::vector<Rgb8> cool_warm_table() {
  std::vector<Rgb8> table(kTableSize);
  for (int i = 0; i < kTableSize; ++i)
    table[i] = moreland_interpolate({59, 76, 192}, {180, 4, 38}, i / double(kTableSize - 1));
  return table;
}

// Viridis (matplotlib) at t = 0, 1/4, 1/2, 3/4, 1, joined by straight segments in CIELAB.
std::vector<Rgb8> viridis_like_table() {
  const std::array<Rgb8, 5> anchors{{{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
  std::vector<Rgb8> table(kTableSize);
  for (int i = 0; i < kTableSize; ++i) {
    const double u = 4.0 * i / double(kTableSize - 1);
    const int k = std::min(3, static_cast<int>(u));
    const double t = u - k;
    const Lab a = rgb_to_lab(anchors[k]), b = rgb_to_lab(anchors[k + 1]);
    table[i] = lab_to_rgb({(1 - t) * a.L + t * b.L, (1 - t) * a.a + t * b.a, (1 - t) * a.b + t * b.b});
  }
  return table;
}

struct MapSpec {
  ColorMap map;
  const char* name;
};
constexpr std::array<MapSpec, 3> kMaps{{{ColorMap::diverging, "diverging"},
                                        {ColorMap::sequential, "sequential"},
                                        {ColorMap::none, "none"}}};

}  // namespace

std::string color_map_name(ColorMap map) {
  for (const auto& spec : kMaps)
    if (spec.map == map) return spec.name;
  throw InvalidArgument("color_map_name: unknown colour map value");
}

ColorMap color_map_from_name(const std::string& name) {
  for (const auto& spec : kMaps)
    if (name == spec.name) return spec.map;
  throw InvalidArgument("color_map_from_name: unknown colour map '" + name +
                        "' (valid: diverging, sequential, none)");
}

Rgb8 map_color(ColorMap map, double value, const ColorRange& range) {
  if (map == ColorMap::none) return kGrey;
  if (!std::isfinite(value)) return kNoDataColor;
  const double t = std::clamp((value - range.lo) / (range.hi - range.lo), 0.0, 1.0);
  return render_detail::color_table(map)[static_cast<std::size_t>(t * (kTableSize - 1) + 0.5)];
}

namespace render_detail {

const std::vector<Rgb8>& color_table(ColorMap map) {
  static const std::vector<Rgb8> cool_warm = cool_warm_table();
  static const std::vector<Rgb8> viridis_like = viridis_like_table();
  static const std::vector<Rgb8> grey(kTableSize, kGrey);
  switch (map) {
    case ColorMap::diverging: return cool_warm;
    case ColorMap::sequential: return viridis_like;
    case ColorMap::none: return grey;
  }
  throw InvalidArgument("color_table: unknown colour map value");
}

}  // namespace render_detail
}  // namespace fairsurf
