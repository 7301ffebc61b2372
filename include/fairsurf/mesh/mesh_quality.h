// fairsurf — figures that say whether a smoothing run did what a user expects: faces that turned
// over against a reference state, and the data README's rough noise index.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

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

}  // namespace fairsurf
