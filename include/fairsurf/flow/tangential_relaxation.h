// fairsurf — tangential relaxation: moving vertices within their tangent planes towards better
// shaped triangles, the standard stabiliser of curvature flows on irregular meshes (method.md §5 allows
// it: normal motion fixes the shape, not the vertex distribution).
//
// A vertex v moves a fraction `weight` of the way towards the mean of its neighbours (the uniform
// umbrella), with the component along its unit normal n_v removed:
//   x_v ← x_v + weight · (I − n_v n_vᵀ) (mean_{u ∈ N(v)} x_u − x_v).
// Because the move is orthogonal to n_v, the surface changes only to second order in the move
// (|move|² · curvature); the uniform umbrella pulls a vertex away from the long side of a needle
// triangle and evens out edge lengths, so repeated relaxation removes needles that the vertex
// placement of a raw scan creates. The moves are computed from the positions before the call
// (Jacobi), so the result does not depend on the order of the vertices. The moves are not checked:
// on rough input pair them with orientation_guard.h, as run_flow does.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <span>

namespace fairsurf {

/// Relaxes the listed `vertices` of X (#V by 3) in place; every other vertex stays where it is.
/// `normals` (#V by 3) are unit normals, read at the listed vertices only. weight in [0, 1]: 0 does
/// nothing, 1 moves to the tangential projection of the neighbours' mean. Throws InvalidArgument
/// for a weight outside [0, 1] or sizes that do not match.
void relax_tangentially(Vertices& X, const Topology& topo, std::span<const int> vertices,
                        const Vertices& normals, double weight);

}  // namespace fairsurf
