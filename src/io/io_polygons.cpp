// The faces writers give back: polygons rebuilt from the fans triangulate() made of them, and the
// per-vertex view of per-corner attributes that PLY needs.
#include "io_formats.h"

#include <unordered_map>

namespace fairsurf::io_detail {
namespace {

// Texture and normal index of corner k of face f (-1 without the array).
int tc_of(const Mesh& mesh, int f, int k) { return mesh.FTC.rows() > 0 ? mesh.FTC(f, k) : -1; }
int normal_of(const Mesh& mesh, int f, int k) { return mesh.FN.rows() > 0 ? mesh.FN(f, k) : -1; }

bool same_corner(const Mesh& mesh, int f, int k, int g, int l) {
  return mesh.F(f, k) == mesh.F(g, l) && tc_of(mesh, f, k) == tc_of(mesh, g, l) &&
         normal_of(mesh, f, k) == normal_of(mesh, g, l);
}

void add_corner(const Mesh& mesh, int f, int k, OutputPolygons& out) {
  out.vertex.push_back(mesh.F(f, k));
  out.tc.push_back(tc_of(mesh, f, k));
  out.normal.push_back(normal_of(mesh, f, k));
}

void close_polygon(OutputPolygons& out) { out.offsets.push_back(static_cast<int>(out.vertex.size())); }

// Whether faces [first, end) are the fan (c0, c_i, c_i+1) of one polygon; `reversed`: each with its
// corners 1 and 2 swapped, as orienting the polygon the other way leaves them.
bool is_fan(const Mesh& mesh, int first, int end, bool reversed) {
  for (int f = first + 1; f < end; ++f) {
    if (!same_corner(mesh, f, 0, first, 0)) return false;
    if (reversed ? !same_corner(mesh, f, 2, f - 1, 1) : !same_corner(mesh, f, 1, f - 1, 2)) return false;
  }
  return true;
}

void add_fan(const Mesh& mesh, int first, int end, bool reversed, OutputPolygons& out) {
  add_corner(mesh, first, 0, out);
  if (!reversed) {
    add_corner(mesh, first, 1, out);
    for (int f = first; f < end; ++f) add_corner(mesh, f, 2, out);
  } else {
    add_corner(mesh, end - 1, 1, out);
    for (int f = end - 1; f >= first; --f) add_corner(mesh, f, 2, out);
  }
  close_polygon(out);
}

}  // namespace

OutputPolygons output_polygons(const Mesh& mesh) {
  OutputPolygons out;
  const int num_faces = mesh.num_faces();
  out.offsets.reserve(static_cast<std::size_t>(num_faces) + 1);
  out.vertex.reserve(3 * static_cast<std::size_t>(num_faces));
  out.tc.reserve(out.vertex.capacity());
  out.normal.reserve(out.vertex.capacity());
  const bool grouped = mesh.face_polygon.size() == num_faces;
  std::unordered_map<int, int> triangles;  // polygon -> its triangles anywhere in the mesh
  if (grouped)
    for (int f = 0; f < num_faces; ++f) ++triangles[mesh.face_polygon[f]];
  for (int f = 0; f < num_faces;) {
    int end = f + 1;
    const int polygon = grouped ? mesh.face_polygon[f] : -1;
    if (polygon >= 0)
      while (end < num_faces && mesh.face_polygon[end] == polygon) ++end;
    const bool whole = polygon >= 0 && end - f > 1 && triangles[polygon] == end - f;
    if (whole && is_fan(mesh, f, end, false)) {
      add_fan(mesh, f, end, false, out);
    } else if (whole && is_fan(mesh, f, end, true)) {
      add_fan(mesh, f, end, true, out);
    } else {
      for (int g = f; g < end; ++g) {
        for (int k = 0; k < 3; ++k) add_corner(mesh, g, k, out);
        close_polygon(out);
      }
    }
    f = end;
  }
  return out;
}

void append_polygon_lines(const OutputPolygons& polygons, std::string& out) {
  for (int p = 0; p < polygons.size(); ++p) {
    append_number(out, static_cast<long long>(polygons.corners(p)));
    for (int c = polygons.offsets[p]; c < polygons.offsets[p + 1]; ++c) {
      out += ' ';
      append_number(out, static_cast<long long>(polygons.vertex[c]));
    }
    out += '\n';
  }
}

bool per_vertex_rows(const Mesh& mesh, const Faces& FX, const Eigen::Ref<const Table>& table,
                     std::vector<int>& of_vertex) {
  of_vertex.assign(static_cast<std::size_t>(mesh.num_vertices()), -1);
  if (FX.rows() != mesh.num_faces()) return false;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int row = FX(f, k);
      if (row < 0) return false;
      int& chosen = of_vertex[mesh.F(f, k)];
      if (chosen >= 0 && chosen != row && table.row(chosen) != table.row(row)) return false;
      chosen = row;
    }
  return true;
}

}  // namespace fairsurf::io_detail
