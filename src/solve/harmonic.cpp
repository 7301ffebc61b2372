#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/solve/harmonic.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fairsurf {

Eigen::SparseMatrix<double> cotangent_laplacian(const Vertices& V, const Faces& F) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(F.rows()) * 12);
  for (int f = 0; f < F.rows(); ++f) {
    // The angle at corner k is opposite the edge (k+1, k+2).
    double cot[3];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
      const Eigen::Vector3d b = V.row(F(f, (k + 2) % 3)) - V.row(F(f, k));
      cot[k] = a.dot(b) / a.cross(b).norm();
    }
    // A degenerate face contributes nothing rather than infinity.
    if (!(std::isfinite(cot[0]) && std::isfinite(cot[1]) && std::isfinite(cot[2]))) continue;
    // The three scaled together, not clamped one by one: cot α cot β + cot β cot γ + cot γ cot α = 1
    // keeps the face's 3×3 block semi-definite, which clamping a needle's two sharp corners but not
    // its blunt one would break.
    const double largest = std::max({std::abs(cot[0]), std::abs(cot[1]), std::abs(cot[2])});
    const double scale = largest > kMaxCotangent ? kMaxCotangent / largest : 1.0;
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, (k + 1) % 3), j = F(f, (k + 2) % 3);
      const double half_cot = 0.5 * scale * cot[k];
      entries.emplace_back(i, j, half_cot);
      entries.emplace_back(j, i, half_cot);
      entries.emplace_back(i, i, -half_cot);
      entries.emplace_back(j, j, -half_cot);
    }
  }
  Eigen::SparseMatrix<double> L(V.rows(), V.rows());
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

namespace {

// ∆^k x = 0 determines a free vertex only through fixed data reached along free edges; a free
// component that touches no fixed vertex leaves the system singular (and, with a zero right-hand
// side, a direct solver may quietly return zeros). Returns such a vertex, or -1.
int unanchored_free_vertex(const Topology& topo, const Region& region) {
  std::vector<char> seen(topo.num_vertices, 0);
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

// The free rows of ∆^k at the current positions: the free-column block (the system, #free by #free)
// and the fixed columns times the fixed positions moved to the right-hand side (#free by 3).
void assemble(const Vertices& V, const Faces& F, const Region& region, int order,
              Eigen::SparseMatrix<double, Eigen::RowMajor>& system, Eigen::MatrixX3d& rhs) {
  const Eigen::SparseMatrix<double> L = cotangent_laplacian(V, F);
  const Eigen::VectorXd areas = vertex_areas(V, F);
  Eigen::VectorXd inverse_mass(areas.size());
  for (Eigen::Index i = 0; i < areas.size(); ++i)
    inverse_mass[i] = areas[i] > 0 ? 1.0 / areas[i] : 0.0;

  // M(M⁻¹L)^k = L(M⁻¹L)^(k−1): the rows of ∆^k scaled by the vertex areas, which keeps the system
  // as well conditioned as the plain Laplacian's powers allow. Only the free rows are formed, each
  // product in row storage (L is symmetric, so its column storage is its row storage).
  const int n = region.num_free();
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> L_rows(
      L.rows(), L.cols(), L.nonZeros(), L.outerIndexPtr(), L.innerIndexPtr(), L.valuePtr());
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows(n, L.cols());
  {
    std::vector<Eigen::Triplet<double>> picked;
    for (int r = 0; r < n; ++r)
      for (decltype(L_rows)::InnerIterator it(L_rows, region.free_vertices[r]); it; ++it)
        picked.emplace_back(r, static_cast<int>(it.col()), it.value());
    rows.setFromTriplets(picked.begin(), picked.end());
  }
  for (int k = 1; k < order; ++k) rows = rows * inverse_mass.asDiagonal() * L_rows;

  std::vector<Eigen::Triplet<double>> free_part;
  free_part.reserve(static_cast<std::size_t>(rows.nonZeros()));
  rhs = Eigen::MatrixX3d::Zero(n, 3);
  for (int r = 0; r < n; ++r)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, r); it; ++it) {
      const int c = region.free_index[it.col()];
      if (c >= 0)
        free_part.emplace_back(r, c, it.value());
      else
        rhs.row(r) -= it.value() * V.row(it.col());
    }
  system.resize(n, n);
  system.setFromTriplets(free_part.begin(), free_part.end());
}

