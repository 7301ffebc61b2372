// The rasterizer: orthographic projection, a z-buffer filled band by band, then per-sample Phong
// shading (interpolated vertex normals and an interpolated scalar looked up in the colour table),
// box-filtered down to pixels.
//
// Robustness and determinism: vertices are snapped to a fixed-point grid of 1/256 sample, so edge
// functions are exact 64-bit integers; a sample on a shared edge is covered by both triangles (no
// cracks) and the nearer one wins, ties going to the smaller face index. Each z-buffer band and each
// output row is owned by one thread, and every sample's value is a function of the scene alone, so
// the image does not depend on the number of threads or on their scheduling.
#include "render_internal.h"

#include <fairsurf/mesh/topology.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fairsurf::render_detail {
namespace {

constexpr std::int64_t kFixedOne = 256;           // fixed-point units per sample
constexpr std::int64_t kFixedHalf = kFixedOne / 2;  // sample centres sit at half-integers
constexpr double kMaxSampleCoordinate = 1e6;     // keeps products of fixed coordinates in int64
constexpr int kBandPixelRows = 8;  // output pixel rows per z-buffer band
constexpr Rgb8 kWireColor{20, 20, 20};
constexpr double kWireOpacity = 0.7;  // dense meshes keep some of their colour

struct ProjectedMesh {
  std::vector<std::int64_t> fx, fy;  ///< #V fixed-point sample coordinates (x right, y down)
  std::vector<double> depth;         ///< #V camera z (toward the viewer: larger is nearer)
  std::vector<char> valid;           ///< #V finite and on the fixed-point grid's safe range
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> normals;  ///< #V camera-space unit
};

ProjectedMesh project(const Mesh& mesh, const PanelCamera& camera) {
  const int n = mesh.num_vertices();
  ProjectedMesh p;
  p.fx.resize(n);
  p.fy.resize(n);
  p.depth.resize(n);
  p.valid.resize(n);
#pragma omp parallel for schedule(static)
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector3d c = camera.rotation * mesh.V.row(v).transpose();
    const double x = 0.5 * camera.width + camera.scale * (c.x() - camera.center_world.x());
    const double y = 0.5 * camera.height - camera.scale * (c.y() - camera.center_world.y());
    p.valid[v] = std::isfinite(x) && std::isfinite(y) && std::isfinite(c.z()) &&
                 std::abs(x) < kMaxSampleCoordinate && std::abs(y) < kMaxSampleCoordinate;
    p.fx[v] = p.valid[v] ? static_cast<std::int64_t>(std::floor(x * kFixedOne + 0.5)) : 0;
    p.fy[v] = p.valid[v] ? static_cast<std::int64_t>(std::floor(y * kFixedOne + 0.5)) : 0;
    p.depth[v] = c.z();
  }
  // Area-weighted vertex normals, rotated into camera space.
  Eigen::MatrixX3d face_normals;
  Eigen::VectorXd face_areas;
  face_normals_and_areas(mesh.V, mesh.F, face_normals, face_areas);
  p.normals.setZero(n, 3);
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (std::isfinite(face_areas[f]))
      for (int k = 0; k < 3; ++k) p.normals.row(mesh.F(f, k)) += face_areas[f] * face_normals.row(f);
#pragma omp parallel for schedule(static)
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector3d c = camera.rotation * p.normals.row(v).transpose();
    const double norm = c.norm();
    p.normals.row(v) = norm > 0 ? Eigen::Vector3d(c / norm) : Eigen::Vector3d(0, 0, 1);
  }
  return p;
}

/// A triangle on the fixed-point grid with its three edge functions; vertex order is made
/// counter-clockwise in sample space (positive doubled area) so "inside" is all edges >= 0.
struct ScreenTriangle {
  std::array<int, 3> corner;  ///< mesh vertex per corner
  std::array<std::int64_t, 3> x, y;
  std::int64_t area2 = 0;

