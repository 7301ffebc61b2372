// Object File Format (ASCII): OFF and its COFF/NOFF/NCOFF/STOFF variants. Anything after the
// coordinates of a vertex line (colour, normal, texture) and after the indices of a face line
// (colour) is ignored.
#include "io_formats.h"

#include <climits>

namespace fairsurf::io_detail {
namespace {

// "OFF" with any of the optional ST, C, N prefixes; 4OFF and nOFF (other dimensions) are refused.
bool is_off_keyword(std::string_view keyword) {
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF") return false;
  for (const char c : keyword.substr(0, keyword.size() - 3))
    if (c != 'S' && c != 'T' && c != 'C' && c != 'N') return false;
  return true;
}

class OffReader {
 public:
  OffReader(const Source& source, ReadReport& report)
      : source_(source), report_(report), scanner_(source.bytes, 0, true) {}

  RawMesh read() {
    read_header();
    read_vertices();
    read_faces();
    if (!scanner_.next().empty())
      report_.notes.push_back("ignored content after the last face (line " +
                              std::to_string(source_.line_at(scanner_.position())) + ")");
    return std::move(raw_);
  }

 private:
  [[noreturn]] void fail_here(const std::string& what) const {
    source_.fail("line " + std::to_string(source_.line_at(scanner_.position())) + ": " + what);
  }

  int count(std::string_view token, const char* what) {
    long long value = 0;
    if (token.empty()) source_.fail("unexpected end of file in the counts line");
    if (!parse_int64(token, value) || value < 0 || value > INT_MAX)
      fail_here(std::string("invalid ") + what + " count '" + std::string(token) + "'");
    return static_cast<int>(value);
  }

  void read_header() {
    const std::string_view keyword = scanner_.next();
    if (!is_off_keyword(keyword)) fail_here("expected an 'OFF' header, found '" + std::string(keyword) + "'");
    std::string_view first = scanner_.next_on_line();  // counts may follow on the header line
    if (first == "BINARY") fail_here("binary OFF is not supported");
    if (first.empty()) first = scanner_.next();
    num_vertices_ = count(first, "vertex");
    num_faces_ = count(scanner_.next(), "face");
    scanner_.skip_line();  // the edge count, which nothing uses
  }

  double coordinate(std::string_view token, int vertex) const {
    if (token.empty() && scanner_.remaining() == 0)
      source_.fail("unexpected end of file after " + std::to_string(vertex) + " of " +
                   std::to_string(num_vertices_) + " vertices");
    if (token.empty()) fail_here("vertex " + std::to_string(vertex) + " has fewer than 3 coordinates");
    double value = 0;
    if (!parse_double(token, value)) fail_here("malformed number '" + std::string(token) + "'");
    return value;
  }

  void read_vertices() {
    std::vector<double> xyz;
    xyz.reserve(3 * safe_reserve(num_vertices_, scanner_.remaining(), 6));
    for (int v = 0; v < num_vertices_; ++v) {
      xyz.push_back(coordinate(scanner_.next(), v));
      xyz.push_back(coordinate(scanner_.next_on_line(), v));
      xyz.push_back(coordinate(scanner_.next_on_line(), v));
      scanner_.skip_line();
    }
    raw_.V = to_vertices(xyz);
  }

  long long integer(std::string_view token, int face) const {
    if (token.empty() && scanner_.remaining() == 0)
      source_.fail("unexpected end of file after " + std::to_string(face) + " of " +
                   std::to_string(num_faces_) + " faces");
    if (token.empty()) fail_here("face " + std::to_string(face) + " has fewer indices than its corner count");
    long long value = 0;
    if (!parse_int64(token, value)) fail_here("malformed integer '" + std::string(token) + "'");
    return value;
  }

  void read_faces() {
    const std::size_t reserve = safe_reserve(num_faces_, scanner_.remaining(), 8);
    raw_.polygon_offsets.reserve(reserve + 1);
    raw_.polygon_indices.reserve(3 * reserve);
    for (int f = 0; f < num_faces_; ++f) {
      const long long corners = integer(scanner_.next(), f);
      if (corners < 0) fail_here("face " + std::to_string(f) + " has a negative corner count");
      for (long long k = 0; k < corners; ++k) {
        const long long index = integer(scanner_.next_on_line(), f);
        if (index < INT_MIN || index > INT_MAX) fail_here("vertex index " + std::to_string(index) + " out of range");
        raw_.polygon_indices.push_back(static_cast<int>(index));
      }
      if (raw_.polygon_indices.size() > static_cast<std::size_t>(INT_MAX)) fail_here("too many face corners");
      raw_.polygon_offsets.push_back(static_cast<int>(raw_.polygon_indices.size()));
      scanner_.skip_line();  // optional face colour
    }
  }

  const Source& source_;
  ReadReport& report_;
  TextScanner scanner_;
  RawMesh raw_;
  int num_vertices_ = 0;
  int num_faces_ = 0;
};

}  // namespace

RawMesh read_off(const Source& source, ReadReport& report) { return OffReader(source, report).read(); }

void write_off(const Mesh& mesh, std::string& out, std::vector<std::string>& notes) {
  const OutputPolygons polygons = output_polygons(mesh);
  out.reserve(static_cast<std::size_t>(mesh.V.rows()) * 62 + polygons.vertex.size() * 8 + 32);
  out += "OFF\n";
  append_number(out, static_cast<long long>(mesh.V.rows()));
  out += ' ';
  append_number(out, static_cast<long long>(polygons.size()));
  out += " 0\n";
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    for (int k = 0; k < 3; ++k) {
      if (k) out += ' ';
      append_number(out, mesh.V(v, k));
    }
    out += '\n';
  }
  append_polygon_lines(polygons, out);
  // OFF's vertex lines could carry one normal or texture coordinate per vertex, but few readers
  // agree on the layout (NOFF, STOFF): OBJ keeps them per corner.
  if (mesh.FTC.rows() > 0) notes.push_back("texture coordinates not written: OFF has no place for them (OBJ keeps them)");
  if (mesh.FN.rows() > 0) notes.push_back("normals not written: OFF has no place for them (OBJ keeps them)");
}

}  // namespace fairsurf::io_detail
