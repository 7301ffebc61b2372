#include <fairsurf/geometry/operators.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include "parallel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fairsurf {
namespace {

using Vector5d = Eigen::Matrix<double, 5, 1>;

// The fitted surface's differential geometry at one vertex, and the functionals λ that turn a
// column of C_i into stencil weights (method.md §3.4).
struct LocalGeometry {
  Eigen::Vector3d t1, t2, n;
  double H = 0, K = 0;
  double g11 = 0, g12 = 0, g22 = 0;  // inverse metric g^αβ
  double T11 = 0, T12 = 0, T22 = 0;  // T^αβ = adj(b)/g
  Vector5d laplace, giaquinta;       // λ for ∆ and □
};

bool has_fit(FitStatus s) {
  return s == FitStatus::kOk || s == FitStatus::kFold || s == FitStatus::kIllConditioned;
}

const double* columns_of(const QuadraticFits& fits, int i) {
  return fits.coefficients.data() + 5 * static_cast<std::ptrdiff_t>(fits.neighbours.offsets[i]);
}

// λ = (−m^αβ Γ¹_αβ, −m^αβ Γ²_αβ, 2m¹¹, 2m¹², 2m²²) for a symmetric tensor m (g⁻¹ or T).
Vector5d second_order_functional(double m11, double m12, double m22, const double gamma[2][3]) {
  Vector5d lambda;
  for (int c = 0; c < 2; ++c)
    lambda[c] = -(m11 * gamma[c][0] + 2.0 * m12 * gamma[c][1] + m22 * gamma[c][2]);
  lambda.tail<3>() << 2.0 * m11, 2.0 * m12, 2.0 * m22;
  return lambda;
}

LocalGeometry local_geometry(const QuadraticFits& fits, const Vertices& V, int i) {
  // a_r = Σ_j C_i(r, j) (x_j − x_i); t₁ = a₁, t₂ = a₂, t₁₁ = 2a₃, t₁₂ = a₄, t₂₂ = 2a₅.
  Eigen::Matrix<double, 5, 3> a = Eigen::Matrix<double, 5, 3>::Zero();
  const double* C = columns_of(fits, i);
  const Eigen::RowVector3d xi = V.row(i);
  for (int j : fits.neighbours.row(i)) {
    a.noalias() += Eigen::Map<const Vector5d>(C) * (V.row(j) - xi);
    C += 5;
  }
  LocalGeometry geo;
  geo.t1 = a.row(0).transpose();
  geo.t2 = a.row(1).transpose();
  const Eigen::Vector3d t11 = 2.0 * a.row(2).transpose(), t12 = a.row(3).transpose(),
                        t22 = 2.0 * a.row(4).transpose();
  const double G11 = geo.t1.dot(geo.t1), G12 = geo.t1.dot(geo.t2), G22 = geo.t2.dot(geo.t2);
  const double g = G11 * G22 - G12 * G12;
  geo.g11 = G22 / g, geo.g12 = -G12 / g, geo.g22 = G11 / g;
  geo.n = geo.t1.cross(geo.t2).normalized();
  const double b11 = geo.n.dot(t11), b12 = geo.n.dot(t12), b22 = geo.n.dot(t22);
  geo.H = 0.5 * (geo.g11 * b11 + 2.0 * geo.g12 * b12 + geo.g22 * b22);
  geo.K = (b11 * b22 - b12 * b12) / g;
  geo.T11 = b22 / g, geo.T12 = -b12 / g, geo.T22 = b11 / g;
  // Γ^γ_αβ = g^γδ t_δ·t_αβ, with αβ ∈ {11, 12, 22}.
  const Eigen::Vector3d* second[3] = {&t11, &t12, &t22};
  double gamma[2][3];
  for (int k = 0; k < 3; ++k) {
    const double p1 = geo.t1.dot(*second[k]), p2 = geo.t2.dot(*second[k]);
    gamma[0][k] = geo.g11 * p1 + geo.g12 * p2;
    gamma[1][k] = geo.g12 * p1 + geo.g22 * p2;
  }
  geo.laplace = second_order_functional(geo.g11, geo.g12, geo.g22, gamma);
  geo.giaquinta = second_order_functional(geo.T11, geo.T12, geo.T22, gamma);
  return geo;
}

void store_geometry(SurfaceGeometry& out, int i, const Eigen::Vector3d& n, double H, double K) {
  out.normal.row(i) = n;
  out.H[i] = H;
  out.K[i] = K;
  const double root = std::sqrt(std::max(H * H - K, 0.0));
  out.k1[i] = H + root;
  out.k2[i] = H - root;
}

// Sized without initialization: evaluate_vertices writes every entry, in parallel.
void resize_geometry(SurfaceGeometry& out, int n) {
  out.normal.resize(n, 3);
  out.H.resize(n);
  out.K.resize(n);
  out.k1.resize(n);
  out.k2.resize(n);
}

// Writes every vertex's geometry (zeros and N0 where the fit is unusable) and hands each vertex's
// local geometry, or nullptr, to write_row.
template <class RowWriter>
void evaluate_vertices(const QuadraticFits& fits, const Vertices& V, SurfaceGeometry& out,
                       RowWriter write_row) {
  const int n = fits.num_vertices();
  resize_geometry(out, n);
#pragma omp parallel for if (detail::worth_parallel(n)) schedule(dynamic, 512)
  for (int i = 0; i < n; ++i) {
    if (!has_fit(fits.status[i])) {
      store_geometry(out, i, fits.frame_normal.row(i).transpose(), 0.0, 0.0);
      write_row(i, nullptr);
      continue;
    }
    const LocalGeometry geo = local_geometry(fits, V, i);
    store_geometry(out, i, geo.n, geo.H, geo.K);
    write_row(i, &geo);
  }
  out.area = vertex_areas(V, fits.faces);
}

void check_size(const QuadraticFits& fits, const Vertices& V, const char* function) {
  if (V.rows() != fits.num_vertices())
    throw InvalidArgument(std::string(function) + ": " + std::to_string(V.rows()) +
                          " positions for fits over " + std::to_string(fits.num_vertices()) +
                          " vertices");
}

// Length of row i of the pattern N(i) ∪ {i} (empty where not fitted).
int pattern_row_length(const QuadraticFits& fits, int i) {
  return fits.neighbourhood[i] == Neighbourhood::kNotFitted ? 0 : fits.neighbours.size(i) + 1;
}

// Row offsets of the pattern.
std::vector<int> pattern_offsets(const QuadraticFits& fits) {
  const int n = fits.num_vertices();
  std::vector<int> outer(n + 1, 0);
  for (int i = 0; i < n; ++i) outer[i + 1] = outer[i] + pattern_row_length(fits, i);
  return outer;
}

// Every operator of `ops`, in a fixed order: L∆, L□, G_x, G_y, G_z, D_x, D_y, D_z.
std::array<SparseRowMatrix*, 8> all_operators(SurfaceOperators& ops) {
  return {&ops.laplace,         &ops.giaquinta,       &ops.gradient[0],        &ops.gradient[1],
          &ops.gradient[2],     &ops.second_gradient[0], &ops.second_gradient[1],
          &ops.second_gradient[2]};
}

// Sizes every operator for the pattern and writes its row offsets and column indices (N(i) with i
// inserted in order). Rows are filled in parallel, so the pages of the large arrays are first
// touched by the threads that later write their values.
void build_patterns(const QuadraticFits& fits, SurfaceOperators& ops) {
  const int n = fits.num_vertices();
  const std::vector<int> outer = pattern_offsets(fits);
  const auto matrices = all_operators(ops);
  for (SparseRowMatrix* m : matrices) {
    m->resize(n, n);
    m->resizeNonZeros(outer.back());
  }
#pragma omp parallel for if (detail::worth_parallel(n)) schedule(dynamic, 512)
  for (int i = 0; i < n; ++i) {
    for (SparseRowMatrix* m : matrices) m->outerIndexPtr()[i + 1] = outer[i + 1];
    if (outer[i] == outer[i + 1]) continue;
    const auto row = fits.neighbours.row(i);
    const auto split = std::lower_bound(row.begin(), row.end(), i);
    for (SparseRowMatrix* m : matrices) {
      int* inner = m->innerIndexPtr() + outer[i];
      inner = std::copy(row.begin(), split, inner);
      *inner++ = i;
      std::copy(split, row.end(), inner);
    }
  }
}

// Whether every operator of `ops` has the fits' pattern row lengths (checked in one parallel pass).
bool has_pattern(const QuadraticFits& fits, SurfaceOperators& ops) {
  const int n = fits.num_vertices();
  const auto matrices = all_operators(ops);
  for (const SparseRowMatrix* m : matrices)
    if (m->rows() != n || m->cols() != n || !m->isCompressed()) return false;
  bool same = true;
#pragma omp parallel for if (detail::worth_parallel(n)) schedule(static) reduction(&& : same)
  for (int i = 0; i < n; ++i) {
    const int length = pattern_row_length(fits, i);
    for (const SparseRowMatrix* m : matrices)
      same = same && m->outerIndexPtr()[i + 1] - m->outerIndexPtr()[i] == length;
  }
  return same;
}

// Fills row i of every operator: w_ij at the neighbours' slots, −Σ_j w_ij on the diagonal.
void write_operator_row(const QuadraticFits& fits, int i, const LocalGeometry* geo,
                        SurfaceOperators& ops) {
  const int start = ops.laplace.outerIndexPtr()[i];
  const int end = ops.laplace.outerIndexPtr()[i + 1];
  if (start == end) return;
  const auto matrices = all_operators(ops);
  std::array<double*, 8> values;
  for (int q = 0; q < 8; ++q) values[q] = matrices[q]->valuePtr() + start;
  if (geo == nullptr) {
    for (double* v : values) std::fill(v, v + (end - start), 0.0);
    return;
  }
  const auto row = fits.neighbours.row(i);
  const int diagonal = static_cast<int>(std::lower_bound(row.begin(), row.end(), i) - row.begin());
  std::array<double, 8> sum{};
  const double* C = columns_of(fits, i);
  for (int k = 0; k < static_cast<int>(row.size()); ++k, C += 5) {
    const Eigen::Map<const Vector5d> column(C);
    const Eigen::Vector3d grad = geo->t1 * (geo->g11 * C[0] + geo->g12 * C[1]) +
                                 geo->t2 * (geo->g12 * C[0] + geo->g22 * C[1]);
    const Eigen::Vector3d diamond = geo->t1 * (geo->T11 * C[0] + geo->T12 * C[1]) +
                                    geo->t2 * (geo->T12 * C[0] + geo->T22 * C[1]);
    const std::array<double, 8> w = {geo->laplace.dot(column), geo->giaquinta.dot(column),
                                     grad.x(), grad.y(), grad.z(),
                                     diamond.x(), diamond.y(), diamond.z()};
    const int slot = k < diagonal ? k : k + 1;
    for (int q = 0; q < 8; ++q) {
      values[q][slot] = w[q];
      sum[q] += w[q];
    }
  }
  for (int q = 0; q < 8; ++q) values[q][diagonal] = -sum[q];
}

}  // namespace

