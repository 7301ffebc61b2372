// fairsurf — per-vertex curvatures of a whole mesh in one call: topology, quadratic fits and
// geometry (quadratic_fit.h, operators.h), for callers that want H, K, k1, k2 and nothing else
// (`fairsurf curvature` and `render`, the Python bindings).
#pragma once

#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/mesh/mesh.h>

#include <vector>

namespace fairsurf {

struct Curvatures {
  SurfaceGeometry geometry;        ///< normal, H (= −1/R on an outward sphere), K, k1, k2, area
  std::vector<FitStatus> status;   ///< #V: whether each vertex's fit is well posed
};

/// Fits every vertex of `mesh` and evaluates its curvatures (a vertex without faces gets an
/// ill-posed status). Throws InvalidMeshError for a face index outside [0, #V), a face repeating a
/// vertex or a non-finite coordinate.
Curvatures curvatures(const Mesh& mesh);

}  // namespace fairsurf