  ScreenTriangle(const Mesh& mesh, const ProjectedMesh& p, int f) {
    for (int k = 0; k < 3; ++k) {
      corner[k] = mesh.F(f, k);
      x[k] = p.fx[corner[k]];
      y[k] = p.fy[corner[k]];
    }
    area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (area2 < 0) {
      std::swap(corner[1], corner[2]);
      std::swap(x[1], x[2]);
      std::swap(y[1], y[2]);
      area2 = -area2;
    }
  }
  /// Edge function of the edge opposite corner k at fixed-point (px, py); its barycentric weight
  /// is edge(k) / area2.
  std::int64_t edge(int k, std::int64_t px, std::int64_t py) const {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    return (x[b] - x[a]) * (py - y[a]) - (y[b] - y[a]) * (px - x[a]);
  }
};

bool face_drawable(const Mesh& mesh, const ProjectedMesh& p, int f) {
  return p.valid[mesh.F(f, 0)] && p.valid[mesh.F(f, 1)] && p.valid[mesh.F(f, 2)];
}

/// First and last sample index whose centre lies in [lo, hi] (fixed-point), clipped to [0, n-1].
std::pair<int, int> sample_span(std::int64_t lo, std::int64_t hi, int n) {
  const auto first = (lo - kFixedHalf + kFixedOne - 1) / kFixedOne;  // ceil for lo >= kFixedHalf
  const auto last = (hi - kFixedHalf) / kFixedOne;
  const std::int64_t clipped_first = lo < kFixedHalf ? 0 : first;
  return {static_cast<int>(std::max<std::int64_t>(0, clipped_first)),
          static_cast<int>(std::min<std::int64_t>(n - 1, hi < kFixedHalf ? -1 : last))};
}

std::pair<int, int> row_span(const Mesh& mesh, const ProjectedMesh& p, int f, int height) {
  const auto [lo, hi] = std::minmax({p.fy[mesh.F(f, 0)], p.fy[mesh.F(f, 1)], p.fy[mesh.F(f, 2)]});
  return sample_span(lo, hi, height);
}

/// The z-buffer of one band of sample rows: depth and visible face (-1: background) per sample.
struct BandBuffer {
  int width = 0, row_begin = 0, rows = 0;
  std::vector<double> depth;
  std::vector<int> face;

  void reset(int band_width, int band_row_begin, int band_rows) {
    width = band_width;
    row_begin = band_row_begin;
    rows = band_rows;
    depth.assign(static_cast<std::size_t>(width) * rows, -std::numeric_limits<double>::infinity());
    face.assign(static_cast<std::size_t>(width) * rows, -1);
  }
  int face_at(int i, int j) const { return face[static_cast<std::size_t>(j - row_begin) * width + i]; }
};

void rasterize_face(const Mesh& mesh, const ProjectedMesh& p, int f, BandBuffer& z) {
  const ScreenTriangle t(mesh, p, f);
  if (t.area2 == 0) return;
  const auto [x_lo, x_hi] = std::minmax({t.x[0], t.x[1], t.x[2]});
  const auto [y_lo, y_hi] = std::minmax({t.y[0], t.y[1], t.y[2]});
  const auto [i0, i1] = sample_span(x_lo, x_hi, z.width);
  auto [j0, j1] = sample_span(y_lo, y_hi, z.row_begin + z.rows);
  j0 = std::max(j0, z.row_begin);
  const double inv_area = 1.0 / static_cast<double>(t.area2);
  const std::array<double, 3> depth{p.depth[t.corner[0]], p.depth[t.corner[1]], p.depth[t.corner[2]]};
  std::array<std::int64_t, 3> step{};  // change of each edge function from one sample to the next
  for (int k = 0; k < 3; ++k) step[k] = -(t.y[(k + 2) % 3] - t.y[(k + 1) % 3]) * kFixedOne;
  for (int j = j0; j <= j1; ++j) {
    const std::int64_t py = j * kFixedOne + kFixedHalf, px = i0 * kFixedOne + kFixedHalf;
    std::array<std::int64_t, 3> e{t.edge(0, px, py), t.edge(1, px, py), t.edge(2, px, py)};
    const std::size_t row = static_cast<std::size_t>(j - z.row_begin) * z.width;
    for (int i = i0; i <= i1; ++i, e[0] += step[0], e[1] += step[1], e[2] += step[2]) {
      if (e[0] < 0 || e[1] < 0 || e[2] < 0) continue;
      const double d = (e[0] * depth[0] + e[1] * depth[1] + e[2] * depth[2]) * inv_area;
      const std::size_t s = row + i;
      if (d > z.depth[s] || (d == z.depth[s] && f < z.face[s])) {
        z.depth[s] = d;
        z.face[s] = f;
      }
    }
  }
}

