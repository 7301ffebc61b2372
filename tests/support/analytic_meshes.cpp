#include "analytic_meshes.h"

#include <fairsurf/applications/scenes.h>
#include <fairsurf/mesh/topology.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace fairsurf::test {
namespace {

// Faces of an nu by nv vertex grid (vertex (i, j) = j·nu + i), counter-clockwise in (i, j); a
// periodic direction wraps its last column of quads around to the first.
Faces grid_faces(int nu, int nv, bool periodic_u, bool periodic_v) {
  const int qu = periodic_u ? nu : nu - 1, qv = periodic_v ? nv : nv - 1;
  Faces F(2 * qu * qv, 3);
  int f = 0;
  for (int j = 0; j < qv; ++j)
    for (int i = 0; i < qu; ++i) {
      const int i1 = (i + 1) % nu, j1 = (j + 1) % nv;
      const int a = j * nu + i, b = j * nu + i1, c = j1 * nu + i, d = j1 * nu + i1;
      F.row(f++) << a, b, d;
      F.row(f++) << a, d, c;
    }
  return F;
}

}  // namespace

double mean_edge_length(const Mesh& m) {
  return fairsurf::mean_edge_length(m.V, build_topology(m.F, m.num_vertices()));
}

Mesh icosphere(int level, double radius) { return fairsurf::icosphere(level, radius); }

Mesh jittered_sphere(int level, double radius, double amplitude, unsigned seed) {
  Mesh m = icosphere(level, radius);
  const double step = amplitude * mean_edge_length(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int v = 0; v < m.V.rows(); ++v) {
    const Eigen::Vector3d n = m.V.row(v).normalized();
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    Eigen::Vector3d offset;
    do offset = unit(rng) * e1 + unit(rng) * e2;
    while (offset.norm() > 1.0);
    m.V.row(v) = radius * (m.V.row(v).transpose() + step * offset).normalized();
  }
  return m;
}

Mesh ellipsoid(int level, double a, double b, double c) {
  Mesh m = icosphere(level, 1.0);
  m.V = m.V * Eigen::Vector3d(a, b, c).asDiagonal();
  return m;
}

double ellipsoid_mean_curvature(const Eigen::Vector3d& p, double a, double b, double c) {
  const double h = std::sqrt(p.x() * p.x() / std::pow(a, 4) + p.y() * p.y() / std::pow(b, 4) +
                             p.z() * p.z() / std::pow(c, 4));
  return (p.squaredNorm() - a * a - b * b - c * c) / (2.0 * a * a * b * b * c * c * h * h * h);
}

double ellipsoid_gaussian_curvature(const Eigen::Vector3d& p, double a, double b, double c) {
  const double h2 = p.x() * p.x() / std::pow(a, 4) + p.y() * p.y() / std::pow(b, 4) +
                    p.z() * p.z() / std::pow(c, 4);
  return 1.0 / (a * a * b * b * c * c * h2 * h2);
}

ParametricMesh torus_grid(int n, int m, double R, double r, double jitter, unsigned seed) {
  ParametricMesh out;
  out.uv.resize(n * m, 2);
  out.mesh.V.resize(n * m, 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-jitter, jitter);
  const double du = 2.0 * std::numbers::pi / n, dv = 2.0 * std::numbers::pi / m;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = (i + (jitter > 0 ? unit(rng) : 0.0)) * du;
      const double v = (j + (jitter > 0 ? unit(rng) : 0.0)) * dv;
      const int k = j * n + i;
      out.uv.row(k) << u, v;
      const double rho = R + r * std::cos(v);
      out.mesh.V.row(k) << rho * std::cos(u), rho * std::sin(u), r * std::sin(v);
    }
  out.mesh.F = grid_faces(n, m, true, true);
  return out;
}

Mesh open_cylinder(int around, int along, double radius, double height) {
  Mesh m;
  m.V.resize(around * (along + 1), 3);
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const double theta = 2.0 * std::numbers::pi * i / around;
      m.V.row(j * around + i) << radius * std::cos(theta), radius * std::sin(theta),
          height * j / along;
    }
  m.F = grid_faces(around, along + 1, true, false);
  return m;
}

Mesh saddle_patch(int n, double w) {
  Mesh m;
  m.V.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -w + 2.0 * w * i / n, y = -w + 2.0 * w * j / n;
      m.V.row(j * (n + 1) + i) << x, y, x * x - y * y;
    }
  m.F = grid_faces(n + 1, n + 1, false, false);
  return m;
}

}  // namespace fairsurf::test
