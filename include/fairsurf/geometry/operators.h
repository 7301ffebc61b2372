// fairsurf — discrete differential operators and curvatures from the local quadratic fits
// (method.md §1–§3).
//
// Sign conventions (method.md §1): n is the fitted normal t₁×t₂/‖t₁×t₂‖, oriented like the fit's frame
// normal N0 (the area-weighted face normal, outward on a closed counter-clockwise mesh).
// H = ½ g^αβ b_αβ and K = b/g with b_αβ = n·t_αβ, so that ∆x = 2Hn and □x = 2Kn: a sphere of radius R
// with outward normals has H = −1/R, K = 1/R²; a cylinder H = −1/(2R), K = 0. Principal curvatures
// k1 = H + √(H² − K) ≥ k2 = H − √(H² − K) (the radicand clamped at 0). Units: H, k1, k2 in 1/length,
// K in 1/length², areas in length²; each operator's units are listed below.
//
// Every operator is a stencil over N(i) (method.md §3.4): (Op f)_i = Σ_{j∈N(i)} w_ij (f_j − f_i). It is
// stored as a #V by #V row-major sparse matrix with the pattern N(i) ∪ {i}, columns ascending, the
// diagonal holding −Σ_j w_ij, so that (Op f) = Op * f for any #V vector f. The matrices are not
// symmetric. Rows of vertices that were not fitted are empty; rows of vertices whose fit status is
// kTooFewNeighbours or kDegenerate are zero (their pattern is kept). Dimensions per row:
//   L∆ (laplace):            ∆f = g^αβ (f_αβ − Γ^γ_αβ f_γ)                   [1/length²]·[f]
//   L□ (giaquinta):          □f = T^αβ (f_αβ − Γ^γ_αβ f_γ), T = adj(b)/g      [1/length³]·[f]
//   G_c (gradient[c]):       component c ∈ {x,y,z} of ∇f = g^αβ f_α t_β        [1/length]·[f]
//   D_c (second_gradient[c]): component c of ◇f = T^αβ f_α t_β                 [1/length²]·[f]
// Exact discrete identities (to round-off): (L∆ x)_i = 2H_i n_i and (L□ x)_i = 2K_i n_i.
//
// Re-evaluation on moved positions with the same connectivity: refit_quadratics(fits, V) then
// update_operators(fits, V, ops) rewrites the value arrays in place; the patterns are built once.
#pragma once

#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/geometry/sparse.h>
#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>

namespace fairsurf {

/// Per-vertex geometry of the fitted surface. Vertices that are not fitted, or whose fit has status
/// kTooFewNeighbours or kDegenerate, get n = N0 (zero if undefined) and H = K = k1 = k2 = 0; their
/// status in the fits says why.
struct SurfaceGeometry {
  Vertices normal;     ///< #V by 3 unit normals n (oriented like N0)
  Eigen::VectorXd H;   ///< #V mean curvature, H = −1/R on an outward sphere
  Eigen::VectorXd K;   ///< #V Gaussian curvature
  Eigen::VectorXd k1;  ///< #V larger principal curvature, H + √(H² − K)
  Eigen::VectorXd k2;  ///< #V smaller principal curvature, H − √(H² − K)
  Eigen::VectorXd area;  ///< #V vertex areas: one third of the incident triangle areas
};

/// The operators of method.md §3.4 plus the geometry they come with.
struct SurfaceOperators {
  SparseRowMatrix laplace;                        ///< L∆
  SparseRowMatrix giaquinta;                      ///< L□ (Giaquinta–Hildebrandt)
  std::array<SparseRowMatrix, 3> gradient;        ///< G_x, G_y, G_z
  std::array<SparseRowMatrix, 3> second_gradient; ///< D_x, D_y, D_z
  SurfaceGeometry geometry;
};

/// Builds the sparsity pattern once and evaluates every operator from `fits` (fitted at `V`).
/// Throws InvalidArgument if V's size differs from the fits'.
SurfaceOperators compute_operators(const QuadraticFits& fits, const Vertices& V);

/// Re-evaluates `ops` in place after refit_quadratics(fits, V): the value arrays are rewritten,
/// the patterns kept. Throws InvalidArgument if `ops` was not built from these fits' pattern.
void update_operators(const QuadraticFits& fits, const Vertices& V, SurfaceOperators& ops);

/// Geometry only (no matrices), for curvature output and rendering.
SurfaceGeometry compute_geometry(const QuadraticFits& fits, const Vertices& V);

/// The normal-weighted operator A = L ∘ (n_i·n_j) of method.md §5: A(i,j) = L(i,j) n_i·n_j off the
/// diagonal and A(i,i) = L(i,i) = −Σ_j w_ij (n_i·n_i = 1), so that for a normal displacement
/// x_j → x_j + d_j n_j and frozen stencils, ½ n_i·(L∆(x + d n))_i = H_i + ½ (A_H d)_i exactly
/// (A_H from L∆), and ½ n_i·(L□(x + d n))_i = K_i + ½ (A_K d)_i (A_K from L□; the flow uses
/// K^{k+1} = K^k + A_K d, method.md §5). `normal` is #V by 3. `out` keeps its storage when it already
/// has L's pattern (same size and non-zero count), so calling this every step does not allocate.
void normal_weighted(const SparseRowMatrix& L, const Vertices& normal, SparseRowMatrix& out);

}  // namespace fairsurf