bool same_pattern(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                  const Eigen::SparseMatrix<double, Eigen::RowMajor>& b) {
  if (a.rows() != b.rows() || a.nonZeros() != b.nonZeros()) return false;
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.rows() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
}

// Mean length of the edges with a free end.
double mean_free_edge_length(const Vertices& V, const Topology& topo, const Region& region) {
  double total = 0;
  int count = 0;
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e) {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    if (!region.is_free(a) && !region.is_free(b)) continue;
    total += (V.row(a) - V.row(b)).norm();
    ++count;
  }
  return count > 0 ? total / count : 0.0;
}

void check_options(const HarmonicOptions& options) {
  if (options.order < 1 || options.order > 3)
    throw InvalidArgument("harmonic_fair: order " + std::to_string(options.order) +
                          " is not 1, 2 or 3");
  if (options.iterations < 1)
    throw InvalidArgument("harmonic_fair: iterations must be at least 1, got " + std::to_string(options.iterations));
}

}  // namespace

HarmonicReport harmonic_fair(Vertices& V, const Faces& F, const Region& region,
                             const HarmonicOptions& options) {
  check_options(options);  // before the faces, as always
  return harmonic_fair(V, F, build_topology(F, static_cast<int>(V.rows())), region, options);
}

HarmonicReport harmonic_fair(Vertices& V, const Faces& F, const Topology& topo, const Region& region,
                             const HarmonicOptions& options) {
  check_options(options);
  if (topo.num_vertices != V.rows() || topo.num_faces != F.rows())
    throw InvalidArgument("harmonic_fair: the topology was built for another mesh");
  if (const int v = unanchored_free_vertex(topo, region); v >= 0)
    throw InvalidArgument("harmonic_fair: free vertex " + std::to_string(v) +
                          " is not connected to any fixed vertex, so the fairing is undetermined");
  const int n = region.num_free();
  const double tolerance = options.tolerance * mean_free_edge_length(V, topo, region);
  LinearSolverOptions solver_options = options.solver;
  solver_options.symmetric = true;  // the free block of L(M⁻¹L)^(k−1) is symmetric
  auto solver = make_linear_solver(solver_options);
  Eigen::SparseMatrix<double, Eigen::RowMajor> system, analyzed;
  Eigen::MatrixX3d rhs, x(n, 3), input(n, 3);
  for (int r = 0; r < n; ++r) input.row(r) = V.row(region.free_vertices[r]);
  HarmonicReport report{n, options.order, 0.0};
  try {
    for (int it = 0; it < options.iterations; ++it) {
      assemble(V, F, region, options.order, system, rhs);
      // The pattern is the connectivity's (unless a weight is exactly zero): analyze it once.
      if (!same_pattern(system, analyzed)) solver->analyze(system), analyzed = system;
      solver->factorize(system);
      report.backward_error = 0;
      for (int c = 0; c < 3; ++c) {
        x.col(c) = solver->solve(rhs.col(c));
        report.backward_error = std::max(report.backward_error, solver->report().backward_error);
      }
      double move = 0;
      for (int r = 0; r < n; ++r) move = std::max(move, (x.row(r) - V.row(region.free_vertices[r])).norm());
      // A re-evaluation that moves the vertices farther than the one before it is not contracting
      // (it can fold a large region): keep the previous solution.
      if (it > 0 && move > report.max_move) break;
      for (int r = 0; r < n; ++r) V.row(region.free_vertices[r]) = x.row(r);
      report.max_move = move;
      report.iterations = it + 1;
      if (report.max_move <= tolerance) break;
    }
  } catch (const Error&) {
    for (int r = 0; r < n; ++r) V.row(region.free_vertices[r]) = input.row(r);
    throw;
  }
  return report;
}

}  // namespace fairsurf
