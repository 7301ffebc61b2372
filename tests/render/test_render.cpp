#include <fairsurf/mesh/errors.h>
#include <fairsurf/render/render.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "analytic_meshes.h"

using namespace fairsurf;

namespace {

constexpr Rgb8 kBackground{10, 200, 30};  // a colour no map produces

RenderOptions plain_options(int width, int height) {
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.color_bar = false;
  o.background = kBackground;
  return o;
}

int count_pixels(const Image& image, const auto& predicate, int x0 = 0, int x1 = -1) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < (x1 < 0 ? image.width : x1); ++x) count += predicate(image.pixel(x, y)) ? 1 : 0;
  return count;
}

bool is_background(Rgb8 c) { return c == kBackground; }

/// Gaussian curvature cos v / (r (R + r cos v)) at every vertex of a torus_grid.
Eigen::VectorXd torus_gaussian_curvature(const test::ParametricMesh& torus, double R, double r) {
  const Eigen::ArrayXd c = torus.uv.col(1).array().cos();
  return c / (r * (R + r * c));
}

/// HSV hue in degrees.
double hue(Rgb8 c) {
  const double r = c.r, g = c.g, b = c.b, hi = std::max({r, g, b}), lo = std::min({r, g, b});
  if (hi == lo) return 0;
  double h = hi == r ? (g - b) / (hi - lo) : hi == g ? 2 + (b - r) / (hi - lo) : 4 + (r - g) / (hi - lo);
  return std::fmod(60 * h + 360, 360);
}

double luma(Rgb8 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

/// CIELAB lightness L* (D65) of an sRGB colour.
double lightness(Rgb8 c) {
  const auto linear = [](double u) { u /= 255; return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4); };
  const double y = 0.2126729 * linear(c.r) + 0.7151522 * linear(c.g) + 0.0721750 * linear(c.b);
  return y > 216.0 / 24389.0 ? 116 * std::cbrt(y) - 16 : 24389.0 / 27.0 * y;
}

std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("fairsurf_test_render_" + name);
}

}  // namespace

TEST(Render, ConstantScalarUnshadedSphereIsOneColour) {
  const Mesh sphere = test::icosphere(3);
  RenderOptions o = plain_options(80, 60);
  o.shading = false;
  o.supersampling = 1;  // no edge blending, so every covered pixel is exactly the map's colour
  o.range = ColorRange{-1.0, 1.0};
  const Rgb8 expected = map_color(ColorMap::diverging, 0.5, *o.range);
  const Image image = render({{&sphere, Eigen::VectorXd::Constant(sphere.num_vertices(), 0.5), ""}}, o);
  const int covered = count_pixels(image, [&](Rgb8 c) { return c == expected; });
  EXPECT_EQ(covered + count_pixels(image, is_background), 80 * 60);
  // The disc spans 92% of the 60-pixel height: about pi * 27.6^2 = 2390 pixels.
  EXPECT_NEAR(covered, 2390, 120);
}

TEST(Render, ShadingChangesBrightnessNotHue) {
  const Mesh sphere = test::icosphere(3);
  RenderOptions o = plain_options(120, 100);
  o.range = ColorRange{-1.0, 1.0};
  const Rgb8 base = map_color(ColorMap::diverging, 0.8, *o.range);
  const Image image = render({{&sphere, Eigen::VectorXd::Constant(sphere.num_vertices(), 0.8), ""}}, o);
  int interior = 0, dimmer = 0;
  for (int y = 1; y + 1 < image.height; ++y)
    for (int x = 1; x + 1 < image.width; ++x) {
      bool inside = true;  // all 3x3 neighbours covered: no blending with the background
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) inside = inside && !is_background(image.pixel(x + dx, y + dy));
      if (!inside) continue;
      ++interior;
      const Rgb8 c = image.pixel(x, y);
      EXPECT_NEAR(hue(c), hue(base), 4.0) << x << "," << y;
      dimmer += luma(c) < luma(base) - 20 ? 1 : 0;
    }
  EXPECT_GT(interior, 4000);
  EXPECT_GT(dimmer, 100);  // the shading is really there: the rim is darker than the base colour
}

