// STL, ASCII and binary. STL stores every triangle with its own three float32 corners, so reading
// welds corners with exactly equal coordinates into shared vertices (a documented repair; vertex
// order is the order of first occurrence), and writing rounds coordinates to float32.
#include "io_formats.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <unordered_map>

namespace fairsurf::io_detail {
namespace {

using Corner = std::array<float, 3>;

struct CornerHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& key) const {
    std::size_t h = 0;
    for (const std::uint32_t k : key) h = (h ^ k) * 0x100000001b3ull + 0x9e3779b97f4a7c15ull;
    return h;
  }
};

// Merges corners with equal coordinates (bitwise, with -0 taken as +0) into shared vertices.
class Welder {
 public:
  explicit Welder(std::size_t expected_corners) { index_.reserve(expected_corners / 4); }

  void add(const Corner& c) {
    std::array<std::uint32_t, 3> key;
    for (int k = 0; k < 3; ++k) key[k] = std::bit_cast<std::uint32_t>(c[k] == 0.0f ? 0.0f : c[k]);
    const auto [it, inserted] = index_.try_emplace(key, static_cast<int>(xyz_.size() / 3));
    if (inserted) xyz_.insert(xyz_.end(), c.begin(), c.end());
    raw_.polygon_indices.push_back(it->second);
    ++corners_;
  }
  void end_polygon() { raw_.polygon_offsets.push_back(static_cast<int>(raw_.polygon_indices.size())); }

  RawMesh finish(ReadReport& report) {
    raw_.V = to_vertices(xyz_);
    report.notes.push_back("welded " + std::to_string(corners_) + " STL corners into " +
                           std::to_string(raw_.V.rows()) + " vertices by exact coordinate equality");
    return std::move(raw_);
  }

 private:
  std::unordered_map<std::array<std::uint32_t, 3>, int, CornerHash> index_;
  std::vector<double> xyz_;
  RawMesh raw_;
  long long corners_ = 0;
};

float load_float(const char* p) {
  unsigned char bytes[4];
  std::memcpy(bytes, p, 4);
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + 4);
  float value;
  std::memcpy(&value, bytes, 4);
  return value;
}

std::uint32_t load_uint32(const char* p) {
  unsigned char bytes[4];
  std::memcpy(bytes, p, 4);
  return std::uint32_t{bytes[0]} | std::uint32_t{bytes[1]} << 8 | std::uint32_t{bytes[2]} << 16 |
         std::uint32_t{bytes[3]} << 24;
}

constexpr std::size_t kHeaderBytes = 84;
constexpr std::size_t kTriangleBytes = 50;

RawMesh read_binary(const Source& source, ReadReport& report) {
  const std::string_view bytes = source.bytes;
  if (bytes.size() < kHeaderBytes)
    source.fail("unexpected end of file in the 84-byte binary STL header (" + std::to_string(bytes.size()) +
                " bytes)");
  const std::uint64_t count = load_uint32(bytes.data() + 80);
  const std::uint64_t present = (bytes.size() - kHeaderBytes) / kTriangleBytes;
  if (present < count)
    source.fail("unexpected end of file after " + std::to_string(present) + " of " + std::to_string(count) +
                " triangles");
  Welder welder(3 * count);
  for (std::uint64_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + kHeaderBytes + t * kTriangleBytes + 12;  // skip the normal
    for (int c = 0; c < 3; ++c)
      welder.add({load_float(record + 12 * c), load_float(record + 12 * c + 4), load_float(record + 12 * c + 8)});
    welder.end_polygon();
  }
  if (present > count)
    report.notes.push_back("ignored " + std::to_string(bytes.size() - kHeaderBytes - count * kTriangleBytes) +
                           " bytes after the last triangle");
  return welder.finish(report);
}

class AsciiStlReader {
 public:
  AsciiStlReader(const Source& source, ReadReport& report)
      : source_(source), report_(report), scanner_(source.bytes, 0, false), welder_(source.bytes.size() / 40) {}

  RawMesh read() {
    expect("solid");
    scanner_.skip_line();  // the solid's name
    for (;;) {
      const std::string_view token = next();
      if (token == "facet") {
        read_facet();
      } else if (token == "endsolid") {
        scanner_.skip_line();
        const std::string_view after = scanner_.next();
        if (after.empty()) break;
        if (after != "solid") unexpected("solid", after);  // files may hold several solids
        scanner_.skip_line();
      } else {
        unexpected("facet' or 'endsolid", token);
      }
    }
    return welder_.finish(report_);
  }

