// Loop subdivision, used by benchmarks to make large smooth meshes from the bundled ones.
#pragma once

#include <fairsurf/mesh/mesh.h>

namespace fairsurf::bench {

/// Applies `levels` rounds of Loop subdivision (Loop 1987, with Warren's weights beta = 3/(8n),
/// 3/16 for valence 3). Each round splits every triangle into four; the old vertices keep their
/// indices (repositioned) and the new edge vertices follow, in the order of topology.h's edges.
/// Border edges use the curve rules (1/2, 1/2 and 1/8, 3/4, 1/8); vertices on non-manifold
/// borders keep their position. Attributes (scalars, colours) are dropped.
/// Throws InvalidArgument for negative `levels` (and build_topology's errors for bad faces).
Mesh loop_subdivide(const Mesh& mesh, int levels);

}  // namespace fairsurf::bench