SurfaceOperators compute_operators(const QuadraticFits& fits, const Vertices& V) {
  check_size(fits, V, "compute_operators");
  SurfaceOperators ops;
  build_patterns(fits, ops);
  update_operators(fits, V, ops);
  return ops;
}

void update_operators(const QuadraticFits& fits, const Vertices& V, SurfaceOperators& ops) {
  check_size(fits, V, "update_operators");
  if (!has_pattern(fits, ops))
    throw InvalidArgument("update_operators: the operators were not built from these fits' pattern");
  evaluate_vertices(fits, V, ops.geometry,
                    [&](int i, const LocalGeometry* geo) { write_operator_row(fits, i, geo, ops); });
}

SurfaceGeometry compute_geometry(const QuadraticFits& fits, const Vertices& V) {
  check_size(fits, V, "compute_geometry");
  SurfaceGeometry geometry;
  evaluate_vertices(fits, V, geometry, [](int, const LocalGeometry*) {});
  return geometry;
}

void normal_weighted(const SparseRowMatrix& L, const Vertices& normal, SparseRowMatrix& out) {
  if (normal.rows() != L.rows() || L.rows() != L.cols())
    throw InvalidArgument("normal_weighted: " + std::to_string(normal.rows()) +
                          " normals for a " + std::to_string(L.rows()) + " by " +
                          std::to_string(L.cols()) + " operator");
  if (!L.isCompressed()) throw InvalidArgument("normal_weighted: the operator is not compressed");
  if (out.rows() != L.rows() || out.cols() != L.cols() || out.nonZeros() != L.nonZeros() ||
      !out.isCompressed())
    out = L;
  const int n = static_cast<int>(L.rows());
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  std::copy(outer, outer + n + 1, out.outerIndexPtr());
  std::copy(inner, inner + L.nonZeros(), out.innerIndexPtr());
#pragma omp parallel for if (detail::worth_parallel(n)) schedule(dynamic, 1024)
  for (int i = 0; i < n; ++i)
    for (int p = outer[i]; p < outer[i + 1]; ++p) {
      const int j = inner[p];
      out.valuePtr()[p] = j == i ? L.valuePtr()[p] : L.valuePtr()[p] * normal.row(i).dot(normal.row(j));
    }
}

}  // namespace fairsurf
