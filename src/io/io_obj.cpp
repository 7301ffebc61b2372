// Wavefront OBJ: `v`, `vt`, `vn` and `f` records are read; every other record is ignored with one
// note per kind.
#include "io_formats.h"

#include <algorithm>
#include <cctype>
#include <climits>

namespace fairsurf::io_detail {
namespace {

bool is_keyword(std::string_view token) {
  if (token.empty() || !(std::isalpha(static_cast<unsigned char>(token[0])) || token[0] == '_')) return false;
  for (const char c : token)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

class ObjReader {
 public:
  ObjReader(const Source& source, ReadReport& report)
      : source_(source), report_(report), scanner_(source.bytes, 0, true) {}

  RawMesh read() {
    while (scanner_.remaining() > 0) {
      ++line_;
      read_line();
      scanner_.skip_line();
    }
    raw_.V = to_vertices(xyz_);
    raw_.TC.resize(static_cast<Eigen::Index>(uv_.size() / 2), 2);
    std::copy(uv_.begin(), uv_.end(), raw_.TC.data());
    raw_.N = to_vertices(normals_);
    ignored_.flush(report_.notes);
    finish_corners(raw_.corner_tc, raw_.TC.rows(), "texture", "vt");
    finish_corners(raw_.corner_n, raw_.N.rows(), "normal", "vn");
    return std::move(raw_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    source_.fail("line " + std::to_string(line_) + ": " + what);
  }

  void read_line() {
    const std::size_t start = scanner_.position();
    const std::string_view keyword = scanner_.next_on_line();
    if (keyword.empty()) {
      if (source_.bytes.substr(start, scanner_.position() - start).find('#') != std::string_view::npos)
        ignored_.add("comment lines", line_);
    } else if (keyword == "v") {
      read_vertex();
    } else if (keyword == "vt") {
      read_texture_coordinate();
    } else if (keyword == "vn") {
      read_normal();
    } else if (keyword == "f") {
      read_face();
    } else if (is_keyword(keyword)) {
      ignored_.add(std::string("'").append(keyword).append("' lines"), line_);
    } else {
      fail("unexpected '" + std::string(keyword) + "' at the start of a line");
    }
  }

  double number(std::string_view token) const {
    double value = 0;
    if (!parse_double(token, value)) fail("malformed number '" + std::string(token) + "'");
    return value;
  }

  // Parses every number left on the line (to catch garbage), appends the first `kept` to `out` and
  // returns how many there were.
  int read_numbers(std::vector<double>& out, int kept) {
    int count = 0;
    for (std::string_view token = scanner_.next_on_line(); !token.empty(); token = scanner_.next_on_line()) {
      const double value = number(token);
      if (count < kept) out.push_back(value);
      ++count;
    }
    return count;
  }

  void read_vertex() {
    const int count = read_numbers(xyz_, 3);
    if (count < 3) fail("'v' needs 3 coordinates, found " + std::to_string(count));
    // Some writers append a w or an RGB colour; both are parsed (to catch garbage) and ignored.
    if (count > 3) ignored_.add("extra values on 'v' lines (w or colour)", line_);
  }

  // `vt u [v [w]]`: w is dropped (2D textures), a missing v is 0.
  void read_texture_coordinate() {
    const int count = read_numbers(uv_, 2);
    if (count < 1) fail("'vt' needs at least 1 coordinate");
    if (count == 1) uv_.push_back(0.0);
  }

  void read_normal() {
    for (int k = 0; k < 3; ++k) {
      const std::string_view token = scanner_.next_on_line();
      if (token.empty()) fail("'vn' needs 3 coordinates, found " + std::to_string(k));
      normals_.push_back(number(token));
    }
  }

  // Resolves one OBJ index (1-based, or negative relative to the last of the `count` records read
  // so far). `what` names the record in messages.
  int index(std::string_view part, std::string_view corner, long long count, const char* what) const {
    long long value = 0;
    if (!parse_int64(part, value)) fail("malformed face corner '" + std::string(corner) + "'");
    if (value == 0) fail(std::string(what) + " index 0 in '" + std::string(corner) + "' (OBJ indices start at 1)");
    const long long resolved = value > 0 ? value - 1 : count + value;
    if (resolved < INT_MIN || resolved > INT_MAX)
      fail(std::string(what) + " index out of range in '" + std::string(corner) + "'");
    return static_cast<int>(resolved);
  }

  // Corners are v, v/vt, v//vn or v/vt/vn; a corner without vt or vn gets -1 there.
  void read_corner(std::string_view corner) {
    const std::size_t slash = corner.find('/');
    raw_.polygon_indices.push_back(index(corner.substr(0, slash), corner, static_cast<long long>(xyz_.size() / 3), "vertex"));
    int texture_index = -1, normal_index = -1;
    if (slash != std::string_view::npos) {
      const std::string_view rest = corner.substr(slash + 1);
      const std::size_t slash2 = rest.find('/');
      const std::string_view texture = rest.substr(0, slash2);
      if (texture.empty() && slash2 == std::string_view::npos) fail("malformed face corner '" + std::string(corner) + "'");
      if (!texture.empty()) texture_index = index(texture, corner, static_cast<long long>(uv_.size() / 2), "texture");
      if (slash2 != std::string_view::npos)
        normal_index = index(rest.substr(slash2 + 1), corner, static_cast<long long>(normals_.size() / 3), "normal");
    }
    raw_.corner_tc.push_back(texture_index);
    raw_.corner_n.push_back(normal_index);
  }

  // Keeps `corner` only if some corner has an index; notes indices outside the table's `rows`,
  // which triangulate reads as none.
  void finish_corners(std::vector<int>& corner, Eigen::Index rows, const char* what, const char* keyword) {
    int outside = 0, used = 0;
    for (const int i : corner) {
      used += i != -1;
      outside += i != -1 && (i < 0 || i >= rows);
    }
    if (used == 0) corner.clear();
    if (outside > 0)
      report_.notes.push_back(std::to_string(outside) + " " + what + " indices of 'f' corners outside the " +
                              std::to_string(rows) + " '" + keyword + "' lines: read as none");
  }

  void read_face() {
    for (std::string_view corner = scanner_.next_on_line(); !corner.empty(); corner = scanner_.next_on_line())
      read_corner(corner);
    if (raw_.polygon_indices.size() > static_cast<std::size_t>(INT_MAX)) fail("too many face corners");
    raw_.polygon_offsets.push_back(static_cast<int>(raw_.polygon_indices.size()));
  }

  const Source& source_;
  ReadReport& report_;
  TextScanner scanner_;
  RawMesh raw_;
  std::vector<double> xyz_;
  std::vector<double> uv_;
  std::vector<double> normals_;
  IgnoredNotes ignored_;
  int line_ = 0;
};

}  // namespace

RawMesh read_obj(const Source& source, ReadReport& report) { return ObjReader(source, report).read(); }

namespace {

template <class Table>
void append_records(const char* keyword, const Table& table, std::string& out) {
  for (Eigen::Index r = 0; r < table.rows(); ++r) {
    out += keyword;
    for (Eigen::Index k = 0; k < table.cols(); ++k) {
      out += ' ';
      append_number(out, table(r, k));
    }
    out += '\n';
  }
}

// One `f` line; a polygon gets vt (vn) indices only when every corner has one.
void append_face(const OutputPolygons& polygons, int p, std::string& out) {
  const int* tc = polygons.tc.data() + polygons.offsets[p];
  const int* normal = polygons.normal.data() + polygons.offsets[p];
  const int corners = polygons.corners(p);
  const bool with_tc = std::all_of(tc, tc + corners, [](int i) { return i >= 0; });
  const bool with_normal = std::all_of(normal, normal + corners, [](int i) { return i >= 0; });
  out += 'f';
  for (int c = 0; c < corners; ++c) {
    out += ' ';
    append_number(out, static_cast<long long>(polygons.vertex[polygons.offsets[p] + c]) + 1);
    if (with_tc || with_normal) out += '/';
    if (with_tc) append_number(out, static_cast<long long>(tc[c]) + 1);
    if (with_normal) {
      out += '/';
      append_number(out, static_cast<long long>(normal[c]) + 1);
    }
  }
  out += '\n';
}

}  // namespace

void write_obj(const Mesh& mesh, std::string& out, std::vector<std::string>& /*notes: OBJ holds it all*/) {
  out.reserve(static_cast<std::size_t>(mesh.V.rows() + mesh.TC.rows() + mesh.N.rows()) * 64 +
              static_cast<std::size_t>(mesh.F.rows()) * 24);
  append_records("v", mesh.V, out);
  if (mesh.FTC.rows() > 0) append_records("vt", mesh.TC, out);
  if (mesh.FN.rows() > 0) append_records("vn", mesh.N, out);
  const OutputPolygons polygons = output_polygons(mesh);
  for (int p = 0; p < polygons.size(); ++p) append_face(polygons, p, out);
}

}  // namespace fairsurf::io_detail
