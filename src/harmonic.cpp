#include <fairsurf/errors.h>
#include <fairsurf/harmonic.h>
#include <fairsurf/topology.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace fairsurf {

Eigen::SparseMatrix<double> cotangent_laplacian(const Vertices& V, const Faces& F) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(F.rows()) * 12);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k is opposite the edge (k+1, k+2).
      const int o = F(f, k), i = F(f, (k + 1) % 3), j = F(f, (k + 2) % 3);
      const Eigen::Vector3d a = V.row(i) - V.row(o), b = V.row(j) - V.row(o);
      const double sine = a.cross(b).norm();
      if (sine == 0) continue;  // a degenerate face contributes nothing rather than infinity
      const double half_cot = 0.5 * a.dot(b) / sine;
      entries.emplace_back(i, j, half_cot);
      entries.emplace_back(j, i, half_cot);
      entries.emplace_back(i, i, -half_cot);
      entries.emplace_back(j, j, -half_cot);
    }
  Eigen::SparseMatrix<double> L(V.rows(), V.rows());
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

namespace {

// ∆^k x = 0 determines a free vertex only through fixed data reached along free edges; a free
// component that touches no fixed vertex leaves the system singular (and, with a zero right-hand
// side, a direct solver may quietly return zeros). Returns such a vertex, or -1.
int unanchored_free_vertex(const Faces& F, int num_vertices, const Region& region) {
  const Topology topo = build_topology(F, num_vertices);
  std::vector<char> seen(num_vertices, 0);
  std::vector<int> stack;
  for (int start : region.free_vertices) {
    if (seen[start]) continue;
    bool anchored = false;
    seen[start] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int w : topo.vertex_vertices.row(v)) {
        if (!region.is_free(w)) anchored = true;
        else if (!seen[w]) seen[w] = 1, stack.push_back(w);
      }
    }
    if (!anchored) return start;
  }
  return -1;
}

}  // namespace

HarmonicReport harmonic_fair(Vertices& V, const Faces& F, const Region& region,
                             const HarmonicOptions& options) {
  if (options.order < 1 || options.order > 3)
    throw InvalidArgument("harmonic_fair: order " + std::to_string(options.order) +
                          " is not 1, 2 or 3");
  if (const int v = unanchored_free_vertex(F, static_cast<int>(V.rows()), region); v >= 0)
    throw InvalidArgument("harmonic_fair: free vertex " + std::to_string(v) +
                          " is not connected to any fixed vertex, so the fairing is undetermined");
  const Eigen::SparseMatrix<double> L = cotangent_laplacian(V, F);
  const Eigen::VectorXd areas = vertex_areas(V, F);
  Eigen::VectorXd inverse_mass(areas.size());
  for (Eigen::Index i = 0; i < areas.size(); ++i)
    inverse_mass[i] = areas[i] > 0 ? 1.0 / areas[i] : 0.0;

  // M(M⁻¹L)^k = L(M⁻¹L)^(k−1): the rows of ∆^k scaled by the vertex areas, which keeps the system
  // as well conditioned as the plain Laplacian's powers allow.
  Eigen::SparseMatrix<double> A = L;
  for (int k = 1; k < options.order; ++k) A = (A * inverse_mass.asDiagonal() * L).pruned();

  // Split into free columns (unknowns) and fixed columns (data) for the free rows.
  const int n = region.num_free();
  std::vector<Eigen::Triplet<double>> free_part;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(n, 3);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = A;
  for (int r = 0; r < n; ++r) {
    const int v = region.free_vertices[r];
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, v); it; ++it) {
      const int c = region.free_index[it.col()];
      if (c >= 0)
        free_part.emplace_back(r, c, it.value());
      else
        rhs.row(r) -= it.value() * V.row(it.col());
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> system(n, n);
  system.setFromTriplets(free_part.begin(), free_part.end());

  auto solver = make_linear_solver(options.solver);
  solver->analyze(system);
  solver->factorize(system);
  HarmonicReport report{n, options.order, 0.0};
  for (int c = 0; c < 3; ++c) {
    const Eigen::VectorXd x = solver->solve(rhs.col(c));
    report.backward_error = std::max(report.backward_error, solver->report().backward_error);
    for (int r = 0; r < n; ++r) V(region.free_vertices[r], c) = x[r];
  }
  return report;
}

}  // namespace fairsurf
