// Subdivision of the bundled meshes for the benchmarks, by OpenMesh's uniform subdividers (a Debian
// package, libopenmesh-dev): Loop's scheme to make large smooth meshes, the modified butterfly
// scheme for a smooth stand-in that keeps the mesh's own vertices (smooth_reference.h).
#pragma once

#include <fairsurf/mesh/mesh.h>

namespace fairsurf::bench {

/// `levels` rounds of Loop subdivision (OpenMesh's LoopT): each round splits every triangle into
/// four and moves every vertex, old and new, by Loop's weights; the surface approximates the input.
/// Attributes are dropped; vertex indices are OpenMesh's (the old vertices first). Throws
/// InvalidArgument for negative `levels` or a face OpenMesh cannot add (a non-manifold one).
Mesh loop_subdivide(const Mesh& mesh, int levels);

/// `levels` rounds of modified butterfly subdivision (OpenMesh's ModifiedButterflyT): each round
/// splits every triangle into four; the scheme interpolates, every vertex of `mesh` stays where it
/// is. Attributes are dropped. Throws as loop_subdivide does.
Mesh butterfly_refined(const Mesh& mesh, int levels);

}  // namespace fairsurf::bench
