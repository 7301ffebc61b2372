// fairsurf — the discrete energy E = Σ_l ∫ ‖∇f_l‖² dA and its Euler–Lagrange expression
// (method.md §4–§5), evaluated from the surface operators at the current positions.
//
//   density_i = Σ_l ‖∇f_l(x_i)‖²,  E = Σ_i A_i density_i,  A_i = one third of the incident triangle
//   areas (SurfaceGeometry::area), ∇f = (G_x f, G_y f, G_z f).
//   EL = Σ_l [2H‖∇f‖² − 2⟨∇f, ◇f⟩ − c ∆f − 2□(f_K ∆f) − ∆(f_H ∆f)],
//        c = 4HK f_K + 2(2H² − K) f_H,
// so that the first variation under a normal motion x + εϕn is δE = ∫ EL ϕ dA (Σ_i A_i EL_i ϕ_i
// discretely, to O(h²) on regular grids: tests/energy/test_energy.cpp) and the flow that DECREASES E is
// ∂x/∂t = −EL n (the paper prints the ascent flow +EL n). Signs of H and K as in operators.h
// (H = −1/R on an outward sphere).
// Units: with lengths L, H ~ 1/L, K ~ 1/L²; for f = H the density is 1/L⁴, E is 1/L² and EL is 1/L⁵.
#pragma once

#include <fairsurf/energy/energy_function.h>
#include <fairsurf/geometry/operators.h>

#include <Eigen/Core>

#include <vector>

namespace fairsurf {

/// One function's per-vertex terms at the current geometry (every array has #V rows).
struct EnergyTerms {
  EnergyValues values;                 ///< f, f_H, f_K
  Eigen::VectorXd laplace_f;           ///< ∆f = L∆ f
  Eigen::MatrixX3d gradient_f;         ///< #V by 3: ∇f
  Eigen::MatrixX3d second_gradient_f;  ///< #V by 3: ◇f
};

/// The energy of a set of functions at one geometry. Buffers are reused by evaluate_energy.
struct EnergyEvaluation {
  std::vector<EnergyTerms> terms;   ///< one per function, in the order given
  Eigen::VectorXd density;          ///< #V: Σ_l ‖∇f_l‖²
  Eigen::VectorXd euler_lagrange;   ///< #V: EL (empty unless requested)
  double energy = 0;                ///< Σ_i A_i density_i over every vertex
};

/// Evaluates f_l, ∇f_l, ◇f_l, ∆f_l, the energy density and E from `ops` (built at the current
/// positions) and, if `with_euler_lagrange`, EL. `out`'s buffers are resized only when their size
/// differs. Throws InvalidArgument for an empty function list, NumericalError (from
/// EnergyFunction::evaluate) where f is not finite.
void evaluate_energy(const SurfaceOperators& ops, const EnergyFunctions& functions,
                     const EnergyScale& scale, EnergyEvaluation& out, bool with_euler_lagrange = true);

/// Convenience: E = Σ_i A_i Σ_l ‖∇f_l(x_i)‖².
double discrete_energy(const SurfaceOperators& ops, const EnergyFunctions& functions,
                       const EnergyScale& scale);

/// #V: the factor c = 4HK f_K + 2(2H² − K) f_H of EL, per vertex.
Eigen::VectorXd euler_lagrange_factor(const SurfaceGeometry& geometry, const EnergyValues& values);

}  // namespace fairsurf