/// Faces binned by the bands of sample rows they touch (counting sort; index order within a band).
struct FaceBins {
  std::vector<int> offsets;  ///< #bands+1
  std::vector<int> faces;

  FaceBins(const Mesh& mesh, const ProjectedMesh& p, int height, int band_rows) {
    const int bands = (height + band_rows - 1) / band_rows;
    // First and last band of every face (last < first: not drawn), computed in parallel; the
    // counting sort that follows reads them sequentially.
    const int n = mesh.num_faces();
    std::vector<int> first(n), last(n);
#pragma omp parallel for schedule(static)
    for (int f = 0; f < n; ++f) {
      const auto [j0, j1] = face_drawable(mesh, p, f) ? row_span(mesh, p, f, height) : std::pair{0, -1};
      first[f] = j0 <= j1 ? j0 / band_rows : 0;
      last[f] = j0 <= j1 ? j1 / band_rows : -1;
    }
    offsets.assign(bands + 1, 0);
    for (int f = 0; f < n; ++f)
      for (int b = first[f]; b <= last[f]; ++b) ++offsets[b + 1];
    for (int b = 0; b < bands; ++b) offsets[b + 1] += offsets[b];
    faces.resize(offsets[bands]);
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int f = 0; f < n; ++f)
      for (int b = first[f]; b <= last[f]; ++b) faces[fill[b]++] = f;
  }
  int bands() const { return static_cast<int>(offsets.size()) - 1; }
};

/// Shades one covered sample; returns its colour.
class SampleShader {
 public:
  SampleShader(const Mesh& mesh, const Eigen::VectorXd& values, const ProjectedMesh& p,
               const ShadeOptions& options)
      : mesh_(mesh), values_(values), p_(p), options_(options) {}

  Rgb8 shade(int f, int i, int j) const {
    const ScreenTriangle t(mesh_, p_, f);
    const std::int64_t px = i * kFixedOne + kFixedHalf, py = j * kFixedOne + kFixedHalf;
    const double inv_area = 1.0 / static_cast<double>(t.area2);
    std::array<double, 3> w{};
    for (int k = 0; k < 3; ++k) w[k] = static_cast<double>(t.edge(k, px, py)) * inv_area;
    std::array<double, 3> rgb = base_color(t, w);
    if (options_.shading) light(t, w, rgb);
    if (options_.wireframe && near_edge(t, px, py)) {
      const std::array<double, 3> wire{double(kWireColor.r), double(kWireColor.g), double(kWireColor.b)};
      for (int k = 0; k < 3; ++k) rgb[k] = (1 - kWireOpacity) * rgb[k] + kWireOpacity * wire[k];
    }
    return {to_byte(rgb[0]), to_byte(rgb[1]), to_byte(rgb[2])};
  }

 private:
  static std::uint8_t to_byte(double c) { return static_cast<std::uint8_t>(std::clamp(c, 0.0, 255.0) + 0.5); }

  std::array<double, 3> base_color(const ScreenTriangle& t, const std::array<double, 3>& w) const {
    Rgb8 c = kGrey;
    if (options_.color_map != ColorMap::none && values_.size() > 0) {
      const double value = w[0] * values_[t.corner[0]] + w[1] * values_[t.corner[1]] + w[2] * values_[t.corner[2]];
      c = map_color(options_.color_map, value, options_.range);
    }
    return {double(c.r), double(c.g), double(c.b)};
  }