TEST(Render, SignedScalarOnTorusShowsBothEndsOfTheMap) {
  const test::ParametricMesh grid = test::torus_grid(64, 32, 1.0, 0.4);
  const Mesh& torus = grid.mesh;
  const Eigen::VectorXd K = torus_gaussian_curvature(grid, 1.0, 0.4);
  RenderOptions o = plain_options(160, 120);
  o.views = {View::front};  // along the torus's axis (z)
  o.shading = false;
  const ColorRange range = resolve_color_range({{&torus, K, ""}}, o);
  EXPECT_DOUBLE_EQ(range.lo, -range.hi);  // automatic diverging ranges are symmetric
  // K runs from -1/(0.4*0.6) = -4.17 inside to 1/(0.4*1.4) = 1.79 outside; the 95% quantile of |K|
  // is on the inner side.
  EXPECT_GT(range.hi, 3.5);
  EXPECT_LE(range.hi, K.cwiseAbs().maxCoeff());
  EXPECT_GT(count_pixels(render({{&torus, K, ""}}, o), [](Rgb8 c) { return c.b > c.r + 40 && !is_background(c); }), 500);
  // With a range inside [min K, max K] both ends of the map appear, clamped: the inner and outer
  // rims seen along the axis.
  o.range = ColorRange{-1.5, 1.5};
  const Image image = render({{&torus, K, ""}}, o);
  const Rgb8 cold = map_color(ColorMap::diverging, -1.5, *o.range), warm = map_color(ColorMap::diverging, 1.5, *o.range);
  EXPECT_GT(count_pixels(image, [&](Rgb8 c) { return c == cold; }), 200);
  EXPECT_GT(count_pixels(image, [&](Rgb8 c) { return c == warm; }), 200);
}

TEST(Render, BackgroundUntouchedOutsideTheSilhouette) {
  const Mesh sphere = test::icosphere(3);
  RenderOptions o = plain_options(100, 60);
  o.wireframe = true;
  const Image image = render({{&sphere, sphere.V.col(0), ""}}, o);
  for (const auto& [x, y] : {std::pair{0, 0}, {99, 0}, {0, 59}, {99, 59}}) EXPECT_EQ(image.pixel(x, y), kBackground);
  // The disc has diameter 0.92 * 60 = 55.2 pixels around x = 50, so columns 0..21 and 79..99 lie
  // outside its projected bounding box.
  EXPECT_EQ(count_pixels(image, is_background, 0, 22), 22 * 60);
  EXPECT_EQ(count_pixels(image, is_background, 79, 100), 21 * 60);
  EXPECT_LT(count_pixels(image, is_background, 22, 79), 57 * 60 - 2000);
}

TEST(Render, ImageHasTheRequestedSize) {
  const Mesh sphere = test::icosphere(2);
  RenderOptions o;  // with title and colour bar
  o.width = 123;
  o.height = 77;
  o.title = "size";
  const Image image = render({{&sphere, sphere.V.col(1), "a"}}, o);
  EXPECT_EQ(image.width, 123);
  EXPECT_EQ(image.height, 77);
  EXPECT_EQ(image.rgb.size(), 123u * 77u * 3u);
}

TEST(Render, RenderingTwiceGivesByteIdenticalPngFiles) {
  const test::ParametricMesh grid = test::torus_grid(48, 24, 1.0, 0.3);
  const Mesh& torus = grid.mesh;
  RenderOptions o;
  o.width = 240;
  o.height = 160;
  o.views = {View::iso, View::left};
  o.wireframe = true;
  o.title = "K on a torus";
  o.quantity = "K";
  const Eigen::VectorXd K = torus_gaussian_curvature(grid, 1.0, 0.3);
  const auto first = temp_path("first.png"), second = temp_path("second.png");
  write_png(first, render({{&torus, K, "torus"}}, o));
  write_png(second, render({{&torus, K, "torus"}}, o));
  const std::string a = test::read_bytes(first), b = test::read_bytes(second);
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a.substr(1, 3), "PNG");
  EXPECT_TRUE(a == b);
  std::filesystem::remove(first);
  std::filesystem::remove(second);
}

