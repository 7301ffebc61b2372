// Wavefront OBJ: `v` and `f` records are read; every other record is ignored with one note per kind.
#include "io_formats.h"

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
    ignored_.flush(report_.notes);
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

  void read_vertex() {
    int count = 0;
    for (std::string_view token = scanner_.next_on_line(); !token.empty(); token = scanner_.next_on_line()) {
      const double value = number(token);
      if (count < 3) xyz_.push_back(value);
      ++count;
    }
    if (count < 3) fail("'v' needs 3 coordinates, found " + std::to_string(count));
    // Some writers append a w or an RGB colour; both are parsed (to catch garbage) and ignored.
    if (count > 3) ignored_.add("extra values on 'v' lines (w or colour)", line_);
  }

  // Resolves one OBJ index (1-based, or negative relative to the last vertex read so far).
  int index(std::string_view part, std::string_view corner) const {
    long long value = 0;
    if (!parse_int64(part, value)) fail("malformed face corner '" + std::string(corner) + "'");
    if (value == 0) fail("vertex index 0 in '" + std::string(corner) + "' (OBJ indices start at 1)");
    const long long resolved = value > 0 ? value - 1 : static_cast<long long>(xyz_.size() / 3) + value;
    if (resolved < INT_MIN || resolved > INT_MAX) fail("vertex index out of range in '" + std::string(corner) + "'");
    return static_cast<int>(resolved);
  }

  // Corners are v, v/vt, v//vn or v/vt/vn; only v is kept.
  void read_corner(std::string_view corner) {
    const std::size_t slash = corner.find('/');
    raw_.polygon_indices.push_back(index(corner.substr(0, slash), corner));
    if (slash == std::string_view::npos) return;
    const std::string_view rest = corner.substr(slash + 1);
    const std::size_t slash2 = rest.find('/');
    const std::string_view texture = rest.substr(0, slash2);
    const std::string_view normal = slash2 == std::string_view::npos ? std::string_view() : rest.substr(slash2 + 1);
    long long unused = 0;
    const bool texture_ok = texture.empty() ? slash2 != std::string_view::npos : parse_int64(texture, unused);
    const bool normal_ok = slash2 == std::string_view::npos || parse_int64(normal, unused);
    if (!texture_ok || !normal_ok) fail("malformed face corner '" + std::string(corner) + "'");
    ignored_.add("texture/normal indices in 'f' corners", line_);
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
  IgnoredNotes ignored_;
  int line_ = 0;
};

}  // namespace

RawMesh read_obj(const Source& source, ReadReport& report) { return ObjReader(source, report).read(); }

void write_obj(const Mesh& mesh, std::string& out) {
  out.reserve(static_cast<std::size_t>(mesh.V.rows()) * 64 + static_cast<std::size_t>(mesh.F.rows()) * 24);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    out += 'v';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, mesh.V(v, k));
    }
    out += '\n';
  }
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, static_cast<long long>(mesh.F(f, k)) + 1);
    }
    out += '\n';
  }
}

}  // namespace fairsurf::io_detail
