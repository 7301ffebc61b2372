// CGAL 5.5's hole filling and fairing as the reference of bench_real_holes. Compiled only into that
// benchmark, and only when CMake finds CGAL (FAIRSURF_BENCH_CGAL): the library never depends on it.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <string>
#include <vector>

namespace fairsurf::bench {

struct CgalResult {
  bool ok = false;             ///< every call reported success
  std::string error;           ///< why not (a failed fairing, an exception, a face CGAL refused)
  Vertices V;                  ///< positions after the call (the input's vertices first)
  Faces F;                     ///< triangles after the call (fill: the input's and the patches')
  std::vector<int> moved;      ///< new vertices (fill) or the faired vertices (fair)
  double seconds = 0;
};

/// triangulate_refine_and_fair_hole with fairing_continuity(2) on every border loop of `mesh`.
CgalResult cgal_fill_holes(const Mesh& mesh);

/// Polygon_mesh_processing::fair with fairing_continuity(2) on `free_vertices`.
CgalResult cgal_fair(const Mesh& mesh, const std::vector<int>& free_vertices);

}  // namespace fairsurf::bench