TEST(ColorMap, DivergingIsNeutralAtZeroAndSymmetricInLightness) {
  const ColorRange range{-2.0, 2.0};
  const Rgb8 zero = map_color(ColorMap::diverging, 0.0, range);
  EXPECT_EQ(zero.r, zero.g);
  EXPECT_EQ(zero.g, zero.b);
  EXPECT_GT(zero.r, 200);  // a light neutral (Moreland's 221 grey)
  const Rgb8 cold = map_color(ColorMap::diverging, -2.0, range), warm = map_color(ColorMap::diverging, 2.0, range);
  EXPECT_GT(cold.b, cold.r + 100);
  EXPECT_GT(warm.r, warm.b + 100);
  EXPECT_EQ(map_color(ColorMap::diverging, -50.0, range), cold);  // clamped
  for (double t = 0.25; t <= 2.0; t += 0.25) {
    const Rgb8 minus = map_color(ColorMap::diverging, -t, range), plus = map_color(ColorMap::diverging, t, range);
    EXPECT_LT(lightness(minus), lightness(map_color(ColorMap::diverging, -t + 0.25, range)));
    EXPECT_NEAR(lightness(minus), lightness(plus), 4.0) << t;  // L* falls off alike on both sides
    EXPECT_GT(minus.b, minus.r);
    EXPECT_GT(plus.r, plus.b);
  }
  EXPECT_EQ(map_color(ColorMap::diverging, std::nan(""), range), (Rgb8{80, 80, 80}));
}

TEST(ColorMap, SequentialLightnessIncreases) {
  const ColorRange range{0.0, 1.0};
  double previous = -1;
  for (int k = 0; k <= 20; ++k) {
    const double l = lightness(map_color(ColorMap::sequential, k / 20.0, range));
    EXPECT_GT(l, previous) << k;
    previous = l;
  }
}

TEST(Render, AutomaticSequentialRangeStartsAtZeroForNonNegativeValues) {
  const Mesh sphere = test::icosphere(2);
  Eigen::VectorXd energy = sphere.V.col(1).array().square() + 3.0;  // in [3, 4]
  RenderOptions o;
  o.color_map = ColorMap::sequential;
  o.robust_quantile = 1.0;
  const ColorRange range = resolve_color_range({{&sphere, energy, ""}}, o);
  EXPECT_EQ(range.lo, 0.0);
  EXPECT_DOUBLE_EQ(range.hi, 4.0);
}

TEST(Render, CompareModeSharesColourRangeAndScale) {
  const Mesh big = test::icosphere(3), small = test::icosphere(3, 0.5);
  RenderOptions o = plain_options(200, 100);
  o.shading = false;
  o.supersampling = 1;
  const std::vector<RenderMesh> meshes{{&big, Eigen::VectorXd::Constant(big.num_vertices(), 0.2), ""},
                                       {&small, Eigen::VectorXd::Constant(small.num_vertices(), 1.0), ""}};
  const ColorRange range = resolve_color_range(meshes, o);
  EXPECT_DOUBLE_EQ(range.hi, 1.0);  // pooled over both meshes
  EXPECT_DOUBLE_EQ(range.lo, -1.0);
  const Image image = render(meshes, o);
  const Rgb8 left = map_color(ColorMap::diverging, 0.2, range), right = map_color(ColorMap::diverging, 1.0, range);
  ASSERT_NE(left, right);
  EXPECT_EQ(image.pixel(50, 50), left);
  EXPECT_EQ(image.pixel(150, 50), right);
  const auto width_of = [&](Rgb8 c) {
    int n = 0;
    for (int x = 0; x < image.width; ++x) n += image.pixel(x, 50) == c ? 1 : 0;
    return n;
  };
  // One scale: the sphere of half the radius is half as wide (92 px vs 46 px).
  EXPECT_NEAR(width_of(left), 92, 2);
  EXPECT_NEAR(width_of(right), 46, 2);
}

