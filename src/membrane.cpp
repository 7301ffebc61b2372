#include <fairsurf/errors.h>
#include <fairsurf/membrane.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <string>

namespace fairsurf {
namespace {

using Vec3 = Eigen::Vector3d;

// Faces with at least one free vertex: the only ones whose weights enter the free rows.
std::vector<int> faces_touching(const Faces& F, const std::vector<int>& free_index) {
  std::vector<int> faces;
  for (int f = 0; f < F.rows(); ++f)
    if (free_index[F(f, 0)] >= 0 || free_index[F(f, 1)] >= 0 || free_index[F(f, 2)] >= 0)
      faces.push_back(f);
  return faces;
}

double area_of(const Vertices& V, const Faces& F, const std::vector<int>& faces) {
  double area = 0.0;
  for (int f : faces) {
    const Vec3 a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

// The free rows of the cotangent Laplacian, −Σ_j w_ij (x_j − x_i) = 0, split into the matrix over
// free unknowns and the right-hand side from fixed neighbours. (Private until the `harmonic` module
// offers a cotangent Laplacian to share.)
void assemble(const Vertices& V, const Faces& F, const std::vector<int>& faces,
              const std::vector<int>& free_index, int num_free, SparseRowMatrix& A,
              Eigen::MatrixX3d& rhs) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(faces.size() * 12);
  rhs.setZero(num_free, 3);
  for (int f : faces)
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, k), j = F(f, (k + 1) % 3), o = F(f, (k + 2) % 3);
      const Vec3 u = V.row(i) - V.row(o), v = V.row(j) - V.row(o);
      const double twice_area = u.cross(v).norm();
      if (twice_area == 0.0) continue;  // a degenerate triangle has no cotangent; it adds nothing
      const double w = 0.5 * u.dot(v) / twice_area;  // ½ cot of the angle at o
      for (const auto& [row, col] : {std::pair{i, j}, std::pair{j, i}}) {
        const int r = free_index[row];
        if (r < 0) continue;
        triplets.emplace_back(r, r, w);
        if (free_index[col] >= 0)
          triplets.emplace_back(r, free_index[col], -w);
        else
          rhs.row(r) += w * V.row(col);
      }
    }
  A.resize(num_free, num_free);
  A.setFromTriplets(triplets.begin(), triplets.end());
}

}  // namespace

MembraneReport relax_membrane(Vertices& V, const Faces& F, std::span<const int> free_vertices,
                              const MembraneOptions& options) {
  if (options.iterations < 1)
    throw InvalidArgument("relax_membrane: iterations must be at least 1, got " +
                          std::to_string(options.iterations));
  if (free_vertices.empty()) throw InvalidArgument("relax_membrane: the free set is empty");
  std::vector<int> free_index(V.rows(), -1), free_list;
  for (int v : free_vertices) {
    if (v < 0 || v >= V.rows())
      throw InvalidArgument("relax_membrane: free vertex " + std::to_string(v) + " is out of range");
    if (free_index[v] < 0) free_index[v] = static_cast<int>(free_list.size()), free_list.push_back(v);
  }
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (F(f, k) < 0 || F(f, k) >= V.rows())
        throw InvalidArgument("relax_membrane: face " + std::to_string(f) + " has a vertex index out of range");
  const int n = static_cast<int>(free_list.size());
  const std::vector<int> faces = faces_touching(F, free_index);

  MembraneReport report;
  report.area.push_back(area_of(V, F, faces));
  auto solver = make_linear_solver(options.solver);
  SparseRowMatrix A;
  Eigen::MatrixX3d rhs;
  for (int it = 0; it < options.iterations; ++it) {
    assemble(V, F, faces, free_index, n, A, rhs);
    if (it == 0) solver->analyze(A);  // the pattern depends on connectivity only
    solver->factorize(A);
    Eigen::MatrixX3d x(n, 3);
    for (int c = 0; c < 3; ++c) x.col(c) = solver->solve(rhs.col(c));
    report.max_displacement = 0.0;
    for (int r = 0; r < n; ++r) {
      report.max_displacement = std::max(report.max_displacement, (x.row(r) - V.row(free_list[r])).norm());
      V.row(free_list[r]) = x.row(r);
    }
    report.area.push_back(area_of(V, F, faces));
    ++report.iterations;
  }
  return report;
}

}  // namespace fairsurf
