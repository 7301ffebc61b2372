// fairsurf — G0 relaxation of free vertices to a membrane (discrete minimal surface), fixed ones held.
//
// One relaxation solves the cotangent Laplace equation ∆x = 0 at the free vertices with the other
// vertices fixed (Pinkall & Polthier): for each free vertex i,
//     Σ_j w_ij (x_j − x_i) = 0,   w_ij = ½ (cot α_ij + cot β_ij),
// α_ij, β_ij the angles opposite edge ij in its (one or two) triangles, the weights computed on the
// positions before the solve. The x, y and z systems share one matrix, factorized once per
// iteration with linear_solver.h. Repeating the solve with weights recomputed on the new positions
// is Pinkall–Polthier's minimal-surface iteration (a mean-curvature-like flow with infinite step);
// it normally lowers the area of the free region (the report has the areas). This is the initial state the sixth-order
// flow starts from in hole filling and blending (method.md §7).
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/solve/linear_solver.h>

#include <span>
#include <vector>

namespace fairsurf {

struct MembraneOptions {
  int iterations = 3;            ///< solves, each with weights from the previous positions
};

/// The solver relax_membrane uses by default for its (#free by #free) Laplace systems: patch-sized,
/// so the minimum-degree ordering.
inline LinearSolverOptions default_membrane_solver() { return {.ordering = FillOrdering::minimum_degree}; }

struct MembraneReport {
  int iterations = 0;
  /// Total area of the faces touching a free vertex: before, then after each iteration.
  std::vector<double> area;
  double max_displacement = 0.0;  ///< largest move of a free vertex in the last iteration
};

/// Moves the vertices `free_vertices` (indices into V, any order) of the mesh (V, F) to the
/// solution of the cotangent Laplace equation, `options.iterations` times (harmonic_fair of order 1
/// with weights from the current positions).
/// Throws InvalidArgument for an index out of range, an empty free set or iterations < 1, and
/// NumericalError if a system is singular (e.g. a free component with no fixed vertex).
MembraneReport relax_membrane(Vertices& V, const Faces& F, std::span<const int> free_vertices,
                              const MembraneOptions& options = {},
                              const LinearSolverOptions& solver = default_membrane_solver());
/// The same on `topo`, the connectivity of F (build_topology), instead of building it again.
MembraneReport relax_membrane(Vertices& V, const Faces& F, const Topology& topo, std::span<const int> free_vertices,
                              const MembraneOptions& options = {},
                              const LinearSolverOptions& solver = default_membrane_solver());

}  // namespace fairsurf
