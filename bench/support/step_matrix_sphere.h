// A stand-in for the flow's step matrix (method.md §5) on the unit icosphere, the mesh of method.md §5's
// reference timings (10 242 / 40 962 / 163 842 vertices at 5 / 6 / 7 subdivisions):
// A = I + (τ/h⁶)(L³ + β L² D), L the uniform graph Laplacian (valence minus adjacency), D the
// antisymmetric 1-ring difference D_ij = (z_j − z_i)/h, h the mean edge length. Same 3-ring stencil
// (≈ 37 non-zeros a row), same τ/h⁶ growth, non-symmetric for β ≠ 0.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/solve/linear_solver.h>

namespace fairsurf::bench {

/// Unit icosphere: the icosahedron with each triangle split into four `subdivisions` times, vertices
/// projected on the sphere; faces counter-clockwise seen from outside. 10·4^s + 2 vertices.
Mesh icosphere(int subdivisions);

/// The step-matrix proxy on icosphere(subdivisions).
SparseRowMatrix sphere_step_matrix_proxy(int subdivisions, double tau, double beta = 0.3);

}  // namespace fairsurf::bench
