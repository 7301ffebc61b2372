// fairsurf — keeping a mesh's optional per-corner attributes (texture coordinates, normals) and its
// polygon grouping true when faces are added, removed or rebuilt, or when vertices move.
//
// The algorithms work on V and F alone; these functions are what the operations that change faces
// (fill, blend, repair, concatenate_meshes) and the commands that move vertices call, so that FTC,
// FN and face_polygon stay either empty or #F rows, each entry meaning what it says.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <span>

namespace fairsurf {

/// Whether `mesh` has texture coordinates, normals or a polygon grouping.
bool has_corner_attributes(const Mesh& mesh);

/// For faces appended to `mesh` (its first faces unchanged and in their order, as fill and blend
/// leave them): gives each new face no texture coordinate, no normal and no polygon (-1), so that
/// FTC, FN and face_polygon have #F rows again. Returns the number of faces padded.
int pad_face_attributes(Mesh& mesh);

/// Carries FTC, FN and face_polygon from `from` onto `to`, whose vertex i is a copy of `from`'s
/// vertex vertex_source[i] at the same position (what repair leaves: vertices merged, split or
/// removed, faces removed, reoriented or rebuilt, nothing moved). A face of `to` takes the values
/// of a face of `from` with the same three corner positions, corner by corner; a face with no such
/// twin (a triangle repair built) gets -1, and so does every triangle of a polygon that lost one.
/// The TC and N tables are copied.
void carry_face_attributes(const Mesh& from, std::span<const int> vertex_source, Mesh& to);

/// The attributes of `first` and `second` joined into `out`, whose faces are first's then second's
/// (concatenate_meshes): the tables appended, second's indices and polygons shifted past first's,
/// -1 for the faces of a mesh that has none of an attribute the other has.
void concatenate_attributes(const Mesh& first, const Mesh& second, Mesh& out);

/// Recomputes every normal (row of N) that a corner of a moved vertex uses, as the area-weighted
/// mean of the normals of the faces whose corners use that row: a crease (a vertex with one normal
/// per side) stays a crease and a smooth vertex stays smooth. `before` holds the positions the
/// stored normals belong to (vertices past its rows are new, and count as moved). A row whose faces
/// have no area keeps its value. Returns the number of rows recomputed.
int refresh_moved_normals(Mesh& mesh, const Vertices& before);

}  // namespace fairsurf