TEST(Render, EachViewSeesItsSideOfTheMesh) {
  const Mesh sphere = test::icosphere(3);
  RenderOptions o = plain_options(60, 60);
  o.shading = false;
  o.range = ColorRange{-1.0, 1.0};
  const struct {
    View view;
    int axis;
    double sign;
  } cases[] = {{View::front, 2, 1}, {View::back, 2, -1}, {View::right, 0, 1},
               {View::left, 0, -1}, {View::top, 1, 1},   {View::bottom, 1, -1}};
  for (const auto& c : cases) {
    o.views = {c.view};
    const Image image = render({{&sphere, sphere.V.col(c.axis), ""}}, o);
    // The value facing the camera is +1 (warm) at the disc's centre.
    const Rgb8 centre = image.pixel(30, 30);
    EXPECT_GT(c.sign * (centre.r - centre.b), 100) << view_name(c.view);
  }
  // Front view: +x is to the right and +y up.
  o.views = {View::front};
  const Image by_x = render({{&sphere, sphere.V.col(0), ""}}, o);
  EXPECT_GT(by_x.pixel(50, 30).r, by_x.pixel(50, 30).b + 100);
  const Image by_y = render({{&sphere, sphere.V.col(1), ""}}, o);
  EXPECT_GT(by_y.pixel(30, 10).r, by_y.pixel(30, 10).b + 100);
}

TEST(Render, WireframeDrawsDarkEdges) {
  const Mesh sphere = test::icosphere(2);
  RenderOptions o = plain_options(120, 120);
  o.shading = false;
  const auto dark = [](Rgb8 c) { return luma(c) < 80; };
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(sphere.num_vertices());
  EXPECT_EQ(count_pixels(render({{&sphere, zero, ""}}, o), dark), 0);
  o.wireframe = true;
  EXPECT_GT(count_pixels(render({{&sphere, zero, ""}}, o), dark), 100);
}

TEST(Render, NamesRoundTripAndUnknownNamesListTheValidOnes) {
  for (View v : {View::front, View::back, View::left, View::right, View::top, View::bottom, View::iso})
    EXPECT_EQ(view_from_name(view_name(v)), v);
  try {
    view_from_name("diagonal");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "view_from_name: unknown view 'diagonal' (valid: front, back, left, right, top, bottom, iso)");
  }
  EXPECT_EQ(color_map_from_name("sequential"), ColorMap::sequential);
  EXPECT_THROW(color_map_from_name("jet"), InvalidArgument);
}

