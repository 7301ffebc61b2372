// Closed analytic meshes for the rendering tests and benchmark (header only, so that bench/ can use
// the same generators without linking GoogleTest): a UV sphere and a torus.
#pragma once

#include <fairsurf/mesh.h>

#include <cmath>
#include <numbers>

namespace fairsurf::test {

/// Grid of (rings-1) latitude circles of `segments` vertices plus two poles, triangles oriented with
/// normals pointing away from the centre. Vertex 0 is the north pole (+y), the last the south pole.
inline Mesh uv_sphere(double radius, int rings, int segments) {
  Mesh m;
  const int n = (rings - 1) * segments + 2;
  m.V.resize(n, 3);
  m.V.row(0) << 0, radius, 0;
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = std::numbers::pi * i / rings, phi = 2 * std::numbers::pi * j / segments;
      m.V.row(1 + (i - 1) * segments + j) << radius * std::sin(theta) * std::cos(phi), radius * std::cos(theta),
          -radius * std::sin(theta) * std::sin(phi);
    }
  m.V.row(n - 1) << 0, -radius, 0;
  m.F.resize(2 * segments * (rings - 1), 3);
  int f = 0;
  const auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) {
    m.F.row(f++) << 0, ring(1, j), ring(1, j + 1);
    m.F.row(f++) << n - 1, ring(rings - 1, j + 1), ring(rings - 1, j);
  }
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      m.F.row(f++) << ring(i, j), ring(i + 1, j), ring(i + 1, j + 1);
      m.F.row(f++) << ring(i, j), ring(i + 1, j + 1), ring(i, j + 1);
    }
  return m;
}

/// Torus around the y axis: tube centre radius R, tube radius r; nu segments around the axis and nv
/// around the tube. Vertex (i, j) has index i*nv+j; its angle around the tube is 2*pi*j/nv, with j = 0
/// on the outer equator.
inline Mesh torus(double R, double r, int nu, int nv) {
  Mesh m;
  m.V.resize(nu * nv, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
      const double rho = R + r * std::cos(v);
      m.V.row(i * nv + j) << rho * std::cos(u), r * std::sin(v), -rho * std::sin(u);
    }
  m.F.resize(2 * nu * nv, 3);
  int f = 0;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
      m.F.row(f++) << a, b, c;
      m.F.row(f++) << a, c, d;
    }
  return m;
}

/// Gaussian curvature of that torus at vertex (i, j): cos(v) / (r (R + r cos v)), per vertex.
inline Eigen::VectorXd torus_gaussian_curvature(double R, double r, int nu, int nv) {
  Eigen::VectorXd K(nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double v = 2 * std::numbers::pi * j / nv;
      K[i * nv + j] = std::cos(v) / (r * (R + r * std::cos(v)));
    }
  return K;
}

}  // namespace fairsurf::test
