// fairsurf — linear cotangent fairing, the classical baseline (CGAL, PMP, libigl).
//
// Solves ∆^k x = 0 on the free vertices with the fixed vertices as boundary data, where ∆ = M⁻¹L is
// the cotangent Laplace–Beltrami operator of the *input* mesh (L: cotangent weights, M: barycentric
// vertex areas). k = 1, 2, 3 gives membrane, thin-plate and minimum-variation surfaces with G0, G1
// and G2 data from k fixed rings. The operator is frozen at the input: the result depends on the
// initial patch's triangulation and is not a geometric flow — which is what fairsurf compares against.
// Optionally the solve is repeated with the operator re-evaluated at the previous solution
// (HarmonicOptions::iterations): the G2 fill starts its flow from that (fair_region.h).
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/solve/linear_solver.h>

#include <Eigen/SparseCore>

namespace fairsurf {

/// The largest |cot| of a corner in cotangent_laplacian: a face with a corner sharper than about
/// 2.9° (or blunter than 177.1°) has its three cotangents scaled down together until that corner's
/// is this. Raw scans have such slivers: 3 corners within 3 rings of a 37-edge hole cut from
/// data/hammer_rawscan.obj, |cot| up to 92, made ∆³ = L(M⁻¹L)² raise a ridge 0.9 mean edges off the
/// scan (0.08 with the bound; docs/real-holes.md, "Sliver triangles"). Faces without such a corner weigh
/// as before.
inline constexpr double kMaxCotangent = 20.0;

/// #V by #V cotangent Laplacian: L(i,j) = ½(cot α_ij + cot β_ij), L(i,i) = −Σ_j L(i,j), a sliver
/// face's cotangents scaled down (kMaxCotangent).
/// Symmetric, negative semi-definite, rows sum to zero. With M = diag(vertex_areas), M⁻¹L x ≈ 2Hn in
/// method.md §1's convention — in the mean: with barycentric areas the pointwise error does not vanish
/// on irregular meshes (15% at valence-5 vertices of an icosphere), which is one reason the flows use
/// quadratic fits instead. Border edges carry their single cotangent.
Eigen::SparseMatrix<double> cotangent_laplacian(const Vertices& V, const Faces& F);

struct HarmonicOptions {
  int order = 3;  ///< k in ∆^k x = 0: 1, 2 or 3 (the continuity reached is G(k−1))
  /// Solves, each with the operator re-evaluated at the previous solution (1: the classical frozen
  /// operator). Pinkall–Polthier's iteration for k = 1; for k = 3 it removes the overshoot that the
  /// operator frozen at a flat patch causes (its kink along the border; see fair_region.h).
  int iterations = 1;
  /// Stop iterating once a solve moves no free vertex by more than this times the mean length of
  /// the edges at free vertices (measured on the input). The iteration also stops, keeping the
  /// previous solution, at a solve that would move the vertices farther than the solve before it
  /// did: there it is not contracting (on a 1256-vertex region of blub it went 8 edges astray).
  double tolerance = 0.0;
  /// The system's free block of L(M⁻¹L)^(k−1) is symmetric: harmonic_fair always sets `symmetric`.
  LinearSolverOptions solver;
};

/// What the fairing did.
struct HarmonicReport {
  int free_vertices = 0;
  int order = 0;
  double backward_error = 0;  ///< largest normwise backward error of the last three solves
  int iterations = 0;         ///< solves done (HarmonicOptions::iterations, tolerance)
  double max_move = 0;        ///< largest move of a free vertex in the last solve
};

/// Moves the free vertices of `region` in `V` (#V by 3, updated in place) to the solution of
/// ∆^k x = 0 (re-solved as HarmonicOptions::iterations says; the sparsity pattern is analyzed once).
/// Throws InvalidArgument for an order outside 1..3, iterations < 1 or a free component that touches
/// no fixed vertex (the system would be singular), NumericalError if the linear solve fails. On a
/// throw, V is unchanged.
HarmonicReport harmonic_fair(Vertices& V, const Faces& F, const Region& region,
                             const HarmonicOptions& options = {});
/// The same on `topo`, the connectivity of F (build_topology), instead of building it again.
HarmonicReport harmonic_fair(Vertices& V, const Faces& F, const Topology& topo, const Region& region,
                             const HarmonicOptions& options = {});

}  // namespace fairsurf
