// fairsurf — figures that say whether a smoothing run did what a user expects: faces that turned
// over against a reference state, and the data README's rough noise index; and how rough a surface
// is at the scale of its edges, which tells fill whether its held-out rings can rank two fills.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <span>
#include <vector>

namespace fairsurf {

/// Faces whose normal (V, F) points against their normal in `reference` (#V by 3, same
/// connectivity): turned by 90° or more, or degenerate in either state. Throws InvalidArgument when
/// the vertex counts differ.
int count_inverted_faces(const Vertices& reference, const Vertices& V, const Faces& F);

/// The noise index of data/README.md: the fraction of edges whose endpoints have opposite signs of
/// the uniform umbrella operator's component along the area-weighted vertex normal, over the edges
/// whose endpoints both have `counted[v]` set (every edge when `counted` is empty; #V otherwise).
/// About 0 on a smooth regular mesh, 0.27–0.38 on raw scans; 0 if no edge is counted.
double noise_index(const Vertices& V, const Faces& F, const Topology& topo,
                   const std::vector<char>& counted = {});

/// How far each vertex lies from where its 2-ring neighbours put it: the offset along its
/// area-weighted normal from the quadratic height function fitted to them by least squares (the
/// vertex itself left out), in units of the mean length of the edges at it. The median over
/// `vertices`; vertices with fewer than 8 such neighbours or no normal are left out, and so are
/// those whose 2-ring holds a face steeper than 60° to their normal (a crease, the edge of a thin
/// part: no height function); 0 where none is left. A quadratic over the 2-ring predicts a smooth,
/// finely sampled surface to a small fraction of an edge (the closed meshes and scans of data/:
/// 0.000–0.021), and normal noise of σ edges at about 0.8 σ (0.1 edges of noise: 0.073–0.084 on
/// the same meshes). Curvature that the 2-ring under-resolves reads as roughness too
/// (data/hand_lowres.obj: 0.037).
double roughness(const Vertices& V, const Faces& F, const Topology& topo, std::span<const int> vertices);

}  // namespace fairsurf
