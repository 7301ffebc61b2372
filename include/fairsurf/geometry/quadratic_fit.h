// fairsurf — per-vertex local quadratic fits (method.md §3), the numerical heart every operator uses.
//
// At vertex i a quadratic x(u,v) = x_i + a1 u + a2 v + a3 u² + a4 uv + a5 v² is fitted by weighted
// least squares to the neighbours j ∈ N(i), in a local frame (N0, e1, e2):
//   N0 = area-weighted normal of the faces incident to i (unit, oriented like the faces),
//   e1 = the projection onto the tangent plane of x_j − x_i for the first neighbour j of N(i)
//        (ascending index) whose projection is not negligible, normalized; e2 = N0 × e1,
//   (u_j, v_j) = ((x_j − x_i)·e1, (x_j − x_i)·e2), weights 1/r_j² with r_j² = u_j² + v_j².
// The fit is linear in the data: a = C_i (x_j − x_i)_j, where C_i = (BᵀWB)⁻¹BᵀW is 5 × |N(i)|
// (rows: the coefficients a1..a5; B has rows (u, v, u², uv, v²)). The same C_i fits any scalar f
// from (f_j − f_i). Columns of B are scaled by (s, s, s², s², s²), s = rms r_j, and the 5 × 5 scaled
// normal matrix M = BₛᵀWBₛ is inverted by Cholesky; the recorded condition number is that of the
// scaled weighted least-squares problem, estimated as sqrt(κ₁(M)) = sqrt(‖M‖₁‖M⁻¹‖₁) (within a
// factor √5 of the 2-norm condition of W^½Bₛ).
//
// Neighbourhoods (method.md §3.1): the 1-ring for an interior vertex of valence ≥ 5 whose 1-ring fit
// has condition ≤ FitOptions::max_one_ring_condition; otherwise the 2-ring (1- and 2-ring vertices).
// The choice is made once, by `fit_quadratics`, from the positions it is given; `refit_quadratics`
// keeps it (the sparsity pattern of every operator depends on it) and reports the new statuses.
//
// Ill-posed neighbourhoods are reported per vertex (FitStatus), never turned into NaN: every stored
// number is finite. Fits with status kTooFewNeighbours or kDegenerate have their C_i set to zero (so
// every operator row built from them is zero); kIllConditioned and kFold fits are kept and flagged.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace fairsurf {

/// Which neighbourhood N(i) a vertex uses, and why.
enum class Neighbourhood : std::uint8_t {
  kNotFitted,               ///< outside the requested subset: N(i) is empty
  kOneRing,                 ///< interior, valence ≥ 5, well-conditioned 1-ring fit
  kTwoRingLowValence,       ///< interior vertex of valence < 5
  kTwoRingBorder,           ///< an incident edge has one face (border) or more than two
  kTwoRingIllConditioned,   ///< the 1-ring fit's condition exceeded max_one_ring_condition
  kTwoRingRequested,        ///< the caller asked for the 2-ring (fit_quadratics' two_ring_vertices)
};

/// Whether the fit at a vertex is well posed. Ordered by precedence: a vertex gets the first that
/// applies.
enum class FitStatus : std::uint8_t {
  kOk,                ///< well posed
  kNotFitted,         ///< outside the requested subset; nothing computed
  kTooFewNeighbours,  ///< |N(i)| < 5 even with the 2-ring: five coefficients cannot be fitted; C_i = 0
  kDegenerate,        ///< N0 vanishes (faces cancel or have no area) or the scaled normal matrix is
                      ///< numerically singular (e.g. collinear projected neighbours); C_i = 0
  kFold,              ///< the neighbourhood is not a graph over the tangent plane: a face incident
                      ///< to i (1-ring) or to a 1-ring neighbour (2-ring) projects onto (e1, e2)
                      ///< with negative orientation; the fit is kept
  kIllConditioned,    ///< condition number above FitOptions::max_condition; the fit is kept
};

const char* to_string(Neighbourhood reason);
const char* to_string(FitStatus status);

struct FitOptions {
  /// A 1-ring fit whose condition number exceeds this uses the 2-ring instead (method.md §3.1).
  double max_one_ring_condition = 1e3;
  /// A fit whose condition number exceeds this is flagged kIllConditioned.
  double max_condition = 1e5;
  /// A fit whose scaled normal matrix is not positive definite, or has κ₁(M) ≥ 1/singular_tolerance,
  /// is kDegenerate.
  double singular_tolerance = 1e-13;
};

/// Per-vertex fits over a fixed connectivity. Rows are indexed by vertex (#V rows in every CSR);
/// vertices outside the fitted subset have empty rows.
struct QuadraticFits {
  static constexpr int kTerms = 5;  ///< a1..a5

  FitOptions options;
  Csr neighbours;  ///< N(i), ascending vertex indices (i itself excluded)
  std::vector<Neighbourhood> neighbourhood;  ///< #V: which N(i) and why
  /// 5 × nnz(neighbours): the column of C_i for the k-th neighbour of row i is
  /// coefficients[5·(neighbours.offsets[i] + k) + r], r = 0..4 for a1..a5.
  Eigen::VectorXd coefficients;
  Vertices frame_normal;      ///< #V by 3: N0 (zero where not fitted or degenerate)
  Vertices frame_tangent1;    ///< #V by 3: e1
  Vertices frame_tangent2;    ///< #V by 3: e2 = N0 × e1
  Eigen::VectorXd condition;  ///< #V: sqrt(κ₁(M)) of the scaled normal matrix M (∞ if singular)
  std::vector<FitStatus> status;  ///< #V

  // What re-fitting on new positions needs, copied so that the fits stand alone.
  Faces faces;       ///< #F by 3, the connectivity the fits were built on
  Csr vertex_faces;  ///< faces incident to each vertex (for N0 and the 1-ring fold check)
  Csr outer_faces;   ///< 2-ring rows only: faces incident to a 1-ring neighbour but not to i

  int num_vertices() const { return neighbours.rows(); }
  /// Counts of vertices per status, indexed by FitStatus.
  std::vector<int> status_counts() const;
};

/// Builds N(i) and fits every vertex (when `vertices` is empty) or only the listed ones. The
/// vertices in `two_ring_vertices` are fitted over their 2-ring whatever their valence: a fit over
/// about 18 neighbours instead of 6 reads the surface at twice the mesh's scale and averages out
/// noise at the scale of one edge (the flow's boundary data, FlowOptions::two_ring_boundary_fits).
/// Throws InvalidArgument if V and `topo` disagree or a listed vertex is out of range, and
/// InvalidMeshError if V contains a non-finite coordinate.
QuadraticFits fit_quadratics(const Vertices& V, const Faces& F, const Topology& topo,
                             const FitOptions& options = {}, std::span<const int> vertices = {},
                             std::span<const int> two_ring_vertices = {});

/// Re-fits with new positions on the same connectivity and the same neighbourhoods, writing into
/// the existing buffers (no allocation). Throws InvalidArgument if V has the wrong size.
void refit_quadratics(QuadraticFits& fits, const Vertices& V);

}  // namespace fairsurf