  // Headlight from the upper left: ambient + Lambert + Blinn-Phong highlight; two-sided, so the
  // inside of an open surface is lit like the outside.
  void light(const ScreenTriangle& t, const std::array<double, 3>& w, std::array<double, 3>& rgb) const {
    Eigen::Vector3d n = w[0] * p_.normals.row(t.corner[0]) + w[1] * p_.normals.row(t.corner[1]) +
                        w[2] * p_.normals.row(t.corner[2]);
    const double norm = n.norm();
    n = norm > 0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d(0, 0, 1);
    if (n.z() < 0) n = -n;
    static const Eigen::Vector3d kLight = Eigen::Vector3d(-0.3, 0.4, 1.0).normalized();
    static const Eigen::Vector3d kHalf = (kLight + Eigen::Vector3d(0, 0, 1)).normalized();
    const double diffuse = std::max(0.0, n.dot(kLight));
    double highlight = std::max(0.0, n.dot(kHalf));
    for (int k = 0; k < 5; ++k) highlight *= highlight;  // exponent 32
    const double intensity = 0.3 + 0.7 * diffuse;
    for (double& c : rgb) c = c * intensity + 60.0 * highlight;
  }

  bool near_edge(const ScreenTriangle& t, std::int64_t px, std::int64_t py) const {
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const double length = std::hypot(double(t.x[b] - t.x[a]), double(t.y[b] - t.y[a]));
      const double distance = static_cast<double>(t.edge(k, px, py)) / length / kFixedOne;
      if (distance < options_.wire_half_width) return true;
    }
    return false;
  }

  const Mesh& mesh_;
  const Eigen::VectorXd& values_;
  const ProjectedMesh& p_;
  const ShadeOptions& options_;
};

}  // namespace

void draw_panel(const Mesh& mesh, const Eigen::VectorXd& values, const PanelCamera& camera,
                const ShadeOptions& shade, int supersampling, Image& image, int x0, int y0) {
  const ProjectedMesh p = project(mesh, camera);
  const SampleShader shader(mesh, values, p, shade);
  const int ss = supersampling, samples = ss * ss, band_rows = kBandPixelRows * ss;
  const int out_w = camera.width / ss, out_h = camera.height / ss;
  const FaceBins bins(mesh, p, camera.height, band_rows);
  // One band at a time per thread: rasterize its faces, then shade and filter its pixel rows. The
  // band's z-buffer stays small (cache-resident) whatever the image size.
#pragma omp parallel
  {
    BandBuffer z;
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < bins.bands(); ++b) {
      z.reset(camera.width, b * band_rows, std::min(band_rows, camera.height - b * band_rows));
      for (int k = bins.offsets[b]; k < bins.offsets[b + 1]; ++k) rasterize_face(mesh, p, bins.faces[k], z);
      for (int y = b * kBandPixelRows; y < std::min(out_h, (b + 1) * kBandPixelRows); ++y)
        for (int x = 0; x < out_w; ++x) {
          std::array<int, 3> sum{0, 0, 0};
          for (int j = y * ss; j < (y + 1) * ss; ++j)
            for (int i = x * ss; i < (x + 1) * ss; ++i) {
              const int f = z.face_at(i, j);
              const Rgb8 c = f < 0 ? shade.background : shader.shade(f, i, j);
              sum[0] += c.r;
              sum[1] += c.g;
              sum[2] += c.b;
            }
          const std::size_t o = 3 * (static_cast<std::size_t>(y0 + y) * image.width + (x0 + x));
          for (int k = 0; k < 3; ++k) image.rgb[o + k] = static_cast<std::uint8_t>((sum[k] + samples / 2) / samples);
        }
    }
  }
}

}  // namespace fairsurf::render_detail
