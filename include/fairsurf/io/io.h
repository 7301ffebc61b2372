// fairsurf — reading and writing meshes: OBJ, OFF, PLY (ASCII and binary), STL (ASCII and binary).
//
// The format is chosen by the file extension (case-insensitive). Reading is raw first: the file is
// parsed into a polygon soup in file order, so that nothing is dropped silently (OpenMesh's readers
// drop non-manifold faces with only a warning); vertex order is preserved exactly. Writing is atomic:
// the file is written to a temporary file beside the target and renamed into place.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fairsurf {

/// A polygon soup exactly as stored in a file.
struct RawMesh {
  Vertices V;                              ///< #V by 3, in file order
  std::vector<int> polygon_offsets{0};     ///< #P+1 offsets into polygon_indices
  std::vector<int> polygon_indices;        ///< 0-based vertex indices, unchecked
  std::map<std::string, Eigen::VectorXd> vertex_scalars;  ///< extra PLY vertex properties
  Colors vertex_colors;                    ///< empty or #V by 3
  TexCoords TC;                            ///< texture coordinate table (OBJ vt; PLY u, v per vertex)
  std::vector<int> corner_tc;              ///< empty or one row of TC per polygon corner, -1: none
  Vertices N;                              ///< normal table (OBJ vn; PLY nx, ny, nz per vertex)
  std::vector<int> corner_n;               ///< empty or one row of N per polygon corner, -1: none
};

/// What reading did beyond parsing, for the caller to report.
struct ReadReport {
  int polygons_triangulated = 0;   ///< polygons with more than 3 corners fanned into triangles
  int triangles_added = 0;         ///< triangles those polygons became beyond one each
  std::vector<std::string> notes;  ///< human-readable remarks (ignored lines, texture indices, ...)
};

/// Parses `path` into a polygon soup. Throws IoError (missing, unreadable, unknown extension) or
/// ParseError (malformed or truncated, with the line or byte offset where it broke).
RawMesh read_raw(const std::filesystem::path& path, ReadReport* report = nullptr);

/// Triangulates a soup (polygons fanned from their first corner) into a Mesh; vertex indices are
/// copied as they are (validate() reports out-of-range ones). Corner texture/normal indices follow
/// their corners into FTC/FN (one outside its table reads as none, -1). When some polygon has more
/// than 3 corners, face_polygon records which polygon each triangle came from. Polygons with fewer
/// than 3 corners throw ParseError.
Mesh triangulate(const RawMesh& raw, ReadReport* report = nullptr);
/// The same, moving the vertex arrays out of `raw` instead of copying them.
Mesh triangulate(RawMesh&& raw, ReadReport* report = nullptr);

/// read_raw followed by triangulate. No validation and no repair: vertex order is the file's.
Mesh read_mesh(const std::filesystem::path& path, ReadReport* report = nullptr);

struct WriteOptions {
  bool binary = true;  ///< PLY and STL: binary (little-endian) or ASCII; ignored for OBJ and OFF
};

/// What the format could not hold, for the caller to report.
struct WriteReport {
  std::vector<std::string> notes;  ///< e.g. "texture coordinates not written: STL has no place for them"
};

/// Writes `mesh` atomically in the format named by the extension of `path`. ASCII coordinates use
/// 17 significant digits, so a round trip is exact. PLY carries vertex_scalars and vertex_colors.
/// OBJ, OFF and PLY write a polygon of face_polygon back as one face where its triangles are all
/// still there, consecutive and in fan order; OBJ writes TC/FTC and N/FN per corner (vt, vn), PLY
/// writes them as vertex properties u, v and nx, ny, nz when each vertex has one value; anything
/// else the format cannot hold is left out with a note in `report`.
/// Throws IoError if the file cannot be written; the target is then left untouched. Throws
/// InvalidArgument, before writing anything, for a face index outside [0, #V), vertex_scalars or
/// vertex_colors whose length is not #V, FTC, FN or face_polygon neither empty nor #F rows, a
/// corner index outside [-1, #TC) or [-1, #N), or a scalar name that is not a valid PLY property
/// name. STL stores float32 coordinates: writing it rounds every coordinate to float.
void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options = {},
                WriteReport* report = nullptr);

/// Writes `bytes` to `path` atomically: into a temporary file beside it, flushed to disk, then renamed
/// onto it. On failure the temporary file is removed, an existing file at `path` is left untouched,
/// and IoError is thrown with a message that starts with `caller` (the public function writing).
/// Every output of the library and the CLI (meshes, images, logs) goes through it.
void write_file_atomically(const std::filesystem::path& path, const std::string& bytes,
                           const std::string& caller);

}  // namespace fairsurf
