// Stanford PLY writing: binary little-endian or ASCII, doubles for every vertex value, polygons as
// `list uchar int vertex_indices`.
#include "io_formats.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <utility>

namespace fairsurf::io_detail {
namespace {

// Little-endian bytes of `value`, whatever the host.
template <typename T>
void put(std::string& out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof(T));
  out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

// What a written vertex record holds beyond x, y, z: per-vertex rows of N and TC (empty when the
// mesh has none, or they differ between the corners of a vertex), scalars, colours.
struct WrittenVertex {
  std::vector<int> normal_row, tc_row;
  bool normals = false, tcs = false;
};

WrittenVertex written_vertex(const Mesh& mesh, std::vector<std::string>& notes) {
  WrittenVertex w;
  if (mesh.FN.rows() > 0) {
    w.normals = per_vertex_rows(mesh, mesh.FN, mesh.N, w.normal_row);
    if (!w.normals)
      notes.push_back("normals not written: PLY holds one per vertex, and some vertex has none or several "
                      "(OBJ keeps them per corner)");
  }
  if (mesh.FTC.rows() > 0) {
    w.tcs = per_vertex_rows(mesh, mesh.FTC, mesh.TC, w.tc_row);
    if (!w.tcs)
      notes.push_back("texture coordinates not written: PLY holds one per vertex, and some vertex has none "
                      "or several, as at a seam (OBJ keeps them per corner)");
  }
  return w;
}

bool is_reserved_name(const std::string& name, const WrittenVertex& w) {
  return name == "x" || name == "y" || name == "z" || name == "red" || name == "green" || name == "blue" ||
         (w.normals && (name == "nx" || name == "ny" || name == "nz")) || (w.tcs && (name == "u" || name == "v"));
}

void write_header(const Mesh& mesh, const WrittenVertex& w, int faces, bool binary, std::string& out) {
  out += "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by fairsurf\nelement vertex " + std::to_string(mesh.V.rows()) +
         "\nproperty double x\nproperty double y\nproperty double z\n";
  if (w.normals) out += "property double nx\nproperty double ny\nproperty double nz\n";
  if (w.tcs) out += "property double u\nproperty double v\n";
  for (const auto& [name, values] : mesh.vertex_scalars) {
    if (name.empty() || is_reserved_name(name, w) ||
        std::any_of(name.begin(), name.end(), [](unsigned char c) { return c <= ' ' || c >= 127; }))
      throw InvalidArgument("write_mesh: vertex scalar name '" + name + "' cannot be a PLY property name");
    out += "property double " + name + "\n";
  }
  if (mesh.vertex_colors.rows() > 0) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "element face " + std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

// The doubles of vertex v after x, y, z, in header order; a vertex of no face gets zeros.
template <class Emit>
void vertex_values(const Mesh& mesh, const WrittenVertex& w, Eigen::Index v, Emit&& emit) {
  for (int k = 0; k < 3; ++k) emit(mesh.V(v, k));
  if (w.normals)
    for (int k = 0; k < 3; ++k) emit(w.normal_row[v] >= 0 ? mesh.N(w.normal_row[v], k) : 0.0);
  if (w.tcs)
    for (int k = 0; k < 2; ++k) emit(w.tc_row[v] >= 0 ? mesh.TC(w.tc_row[v], k) : 0.0);
  for (const auto& entry : mesh.vertex_scalars) emit(entry.second(v));
}

void write_binary_body(const Mesh& mesh, const WrittenVertex& w, const OutputPolygons& polygons, std::string& out) {
  const bool colors = mesh.vertex_colors.rows() > 0;
  out.reserve(out.size() + static_cast<std::size_t>(mesh.V.rows()) * (24 + 8 * mesh.vertex_scalars.size() + 43) +
              static_cast<std::size_t>(polygons.size()) + 4 * polygons.vertex.size());
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    vertex_values(mesh, w, v, [&](double value) { put(out, value); });
    if (colors)
      for (int k = 0; k < 3; ++k) put(out, mesh.vertex_colors(v, k));
  }
  for (int p = 0; p < polygons.size(); ++p) {
    put(out, static_cast<std::uint8_t>(polygons.corners(p)));
    for (int c = polygons.offsets[p]; c < polygons.offsets[p + 1]; ++c)
      put(out, static_cast<std::int32_t>(polygons.vertex[c]));
  }
}

void write_ascii_body(const Mesh& mesh, const WrittenVertex& w, const OutputPolygons& polygons, std::string& out) {
  const bool colors = mesh.vertex_colors.rows() > 0;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    bool first = true;
    vertex_values(mesh, w, v, [&](double value) {
      if (!std::exchange(first, false)) out += ' ';
      append_number(out, value);
    });
    if (colors)
      for (int k = 0; k < 3; ++k) {
        out += ' ';
        append_number(out, static_cast<long long>(mesh.vertex_colors(v, k)));
      }
    out += '\n';
  }
  append_polygon_lines(polygons, out);
}

// The face list counts corners in a uchar: a polygon of more than 255 corners goes as its triangles.
OutputPolygons ply_polygons(const Mesh& mesh) {
  OutputPolygons polygons = output_polygons(mesh);
  for (int p = 0; p < polygons.size(); ++p)
    if (polygons.corners(p) > 255) {
      Mesh triangles_only = mesh;
      triangles_only.face_polygon.resize(0);
      return output_polygons(triangles_only);
    }
  return polygons;
}

}  // namespace

void write_ply(const Mesh& mesh, bool binary, std::string& out, std::vector<std::string>& notes) {
  const WrittenVertex w = written_vertex(mesh, notes);
  const OutputPolygons polygons = ply_polygons(mesh);
  write_header(mesh, w, polygons.size(), binary, out);
  if (binary) write_binary_body(mesh, w, polygons, out);
  else write_ascii_body(mesh, w, polygons, out);
}

}  // namespace fairsurf::io_detail
