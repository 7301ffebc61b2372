#include "flow_step.h"

#include <fairsurf/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fairsurf::flow_detail {
namespace {

// out gets L's pattern (copied only if its size differs) and out(i, j) = value(i, j, p) at L's p-th
// stored entry. Every operator shares L∆'s pattern, so p indexes them all.
template <class Value>
void fill_like(const SparseOperator& L, SparseOperator& out, Value value) {
  if (out.rows() != L.rows() || out.nonZeros() != L.nonZeros() || !out.isCompressed()) out = L;
  const int n = static_cast<int>(L.rows());
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  double* values = out.valuePtr();
#pragma omp parallel for schedule(dynamic, 1024)
  for (int i = 0; i < n; ++i)
    for (int p = outer[i]; p < outer[i + 1]; ++p) values[p] = value(i, inner[p], p);
}

// #F by #V selection of the free rows.
void build_selection(const Region& region, int num_vertices, SparseOperator& select) {
  if (region.num_free() == num_vertices) {
    select.resize(0, 0);
    return;
  }
  if (select.rows() == region.num_free()) return;
  select.resize(region.num_free(), num_vertices);
  select.reserve(Eigen::VectorXi::Ones(region.num_free()));
  for (int k = 0; k < region.num_free(); ++k) select.insert(k, region.free_vertices[k]) = 1.0;
  select.makeCompressed();
}

// S·A (free rows) or A itself when every vertex is free.
SparseOperator free_rows(const SparseOperator& select, const SparseOperator& A) {
  if (select.rows() == 0) return A;
  return select * A;
}
// A·Sᵀ (free columns).
SparseOperator free_columns(const SparseOperator& select, const SparseOperator& A) {
  if (select.rows() == 0) return A;
  return A * SparseOperator(select.transpose());
}

// J = Σ_l P′_l Q_l, P′ = R L∆ − Σ_c diag(w_c) G_c, R = L∆ diag(f_H) + 2 L□ diag(f_K) + diag(c),
// w = 2H∇f − 2◇f, Q = ½ diag(f_H) A_H + diag(f_K) A_K.
void add_sixth_order(const FlowState& state, const EnergyTerms& t, JacobianWorkspace& work,
                     SparseOperator& jacobian) {
  const SurfaceOperators& ops = state.ops;
  const double* lap = ops.laplace.valuePtr();
  const double* gia = ops.giaquinta.valuePtr();
  const Eigen::VectorXd& fH = t.values.f_H;
  const Eigen::VectorXd& fK = t.values.f_K;
  const Eigen::VectorXd c = euler_lagrange_factor(ops.geometry, t.values);
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
  SparseOperator P = free_rows(work.select, work.R) * ops.laplace;
  P -= free_rows(work.select, work.W);
  const SparseOperator term = P * free_columns(work.select, work.Q);
  if (jacobian.nonZeros() == 0)
    jacobian = term;
  else
    jacobian += term;
}

}  // namespace

void initialize_geometry(const Vertices& X, const Faces& F, const Topology& topo,
                         const FitOptions& fit, FlowState& state) {
  state.fits = fit_quadratics(X, F, topo, fit);
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
      V.array() -= 2.0 * H * (H * H - geo.K.array());
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
                       SparseOperator& jacobian) {
  const SurfaceOperators& ops = state.ops;
  const int n = static_cast<int>(ops.laplace.rows());
  build_selection(*problem.region, n, work.select);
  normal_weighted(ops.laplace, ops.geometry.normal, work.A_H);
  jacobian.resize(problem.region->num_free(), problem.region->num_free());  // and empties it
  switch (problem.kind) {
    case FlowKind::sixth_order:
      normal_weighted(ops.giaquinta, ops.geometry.normal, work.A_K);
      for (const EnergyTerms& t : state.evaluation.terms) add_sixth_order(state, t, work, jacobian);
      break;
    case FlowKind::mean_curvature:
      jacobian = free_columns(work.select, free_rows(work.select, work.A_H));
      break;
    case FlowKind::surface_diffusion:
    case FlowKind::willmore:
      jacobian = free_rows(work.select, ops.laplace) * free_columns(work.select, work.A_H);
      jacobian *= -0.5;
      break;
  }
  jacobian.makeCompressed();
}

void row_damping(const SparseOperator& jacobian, double dominance, Eigen::VectorXd& damping) {
  const int n = static_cast<int>(jacobian.rows());
  damping.resize(n);
  const int* outer = jacobian.outerIndexPtr();
  const int* inner = jacobian.innerIndexPtr();
  const double* J = jacobian.valuePtr();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    double diagonal = 0, off = 0;
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      (inner[p] == i ? diagonal : off) += inner[p] == i ? J[p] : std::abs(J[p]);
    damping[i] = off > 0 ? std::max(0.0, diagonal + dominance * off) : 0.0;
  }
}

void form_step_matrix(const SparseOperator& jacobian, const Eigen::VectorXd& damping, double tau,
                      SparseOperator& step) {
  if (step.rows() != jacobian.rows() || step.nonZeros() != jacobian.nonZeros() || !step.isCompressed())
    step = jacobian;
  const int n = static_cast<int>(jacobian.rows());
  const int* outer = jacobian.outerIndexPtr();
  const int* inner = jacobian.innerIndexPtr();
  const double* J = jacobian.valuePtr();
  double* A = step.valuePtr();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i)
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      A[p] = inner[p] == i ? 1.0 - tau * (J[p] - damping[i]) : -tau * J[p];
}

}  // namespace fairsurf::flow_detail
