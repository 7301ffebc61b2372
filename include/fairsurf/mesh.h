// fairsurf — the light mesh type every algorithm works on.
//
// Plain Eigen arrays in the libigl style, stored row-major so that one vertex's coordinates (and
// one face's indices) are contiguous in memory, which is what the per-vertex assembly loops read.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <string>

namespace fairsurf {

/// #V by 3 vertex positions.
using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #F by 3 vertex indices of triangles, counter-clockwise seen from the side the normal points to.
using Faces = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #V by 3 RGB colours, 0-255.
using Colors = Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// A triangle mesh with optional per-vertex attributes.
///
/// Vertex order is meaningful: region files and attributes index vertices in this order, and the
/// readers preserve the order of the file exactly.
struct Mesh {
  Vertices V;  ///< #V by 3 positions
  Faces F;     ///< #F by 3 triangles, 0-based indices into V
  /// Named per-vertex scalars (H, K, ...), each of length #V; written as PLY vertex properties.
  std::map<std::string, Eigen::VectorXd> vertex_scalars;
  /// Optional per-vertex colours: either empty or #V by 3.
  Colors vertex_colors;

  int num_vertices() const { return static_cast<int>(V.rows()); }
  int num_faces() const { return static_cast<int>(F.rows()); }
};

}  // namespace fairsurf
