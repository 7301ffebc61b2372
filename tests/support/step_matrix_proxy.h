// A stand-in for the flow's step matrix (method.md §5) with its structure and its scaling, for the tests
// of the linear solvers: A = I + (τ/h⁶)(L³ + β L² D) on an n by n periodic grid of
// triangles (a flat torus, valence 6, h = 1/n). L is the uniform graph Laplacian (degree minus
// adjacency, positive semi-definite) and D the antisymmetric difference along the grid's first axis,
// so A has the step matrix's 3-ring stencil (37 non-zeros a row), entries growing like τ/h⁶, and is
// non-symmetric for β ≠ 0. (bench/support/step_matrix_sphere.h builds the same on an icosphere.)
#pragma once

#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace fairsurf::test {

inline Eigen::SparseMatrix<double, Eigen::RowMajor> step_matrix_proxy(int n, double tau, double beta = 0.3) {
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const int size = n * n;
  const auto index = [n](int i, int j) { return ((j + n) % n) * n + (i + n) % n; };
  // The six neighbours of a vertex on a grid whose quads are split along the (1, 1) diagonal.
  constexpr std::array<std::array<int, 2>, 6> kNeighbours{
      {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}}};
  std::vector<Eigen::Triplet<double>> laplacian, difference;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int row = index(i, j);
      laplacian.emplace_back(row, row, 6.0);
      for (const auto& d : kNeighbours) laplacian.emplace_back(row, index(i + d[0], j + d[1]), -1.0);
      difference.emplace_back(row, index(i + 1, j), 0.5);
      difference.emplace_back(row, index(i - 1, j), -0.5);
    }
  Matrix L(size, size), D(size, size), identity(size, size);
  L.setFromTriplets(laplacian.begin(), laplacian.end());
  D.setFromTriplets(difference.begin(), difference.end());
  identity.setIdentity();
  const Matrix L2 = L * L;
  const Matrix L3 = L2 * L;
  const Matrix L2D = L2 * D;
  const double h = 1.0 / n, scale = tau / (h * h * h * h * h * h);
  Matrix A = identity + scale * (L3 + beta * L2D);
  A.makeCompressed();
  return A;
}

}  // namespace fairsurf::test
