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
/// #TC by 2 texture coordinates (u, v).
using TexCoords = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// A triangle mesh with optional per-vertex and per-corner attributes.
///
/// Vertex order is meaningful: region files and attributes index vertices in this order, and the
/// readers preserve the order of the file exactly.
///
/// Texture coordinates and normals are stored as OBJ stores them (libigl's TC/FTC, N/FN): a table of
/// values, and for each corner of each triangle an index into it, so that a seam or a crease (one
/// vertex, several values) survives. The grouping `face_polygon` remembers which triangles were
/// fanned from one file polygon, so that writers can give the polygon back. The algorithms read V
/// and F only; whatever changes faces keeps these arrays either empty or #F rows
/// (mesh_attributes.h), and write_mesh refuses a mesh where they do not match.
struct Mesh {
  Vertices V;  ///< #V by 3 positions
  Faces F;     ///< #F by 3 triangles, 0-based indices into V
  /// Named per-vertex scalars (H, K, ...), each of length #V; written as PLY vertex properties.
  std::map<std::string, Eigen::VectorXd> vertex_scalars;
  /// Optional per-vertex colours: either empty or #V by 3.
  Colors vertex_colors;
  TexCoords TC;  ///< texture coordinate table (OBJ vt, PLY u/v), any length
  Faces FTC;     ///< empty or #F by 3: each corner's row of TC, -1 where a corner has none
  Vertices N;    ///< normal table (OBJ vn, PLY nx/ny/nz), any length
  Faces FN;      ///< empty or #F by 3: each corner's row of N, -1 where a corner has none
  /// Empty (every triangle is a face of its own) or #F: the file polygon each triangle was fanned
  /// from, -1 for a triangle of no polygon (one a command added, or one of a polygon that lost a
  /// triangle). A polygon's triangles are consecutive, fanned from its first corner.
  Eigen::VectorXi face_polygon;

  int num_vertices() const { return static_cast<int>(V.rows()); }
  int num_faces() const { return static_cast<int>(F.rows()); }
};

}  // namespace fairsurf
