// fairsurf — whole-mesh operations that later stages build on (blend joins two parts, scenes
// assemble test scenes).
#pragma once

#include <fairsurf/mesh/mesh.h>

namespace fairsurf {

/// `first`'s vertices and faces, then `second`'s with indices shifted by first's #V. Per-vertex
/// scalars and colours are kept when both meshes have them (same names), dropped otherwise.
Mesh concatenate_meshes(const Mesh& first, const Mesh& second);

}  // namespace fairsurf
