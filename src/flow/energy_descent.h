// Private to the flow: the Gauss–Newton model of the sixth-order energy that the energy-descent
// step minimizes (flow.h, FlowStepKind::energy_descent; docs/flow.md "Energy descent").
#pragma once

#include "flow_step.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace fairsurf::flow_detail {

/// What assembling the model needs of the connectivity, found once per run (the operators'
/// shared pattern P and the region are fixed while the connectivity is): row r of B_lc is
/// supported on the free vertices S_r = ∪_{k ∈ P(r)} P(k) ∩ F, and N on ∪_r S_r × S_r.
struct GaussNewtonPattern {
  int num_vertices = -1;            ///< #V it was built for (-1: not built)
  std::vector<int> rows;            ///< the watched rows r (energy_weight > 0)
  std::vector<int> support_offsets; ///< #rows + 1, into support
  std::vector<int> support;         ///< S_r per watched row, ascending free indices
};

/// The watched energy E = Σ_i w_i A_i Σ_l ‖(∇f_l)_i‖² with fits, stencils, normals and areas frozen
/// at the state and f_l linearized in the normal displacement d of the free vertices
/// (f_l + Q_l d, Q_l = ½ diag(f_H) A_H + diag(f_K) A_K, flow.h):
///   E(d) ≈ E + 2 gᵀd + dᵀ N d,  N = Σ_l Σ_c B_lcᵀ diag(w A) B_lc,  g = Σ_l Σ_c B_lcᵀ diag(w A) G_c f_l,
/// with B_lc = G_c Q_l restricted to the free columns. N is symmetric positive semi-definite and g
/// is the gradient of E through f — consistent with the discrete energy by construction, where the
/// fitted EL of method.md §5 is only consistent with it to the order of the discretization.
struct GaussNewtonModel {
  SparseRowMatrix normal;    ///< N, #F by #F, symmetric, every diagonal entry stored
  Eigen::VectorXd gradient;  ///< g, #F (half the derivative of E in d)
  Eigen::VectorXd mass;      ///< #F vertex areas A of the free vertices (the metric of the descent)
  // Kept across assemblies so that after the first one nothing is allocated.
  GaussNewtonPattern pattern;
  SparseRowMatrix A_H, A_K;  ///< the normal-weighted L∆ and L□ (operators.h)
  std::vector<double> q;     ///< Q_l's values on the operators' pattern, one function at a time
  std::vector<int> slot;     ///< #F scratch: position of a free vertex in the current S_r, or -1
  std::vector<double> rows_of_b;  ///< 3 · max |S_r| scratch: row r of B_l0, B_l1, B_l2
};

/// Builds the model at `state` (sixth order only: problem.functions non-empty). Serial, in a fixed
/// order: the same state gives the same model bit for bit. The first call sizes the pattern and
/// buffers; later calls with the same connectivity only write values.
void assemble_gauss_newton(const FlowProblem& problem, const FlowState& state, GaussNewtonModel& model);

/// step = N + diag(mass) / (2τ): the damped system whose solution d = −step⁻¹ g moves like the
/// gradient flow of E in the area metric for small τ (d ≈ −2τ g / A ≈ −τ EL, the flow's explicit
/// step) and is the Gauss–Newton step for large τ.
void form_descent_matrix(const GaussNewtonModel& model, double tau, SparseRowMatrix& step);

}  // namespace fairsurf::flow_detail
