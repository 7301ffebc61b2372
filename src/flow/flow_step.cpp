#include "flow_step.h"
#include "parallel.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <omp.h>

namespace fairsurf::flow_detail {
namespace {

// out gets L's pattern (copied only if its size differs) and out(i, j) = value(i, j, p) at L's p-th
// stored entry. Every operator shares L∆'s pattern, so p indexes them all.
template <class Value>
void fill_like(const SparseRowMatrix& L, SparseRowMatrix& out, Value value) {
  if (out.rows() != L.rows() || out.nonZeros() != L.nonZeros() || !out.isCompressed()) out = L;
  const int n = static_cast<int>(L.rows());
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  double* values = out.valuePtr();
#pragma omp parallel for if (detail::worth_parallel(n)) schedule(dynamic, 1024)
  for (int i = 0; i < n; ++i)
    for (int p = outer[i]; p < outer[i + 1]; ++p) values[p] = value(i, inner[p], p);
}

// Appends to `inner` the columns of P's row at vertex i (P = R L∆ − W: L∆'s 2-ring, which holds its
// 1-ring; P = L∆: its 1-ring; P = I: i), sorted. `mark` (#V) remembers the row that last took a column.
void append_left_row(FlowKind kind, const SparseRowMatrix& L, int i, int row, std::vector<int>& mark,
                     std::vector<int>& inner) {
  const int* outer = L.outerIndexPtr();
  const int* column = L.innerIndexPtr();
  const auto begin = static_cast<std::ptrdiff_t>(inner.size());
  const auto take = [&](int k) {
    if (mark[k] != row) mark[k] = row, inner.push_back(k);
  };
  take(i);
  if (kind != FlowKind::mean_curvature)
    for (int p = outer[i]; p < outer[i + 1]; ++p) {
      take(column[p]);
      if (kind == FlowKind::sixth_order)
        for (int q = outer[column[p]]; q < outer[column[p] + 1]; ++q) take(column[q]);
    }
  std::sort(inner.begin() + begin, inner.end());
}

// Symbolic phase: the patterns of P's free rows and of J_FF (free columns k ∈ L∆ row of some column
// of P's row, and the diagonal, which the step matrix needs), and the scratch of the value loop.
void build_pattern(FlowKind kind, const SparseRowMatrix& L, const Region& region, JacobianWorkspace& work,
                   SparseRowMatrix& jacobian) {
  const int n = static_cast<int>(L.rows());
  const int num_free = region.num_free();
  work.left_outer.assign(1, 0);
  work.left_inner.clear();
  std::vector<int> mark(n, -1), free_mark(num_free, -1);
  std::vector<int> outer(1, 0), inner;
  for (int r = 0; r < num_free; ++r) {
    append_left_row(kind, L, region.free_vertices[r], r, mark, work.left_inner);
    work.left_outer.push_back(static_cast<int>(work.left_inner.size()));
    const auto begin = static_cast<std::ptrdiff_t>(inner.size());
    const auto take = [&](int j) {
      if (j >= 0 && free_mark[j] != r) free_mark[j] = r, inner.push_back(j);
    };
    take(r);
    for (int e = work.left_outer[r]; e < work.left_outer[r + 1]; ++e) {
      const int k = work.left_inner[e];
      for (int q = L.outerIndexPtr()[k]; q < L.outerIndexPtr()[k + 1]; ++q)
        take(region.free_index[L.innerIndexPtr()[q]]);
    }
    std::sort(inner.begin() + begin, inner.end());
    outer.push_back(static_cast<int>(inner.size()));
  }
  std::vector<double> zeros(inner.size(), 0.0);
  jacobian = Eigen::Map<const SparseRowMatrix>(num_free, num_free, static_cast<Eigen::Index>(inner.size()),
                                              outer.data(), inner.data(), zeros.data());
  work.kind = kind;
  work.free_vertices = region.free_vertices;
  work.operator_nonzeros = L.nonZeros();
  work.jacobian_nonzeros = jacobian.nonZeros();
  work.threads = std::max(1, omp_get_max_threads());
  work.left_row.assign(static_cast<std::size_t>(work.threads) * n, 0.0);
  work.column_slot.assign(static_cast<std::size_t>(work.threads) * num_free, 0);
}

bool pattern_current(FlowKind kind, const SparseRowMatrix& L, const Region& region,
                     const JacobianWorkspace& work, const SparseRowMatrix& jacobian) {
  return work.kind == kind && work.operator_nonzeros == L.nonZeros() &&
         work.free_vertices == region.free_vertices && jacobian.rows() == region.num_free() &&
         jacobian.nonZeros() == work.jacobian_nonzeros && jacobian.isCompressed();
}

// J_FF += α P_F: X_:F, X of L∆'s pattern with values `right`. left_row(i, row) adds P's row at vertex
// i into the dense `row` (#V, zero on entry; only columns of P's pattern). Parallel over J's rows,
// allocation-free: each thread has its own dense row and column slots.
template <class LeftRow>
void add_product(const Region& region, const SparseRowMatrix& L, const double* right, double alpha,
                 LeftRow left_row, JacobianWorkspace& work, SparseRowMatrix& jacobian) {
  const int n = static_cast<int>(L.rows());
  const int num_free = region.num_free();
  const int* outer = L.outerIndexPtr();
  const int* column = L.innerIndexPtr();
  const int* j_outer = jacobian.outerIndexPtr();
  const int* j_inner = jacobian.innerIndexPtr();
  double* J = jacobian.valuePtr();
#pragma omp parallel if (detail::worth_parallel(num_free)) num_threads(work.threads)
  {
    double* row = work.left_row.data() + static_cast<std::size_t>(omp_get_thread_num()) * n;
    int* slot = work.column_slot.data() + static_cast<std::size_t>(omp_get_thread_num()) * num_free;
#pragma omp for schedule(dynamic, 256)
    for (int r = 0; r < num_free; ++r) {
      for (int p = j_outer[r]; p < j_outer[r + 1]; ++p) slot[j_inner[p]] = p;
      left_row(region.free_vertices[r], row);
      for (int e = work.left_outer[r]; e < work.left_outer[r + 1]; ++e) {
        const int k = work.left_inner[e];
        const double a = alpha * row[k];
        row[k] = 0;
        if (a == 0) continue;
        for (int q = outer[k]; q < outer[k + 1]; ++q) {
          const int j = region.free_index[column[q]];
          if (j >= 0) J[slot[j]] += a * right[q];
        }
      }
    }
  }
}

// The weight of a lower-order curvature term at vertex i: min(1, resolution / (A κ²)), κ² = 2H² − K,
// A the vertex area. Below 1 only where the radius of curvature is below about an edge: there a
// term of H and K alone outweighs the leading one at the mesh's own scale and grows single-vertex
// spikes (FlowOptions::curvature_resolution).
double resolved_weight(const SurfaceGeometry& geo, Eigen::Index i, double resolution) {
  const double unresolved = geo.area[i] * (2 * geo.H[i] * geo.H[i] - geo.K[i]);
  return unresolved > resolution ? resolution / unresolved : 1.0;
}

// Per vertex, the part of 2(2H² − K) that the flow drops from EL's factor c = 2(2H² − K) f_H
// (euler_lagrange_factor) of every term: 1 − resolved_weight of it where the energy is a function
// of H alone there (every term's f_K is 0), else 0. V = −EL holds that part as +2(2H² − K) f_H ∆f, a
// diffusion of f backwards in time. Energies with a K part are left alone: limited, f = K diverged
// and f = {H, K} failed. Set once per evaluation; the velocity and the Jacobian read it.
void set_dropped_curvature(const SurfaceGeometry& geo, const std::vector<EnergyTerms>& terms, double resolution,
                           Eigen::VectorXd& dropped) {
  dropped.resize(geo.H.size());
  for (Eigen::Index i = 0; i < dropped.size(); ++i) {
    const double weight = resolved_weight(geo, i, resolution);
    bool of_h_alone = true;
    for (const EnergyTerms& t : terms) of_h_alone = of_h_alone && t.values.f_K[i] == 0;
    dropped[i] = weight == 1.0 || !of_h_alone ? 0.0 : (1 - weight) * 2 * (2 * geo.H[i] * geo.H[i] - geo.K[i]);
  }
}

// J += Σ_l P′_l Q_l (free rows and columns), P′ = R L∆ − Σ_c diag(w_c) G_c,
// R = L∆ diag(f_H) + 2 L□ diag(f_K) + diag(c), w = 2H∇f − 2◇f, Q = ½ diag(f_H) A_H + diag(f_K) A_K.
void add_sixth_order(const FlowState& state, const Region& region, const EnergyTerms& t,
                     JacobianWorkspace& work, SparseRowMatrix& jacobian) {
  const SurfaceOperators& ops = state.ops;
  const double* lap = ops.laplace.valuePtr();
  const double* gia = ops.giaquinta.valuePtr();
  const Eigen::VectorXd& fH = t.values.f_H;
  const Eigen::VectorXd& fK = t.values.f_K;
  Eigen::VectorXd c = euler_lagrange_factor(ops.geometry, t.values);
  c -= state.dropped_curvature.cwiseProduct(fH);
  fill_like(ops.laplace, work.R, [&](int i, int j, int p) {
    return lap[p] * fH[j] + 2.0 * gia[p] * fK[j] + (i == j ? c[i] : 0.0);
  });
  const Eigen::VectorXd& H = ops.geometry.H;
  fill_like(ops.laplace, work.W, [&](int i, int, int p) {
    double sum = 0;
    for (int k = 0; k < 3; ++k)
      sum += (2.0 * H[i] * t.gradient_f(i, k) - 2.0 * t.second_gradient_f(i, k)) *
             ops.gradient[k].valuePtr()[p];
    return sum;
  });
  const double* aH = work.A_H.valuePtr();
  const double* aK = work.A_K.valuePtr();
  fill_like(ops.laplace, work.Q,
            [&](int i, int, int p) { return 0.5 * fH[i] * aH[p] + fK[i] * aK[p]; });
  const int* outer = ops.laplace.outerIndexPtr();
  const int* column = ops.laplace.innerIndexPtr();
  const double* R = work.R.valuePtr();
  const double* W = work.W.valuePtr();
  add_product(region, ops.laplace, work.Q.valuePtr(), 1.0, [&](int i, double* row) {
    for (int p = outer[i]; p < outer[i + 1]; ++p) {
      const int m = column[p];
      for (int q = outer[m]; q < outer[m + 1]; ++q) row[column[q]] += R[p] * lap[q];
      row[m] -= W[p];
    }
  }, work, jacobian);
}

}  // namespace

void initialize_geometry(const Vertices& X, const Faces& F, const Topology& topo, const FitOptions& fit,
                         std::span<const int> two_ring_vertices, FlowState& state) {
  state.fits = fit_quadratics(X, F, topo, fit, {}, two_ring_vertices);
  state.ops = compute_operators(state.fits, X);
}

void update_geometry(const Vertices& X, FlowState& state) {
  refit_quadratics(state.fits, X);
  update_operators(state.fits, X, state.ops);
}

void evaluate_flow_terms(const FlowProblem& problem, FlowState& state) {
  const SurfaceGeometry& geo = state.ops.geometry;
  const auto H = geo.H.array();
  Eigen::VectorXd& V = state.velocity;
  const Eigen::VectorXd& weight = problem.energy_weight;
  switch (problem.kind) {
    case FlowKind::sixth_order:
      evaluate_energy(state.ops, problem.functions, problem.scale, state.evaluation);
      V = -state.evaluation.euler_lagrange;
      // EL holds −c ∆f; the flow drops the part of c that unresolved curvature makes anti-diffusive.
      set_dropped_curvature(geo, state.evaluation.terms, problem.curvature_resolution, state.dropped_curvature);
      for (const EnergyTerms& t : state.evaluation.terms)
        for (Eigen::Index i = 0; i < V.size(); ++i)
          V[i] -= state.dropped_curvature[i] * t.values.f_H[i] * t.laplace_f[i];
      state.energy = weight.dot(geo.area.cwiseProduct(state.evaluation.density));
      break;
    case FlowKind::mean_curvature:
      V = 2.0 * geo.H;
      state.energy = weight.dot(geo.area);
      break;
    case FlowKind::surface_diffusion:
      V.noalias() = -(state.ops.laplace * geo.H);
      state.energy = weight.dot(geo.area);
      break;
    case FlowKind::willmore:
      V.noalias() = -(state.ops.laplace * geo.H);
      // The cubic term, explicit, weighed by resolved_weight: at a spike it pushes the vertex out.
      for (Eigen::Index i = 0; i < V.size(); ++i)
        V[i] -= resolved_weight(geo, i, problem.curvature_resolution) * 2.0 * H[i] * (H[i] * H[i] - geo.K[i]);
      state.energy = weight.dot((geo.area.array() * H * H).matrix());
      break;
  }
  const Region& region = *problem.region;
  double max_velocity = 0;
  bool finite = true;
  for (int v = 0; v < static_cast<int>(V.size()); ++v) {
    if (!region.is_free(v)) {
      V[v] = 0;
      continue;
    }
    finite = finite && std::isfinite(V[v]);
    max_velocity = std::max(max_velocity, std::abs(V[v]));
  }
  state.max_velocity = finite ? max_velocity : std::numeric_limits<double>::quiet_NaN();
}

void assemble_jacobian(const FlowProblem& problem, const FlowState& state, JacobianWorkspace& work,
                       SparseRowMatrix& jacobian) {
  const SurfaceOperators& ops = state.ops;
  const Region& region = *problem.region;
  if (!pattern_current(problem.kind, ops.laplace, region, work, jacobian))
    build_pattern(problem.kind, ops.laplace, region, work, jacobian);
  std::fill(jacobian.valuePtr(), jacobian.valuePtr() + jacobian.nonZeros(), 0.0);
  normal_weighted(ops.laplace, ops.geometry.normal, work.A_H);
  const int* outer = ops.laplace.outerIndexPtr();
  const int* column = ops.laplace.innerIndexPtr();
  const double* lap = ops.laplace.valuePtr();
  switch (problem.kind) {
    case FlowKind::sixth_order:
      normal_weighted(ops.giaquinta, ops.geometry.normal, work.A_K);
      for (const EnergyTerms& t : state.evaluation.terms) add_sixth_order(state, region, t, work, jacobian);
      break;
    case FlowKind::mean_curvature:
      add_product(region, ops.laplace, work.A_H.valuePtr(), 1.0, [](int i, double* row) { row[i] = 1.0; },
                  work, jacobian);
      break;
    case FlowKind::surface_diffusion:
    case FlowKind::willmore:
      add_product(region, ops.laplace, work.A_H.valuePtr(), -0.5, [&](int i, double* row) {
        for (int p = outer[i]; p < outer[i + 1]; ++p) row[column[p]] = lap[p];
      }, work, jacobian);
      break;
  }
}

void row_damping(const SparseRowMatrix& jacobian, double dominance, Eigen::VectorXd& damping) {
  const int n = static_cast<int>(jacobian.rows());
  damping.resize(n);
  const int* outer = jacobian.outerIndexPtr();
  const int* inner = jacobian.innerIndexPtr();
  const double* J = jacobian.valuePtr();
#pragma omp parallel for if (detail::worth_parallel(n)) schedule(static)
  for (int i = 0; i < n; ++i) {
    double diagonal = 0, off = 0;
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      (inner[p] == i ? diagonal : off) += inner[p] == i ? J[p] : std::abs(J[p]);
    damping[i] = off > 0 ? std::max(0.0, diagonal + dominance * off) : 0.0;
  }
}

void form_step_matrix(const SparseRowMatrix& jacobian, const Eigen::VectorXd& damping, double tau,
                      SparseRowMatrix& step) {
  if (step.rows() != jacobian.rows() || step.nonZeros() != jacobian.nonZeros() || !step.isCompressed())
    step = jacobian;
  const int n = static_cast<int>(jacobian.rows());
  const int* outer = jacobian.outerIndexPtr();
  const int* inner = jacobian.innerIndexPtr();
  const double* J = jacobian.valuePtr();
  double* A = step.valuePtr();
#pragma omp parallel for if (detail::worth_parallel(n)) schedule(static)
  for (int i = 0; i < n; ++i)
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      A[p] = inner[p] == i ? 1.0 - tau * (J[p] - damping[i]) : -tau * J[p];
}

}  // namespace fairsurf::flow_detail
