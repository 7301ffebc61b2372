// Private to the flow: the state evaluated at one set of positions, and the assembly of the
// linearized velocity J (include/fairsurf/flow/flow.h states the step and the signs).
#pragma once

#include <fairsurf/energy/energy.h>
#include <fairsurf/flow/flow_kind.h>
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/mesh/region.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <limits>
#include <span>
#include <vector>

namespace fairsurf::flow_detail {

/// What stays fixed during one run.
struct FlowProblem {
  FlowKind kind = FlowKind::sixth_order;
  EnergyFunctions functions;  ///< sixth order only
  EnergyScale scale;          ///< ε of the functions, fixed at the start
  double curvature_resolution = std::numeric_limits<double>::infinity();  ///< FlowOptions::curvature_resolution
  const Region* region = nullptr;
  /// #V: 1 where the watched energy is summed (free vertices and their three fixed rings), else 0.
  Eigen::VectorXd energy_weight;
};

/// Fits, operators, velocity and energy at one set of positions X (#V by 3, the flow's units).
struct FlowState {
  QuadraticFits fits;
  SurfaceOperators ops;
  EnergyEvaluation evaluation;  ///< sixth order only
  /// Sixth order: per vertex, the part of 2(2H² − K) that the flow drops from EL's factor c where
  /// the mesh does not resolve the curvature (FlowOptions::curvature_resolution); evaluate_flow_terms
  /// sets it, the Jacobian reads it.
  Eigen::VectorXd dropped_curvature;
  Eigen::VectorXd velocity;     ///< #V normal velocity V (flow.h), zero on fixed vertices
  double energy = 0;            ///< the flow's energy over energy_weight
  double max_velocity = 0;      ///< max over free vertices of |V|
};

/// First evaluation: builds the fits' neighbourhoods and the operators' patterns at X, the vertices
/// of `two_ring_vertices` fitted over their 2-ring (fit_quadratics). Leaves the velocity and energy
/// to evaluate_flow_terms (the energy scale may depend on the geometry).
void initialize_geometry(const Vertices& X, const Faces& F, const Topology& topo, const FitOptions& fit,
                         std::span<const int> two_ring_vertices, FlowState& state);
/// Refits and re-evaluates the operators in place at X (same connectivity).
void update_geometry(const Vertices& X, FlowState& state);
/// Velocity, energy and max |V| from the state's operators.
void evaluate_flow_terms(const FlowProblem& problem, FlowState& state);

/// Buffers of the assembly, kept across steps (their patterns are fixed while the connectivity is).
/// J_FF = α P_F: X_:F with P = R L∆ − W, X = Q (sixth order; one product per function), P = L∆,
/// X = A_H, α = −½ (surface diffusion, Willmore) or P = I, X = A_H (mean curvature). The patterns
/// of P's free rows and of J_FF are built once per connectivity, region and kind (symbolic phase);
/// each step then only computes values, in place: J's pattern is identical between steps, so the
/// linear solver keeps its analysis.
struct JacobianWorkspace {
  SparseRowMatrix A_H, A_K;  ///< L∆ ∘ (n_i·n_j), L□ ∘ (n_i·n_j)
  SparseRowMatrix R, W, Q;   ///< the factors of P′ = R L∆ − W and Q (flow.h), L∆'s pattern

  // Symbolic phase, and what it was built for.
  FlowKind kind = FlowKind::sixth_order;
  std::vector<int> free_vertices;      ///< the region's free vertices (#F)
  Eigen::Index operator_nonzeros = -1; ///< L∆'s non-zeros
  Eigen::Index jacobian_nonzeros = -1; ///< J_FF's non-zeros
  std::vector<int> left_outer, left_inner;  ///< pattern of P's free rows: #F + 1 offsets, vertex columns
  // Per-thread scratch of the value loop: a dense row of P (#V, kept zero between rows) and the
  // position of each free column in the current row of J (#F).
  int threads = 1;
  std::vector<double> left_row;
  std::vector<int> column_slot;
};

/// J_FF (#F by #F, row-major, compressed) of the flow at `state`.
void assemble_jacobian(const FlowProblem& problem, const FlowState& state, JacobianWorkspace& work,
                       SparseRowMatrix& jacobian);

/// damping_i = max(0, J_ii + dominance · Σ_{j≠i} |J_ij|) (#F): what must leave row i's diagonal
/// so that J_ii ≤ −dominance · Σ_{j≠i} |J_ij|.
void row_damping(const SparseRowMatrix& jacobian, double dominance, Eigen::VectorXd& damping);

/// step = I − τ (J − diag(damping)), J's pattern (which holds the diagonal). Keeps step's storage
/// when the pattern matches.
void form_step_matrix(const SparseRowMatrix& jacobian, const Eigen::VectorXd& damping, double tau,
                      SparseRowMatrix& step);

}  // namespace fairsurf::flow_detail
