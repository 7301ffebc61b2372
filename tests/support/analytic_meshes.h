// Analytic-surface meshes for the numerical tests (method.md §8): spheres, an ellipsoid, an open
// cylinder, torus grids and a saddle patch. Every mesh is counter-clockwise with the normal outward
// (closed surfaces) or along +z / away from the axis (patches), and every vertex lies exactly on its
// surface, so that analytic curvatures and test functions can be evaluated at the vertices.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

namespace fairsurf::test {

/// fairsurf::mean_edge_length over the mesh's own topology: each edge once.
double mean_edge_length(const Mesh& m);

/// Icosahedron subdivided `level` times (each triangle into four), projected on the sphere of
/// `radius` centred at the origin: 10·4^level + 2 vertices, valence 5 at the 12 original ones.
Mesh icosphere(int level, double radius = 1.0);

/// icosphere(level, radius) with every vertex moved tangentially by a uniformly random offset of at
/// most `amplitude` times the mean edge length (fixed `seed`), then projected back on the sphere.
Mesh jittered_sphere(int level, double radius, double amplitude, unsigned seed = 1);

/// icosphere(level, 1) scaled by (a, b, c): the ellipsoid x²/a² + y²/b² + z²/c² = 1.
Mesh ellipsoid(int level, double a, double b, double c);
/// Mean curvature (outward normal, H < 0) and Gaussian curvature of that ellipsoid at a point on it.
double ellipsoid_mean_curvature(const Eigen::Vector3d& p, double a, double b, double c);
double ellipsoid_gaussian_curvature(const Eigen::Vector3d& p, double a, double b, double c);

/// A mesh with the surface parameters (u, v) of each vertex (#V by 2).
struct ParametricMesh {
  Mesh mesh;
  Eigen::MatrixX2d uv;
};

/// Torus ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) sampled on an n (in u) by m (in v)
/// grid, each quad split along the same diagonal (valence 6 everywhere). With jitter > 0 every
/// parameter is moved by a uniformly random offset of at most `jitter` grid spacings (fixed seed),
/// which keeps vertices on the torus but makes the mesh irregular. Vertex (i, j) has index j·n + i.
ParametricMesh torus_grid(int n, int m, double R, double r, double jitter = 0.0, unsigned seed = 1);

/// Open cylinder of `radius` around the z axis, z ∈ [0, height], `around` by (`along` + 1) vertices.
Mesh open_cylinder(int around, int along, double radius, double height);

/// The saddle z = x² − y² over [−w, w]², (n+1) by (n+1) vertices, normal towards +z; n even, so
/// that the origin is vertex (n/2)·(n+1) + n/2.
Mesh saddle_patch(int n, double w);

}  // namespace fairsurf::test