 private:
  std::string_view next() {
    const std::string_view token = scanner_.next();
    if (token.empty())
      source_.fail("unexpected end of file after " + std::to_string(facets_) + " facets (no 'endsolid')");
    return token;
  }
  [[noreturn]] void unexpected(const char* expected, std::string_view found) const {
    source_.fail("line " + std::to_string(source_.line_at(scanner_.position())) + ": expected '" + expected +
                 "', found '" + std::string(found) + "'");
  }
  void expect(const char* keyword) {
    const std::string_view token = next();
    if (token != keyword) unexpected(keyword, token);
  }
  float number() {
    const std::string_view token = next();
    float value = 0;
    if (!parse_float(token, value))
      source_.fail("line " + std::to_string(source_.line_at(scanner_.position())) + ": malformed number '" +
                   std::string(token) + "'");
    return value;
  }

  void read_facet() {
    expect("normal");
    for (int k = 0; k < 3; ++k) number();  // recomputed from the corners by whoever needs it
    expect("outer");
    expect("loop");
    for (std::string_view token = next(); token != "endloop"; token = next()) {
      if (token != "vertex") unexpected("vertex' or 'endloop", token);
      const float x = number(), y = number(), z = number();
      welder_.add({x, y, z});
    }
    welder_.end_polygon();
    expect("endfacet");
    ++facets_;
  }

  const Source& source_;
  ReadReport& report_;
  TextScanner scanner_;
  Welder welder_;
  int facets_ = 0;
};

Eigen::Vector3f unit_normal(const Mesh& mesh, Eigen::Index f) {
  const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0 ? Eigen::Vector3f((n / length).cast<float>()) : Eigen::Vector3f::Zero();
}

void put_float(std::string& out, float value) {
  unsigned char bytes[4];
  std::memcpy(bytes, &value, 4);
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + 4);
  out.append(reinterpret_cast<const char*>(bytes), 4);
}

void append_float(std::string& out, float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);  // shortest exact float
  out.append(buffer, result.ptr);
}

void write_binary(const Mesh& mesh, std::string& out) {
  std::string header = "fairsurf binary STL";  // must not start with "solid"
  header.resize(80, '\0');
  out += header;
  const auto count = static_cast<std::uint32_t>(mesh.F.rows());
  for (int k = 0; k < 4; ++k) out += static_cast<char>((count >> (8 * k)) & 0xff);
  out.reserve(out.size() + kTriangleBytes * count);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3f n = unit_normal(mesh, f);
    for (int k = 0; k < 3; ++k) put_float(out, n[k]);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) put_float(out, static_cast<float>(mesh.V(mesh.F(f, c), k)));
    out.append(2, '\0');  // attribute byte count
  }
}

void write_ascii(const Mesh& mesh, std::string& out) {
  const auto triple = [&](const char* keyword, auto value) {
    out += keyword;
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_float(out, static_cast<float>(value(k)));
    }
    out += '\n';
  };
  out += "solid fairsurf\n";
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3f n = unit_normal(mesh, f);
    triple("  facet normal", [&](int k) { return n[k]; });
    out += "    outer loop\n";
    for (int c = 0; c < 3; ++c) triple("      vertex", [&](int k) { return mesh.V(mesh.F(f, c), k); });
    out += "    endloop\n  endfacet\n";
  }
  out += "endsolid fairsurf\n";
}

}  // namespace

RawMesh read_stl(const Source& source, ReadReport& report) {
  // A binary file may also start with "solid"; its size (84 + 50 n) tells them apart.
  const std::string_view bytes = source.bytes;
  const bool exact_binary_size = bytes.size() >= kHeaderBytes &&
                                 bytes.size() == kHeaderBytes + kTriangleBytes * std::uint64_t{load_uint32(bytes.data() + 80)};
  TextScanner probe(bytes, 0, false);
  if (!exact_binary_size && probe.next() == "solid") return AsciiStlReader(source, report).read();
  return read_binary(source, report);
}

void write_stl(const Mesh& mesh, bool binary, std::string& out, std::vector<std::string>& notes) {
  if (binary) write_binary(mesh, out);
  else write_ascii(mesh, out);
  if (mesh.FTC.rows() > 0) notes.push_back("texture coordinates not written: STL has no place for them");
  if (mesh.FN.rows() > 0) notes.push_back("normals not written: STL stores one normal per triangle, its own");
  if (mesh.face_polygon.size() > 0) notes.push_back("polygons written as their triangles: STL stores triangles only");
}

}  // namespace fairsurf::io_detail