TEST(Render, FocusDrawsOnlyTheBallCloseUp) {
  // Coloured by z on [-1, 1], unshaded: the cap of the unit sphere inside a ball of radius 0.3 at
  // its north pole has z >= 0.955, so it is deep red; from the back, the rest of the sphere is not.
  const Mesh sphere = test::icosphere(4);
  RenderOptions o = plain_options(200, 200);
  o.shading = false;
  o.range = ColorRange{-1.0, 1.0};
  const auto red = [](Rgb8 c) { return c.r > c.b + 60; };
  const auto drawn = [](Rgb8 c) { return !is_background(c); };
  o.views = {View::back};  // the camera on -z: without the cut-away, the southern hemisphere hides the cap
  const Image whole = render({{&sphere, sphere.V.col(2), ""}}, o);
  o.focus = RenderFocus{Eigen::Vector3d(0, 0, 1), 0.3};
  const Image cap = render({{&sphere, sphere.V.col(2), ""}}, o);
  EXPECT_GT(count_pixels(whole, drawn), 20000);
  EXPECT_EQ(count_pixels(whole, red), 0);
  // The ball's diameter spans 0.92 of the panel: the cap (projected radius 0.2985, less the last
  // ring of faces that leaves the ball, edges ~0.08) is a disk of 75-92 pixels radius, all red.
  const int cap_pixels = count_pixels(cap, drawn);
  EXPECT_GT(cap_pixels, M_PI * 75 * 75);
  EXPECT_LT(cap_pixels, M_PI * 92 * 92);
  EXPECT_GT(count_pixels(cap, red), 0.95 * cap_pixels);
  // Centred on the ball's centre: the pole is the image's middle pixel.
  EXPECT_TRUE(drawn(cap.pixel(100, 100)));
  EXPECT_FALSE(drawn(cap.pixel(100, 5)));
  // The automatic range comes from the vertices inside the ball only.
  RenderOptions automatic = o;
  automatic.range.reset();
  const ColorRange range = resolve_color_range({{&sphere, sphere.V.col(2), ""}}, automatic);
  EXPECT_GT(range.hi, 0.95);
  EXPECT_LE(range.hi, 1.0);
}

TEST(Render, FocusBallMustHoldAFace) {
  const Mesh sphere = test::icosphere(2);
  RenderOptions o = plain_options(50, 50);
  o.focus = RenderFocus{Eigen::Vector3d(0, 0, 0), 0.5};  // inside the sphere: no vertex
  try {
    render({{&sphere, {}, ""}}, o);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "render: no face has all three vertices inside the focus ball");
  }
  o.focus = RenderFocus{Eigen::Vector3d(0, 0, 1), 0.0};
  EXPECT_THROW(render({{&sphere, {}, ""}}, o), InvalidArgument);
  o.focus = RenderFocus{Eigen::Vector3d(0, NAN, 1), 1.0};
  EXPECT_THROW(render({{&sphere, {}, ""}}, o), InvalidArgument);
}

TEST(Render, RejectsBadInput) {
  Mesh sphere = test::icosphere(2);
  RenderOptions o = plain_options(50, 50);
  EXPECT_THROW(render({{&sphere, Eigen::VectorXd::Zero(3), ""}}, o), InvalidArgument);
  EXPECT_THROW(render({{nullptr, {}, ""}}, o), InvalidArgument);
  EXPECT_THROW(render({}, o), InvalidArgument);
  RenderOptions tiny = o;
  tiny.width = 0;
  EXPECT_THROW(render({{&sphere, {}, ""}}, tiny), InvalidArgument);
  RenderOptions reversed = o;
  reversed.range = ColorRange{1.0, -1.0};
  EXPECT_THROW(render({{&sphere, {}, ""}}, reversed), InvalidArgument);
  RenderOptions no_font = o;
  no_font.title = "t";
  no_font.font = "/nonexistent/font.ttf";
  EXPECT_THROW(render({{&sphere, {}, ""}}, no_font), IoError);
  sphere.F(3, 1) = 1000;
  try {
    render({{&sphere, {}, ""}}, o);
    FAIL();
  } catch (const InvalidMeshError& e) {
    EXPECT_STREQ(e.what(), "render: mesh 0: face 3 has vertex index 1000 outside [0, 162)");
  }
}

TEST(Render, WritePngFailsCleanly) {
  const Image image{2, 2, std::vector<std::uint8_t>(12, 0)};
  EXPECT_THROW(write_png("/nonexistent-dir/x.png", image), IoError);
  EXPECT_FALSE(std::filesystem::exists("/nonexistent-dir"));
  EXPECT_THROW(write_png(temp_path("bad.png"), Image{3, 3, {}}), InvalidArgument);
  EXPECT_FALSE(std::filesystem::exists(temp_path("bad.png")));
}
