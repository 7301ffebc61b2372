// Stanford PLY reading (io_ply_write.cpp writes): ascii, binary_little_endian and binary_big_endian. The `vertex` element gives
// positions (x, y, z), colours (uchar red, green, blue), normals (nx, ny, nz), texture coordinates
// (u, v or s, t or texture_u, texture_v) and extra scalars; the `face` element's
// vertex_indices (or vertex_index) list gives polygons; everything else is skipped. One templated
// reading loop per encoding keeps the binary path a plain sequence of bounded loads.
#include "io_formats.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <optional>
#include <utility>

namespace fairsurf::io_detail {
namespace {

enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

std::optional<Type> type_named(std::string_view name) {
  if (name == "char" || name == "int8") return Type::kInt8;
  if (name == "uchar" || name == "uint8") return Type::kUint8;
  if (name == "short" || name == "int16") return Type::kInt16;
  if (name == "ushort" || name == "uint16") return Type::kUint16;
  if (name == "int" || name == "int32") return Type::kInt32;
  if (name == "uint" || name == "uint32") return Type::kUint32;
  if (name == "float" || name == "float32") return Type::kFloat32;
  if (name == "double" || name == "float64") return Type::kFloat64;
  return std::nullopt;
}

std::size_t size_of(Type type) {
  switch (type) {
    case Type::kInt8: case Type::kUint8: return 1;
    case Type::kInt16: case Type::kUint16: return 2;
    case Type::kInt32: case Type::kUint32: case Type::kFloat32: return 4;
    case Type::kFloat64: return 8;
  }
  return 8;
}

bool is_integral(Type type) { return type != Type::kFloat32 && type != Type::kFloat64; }

struct Property {
  std::string name;
  Type type = Type::kFloat64;
  bool is_list = false;
  Type count_type = Type::kUint8;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;

  // Bytes one record needs at least: scalars, plus the count of each list (lists may be empty).
  std::size_t min_binary_bytes() const {
    std::size_t bytes = 0;
    for (const auto& p : properties) bytes += size_of(p.is_list ? p.count_type : p.type);
    return bytes;
  }
  // Characters one ASCII record needs at least: one digit and one separator per value.
  std::size_t min_ascii_bytes() const { return 2 * properties.size(); }
};

enum class Encoding { kAscii, kLittleEndian, kBigEndian };

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  std::size_t data_start = 0;
};

Header parse_header(const Source& source) {
  TextScanner scanner(source.bytes, 0, false);
  int line = 1;
  const auto fail = [&](const std::string& what) { source.fail("line " + std::to_string(line) + ": " + what); };
  if (scanner.next_on_line() != "ply") fail("not a PLY file (no 'ply' magic line)");
  Header header;
  bool has_format = false;
  for (scanner.skip_line(), ++line;; scanner.skip_line(), ++line) {
    if (scanner.remaining() == 0) source.fail("unexpected end of file in the header (no 'end_header' line)");
    const std::string_view keyword = scanner.next_on_line();
    if (keyword == "end_header") {
      scanner.skip_line();
      header.data_start = scanner.position();
      break;
    }
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      const std::string_view encoding = scanner.next_on_line();
      if (encoding == "ascii") header.encoding = Encoding::kAscii;
      else if (encoding == "binary_little_endian") header.encoding = Encoding::kLittleEndian;
      else if (encoding == "binary_big_endian") header.encoding = Encoding::kBigEndian;
      else fail("unknown format '" + std::string(encoding) + "'");
      has_format = true;
    } else if (keyword == "element") {
      Element element;
      element.name = std::string(scanner.next_on_line());
      const std::string_view count = scanner.next_on_line();
      if (element.name.empty() || !parse_int64(count, element.count) || element.count < 0 || element.count > INT_MAX)
        fail("malformed element line (expected 'element <name> <count>')");
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail("property before any element");
      Property property;
      std::string_view type = scanner.next_on_line();
      if (type == "list") {
        property.is_list = true;
        const auto count_type = type_named(scanner.next_on_line());
        if (!count_type || !is_integral(*count_type)) fail("list count type must be an integer type");
        property.count_type = *count_type;
        type = scanner.next_on_line();
      }
      const auto value_type = type_named(type);
      if (!value_type) fail("unknown property type '" + std::string(type) + "'");
      property.type = *value_type;
      property.name = std::string(scanner.next_on_line());
      if (property.name.empty()) fail("property without a name");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail("unexpected header line starting with '" + std::string(keyword) + "'");
    }
  }
  if (!has_format) source.fail("the header has no 'format' line");
  return header;
}

/// Thrown by cursors at the end of the data; the element loop turns it into a ParseError that
/// says how many records were complete.
struct UnexpectedEnd {};

class AsciiCursor {
 public:
  AsciiCursor(const Source& source, std::size_t start) : source_(source), scanner_(source.bytes, start, false) {}

  double scalar(Type type) {
    if (is_integral(type)) return static_cast<double>(integer(type));
    const std::string_view token = next();
    if (type == Type::kFloat32) {  // read as the float the file declares, like a binary file would be
      float value = 0;
      if (!parse_float(token, value)) malformed(token);
      return value;
    }
    double value = 0;
    if (!parse_double(token, value)) malformed(token);
    return value;
  }

  long long integer(Type type) {
    const std::string_view token = next();
    long long value = 0;
    if (!parse_int64(token, value) || !fits(value, type)) malformed(token);
    return value;
  }

  void skip(Type type, long long count) {
    for (long long i = 0; i < count; ++i) scalar(type);
  }

  std::size_t remaining() const { return scanner_.remaining(); }
  std::string where() const { return "line " + std::to_string(source_.line_at(scanner_.position())); }

  bool only_whitespace_left() { return scanner_.next().empty(); }

 private:
  std::string_view next() {
    const std::string_view token = scanner_.next();
    if (token.empty()) throw UnexpectedEnd{};
    return token;
  }
  static bool fits(long long value, Type type) {
    switch (type) {
      case Type::kInt8: return value >= INT8_MIN && value <= INT8_MAX;
      case Type::kUint8: return value >= 0 && value <= UINT8_MAX;
      case Type::kInt16: return value >= INT16_MIN && value <= INT16_MAX;
      case Type::kUint16: return value >= 0 && value <= UINT16_MAX;
      case Type::kInt32: return value >= INT32_MIN && value <= INT32_MAX;
      case Type::kUint32: return value >= 0 && value <= static_cast<long long>(UINT32_MAX);
      default: return false;
    }
  }
  [[noreturn]] void malformed(std::string_view token) const {
    source_.fail(where() + ": malformed value '" + std::string(token) + "'");
  }

  const Source& source_;
  TextScanner scanner_;
};

template <bool kSwap>
class BinaryCursor {
 public:
  BinaryCursor(const Source& source, std::size_t start)
      : begin_(source.bytes.data()), at_(begin_ + start), end_(begin_ + source.bytes.size()) {}

  double scalar(Type type) {
    switch (type) {
      case Type::kFloat64: return load<double>();
      case Type::kFloat32: return load<float>();
      default: return static_cast<double>(integer(type));
    }
  }

  long long integer(Type type) {
    switch (type) {
      case Type::kInt8: return load<std::int8_t>();
      case Type::kUint8: return load<std::uint8_t>();
      case Type::kInt16: return load<std::int16_t>();
      case Type::kUint16: return load<std::uint16_t>();
      case Type::kInt32: return load<std::int32_t>();
      case Type::kUint32: return load<std::uint32_t>();
      case Type::kFloat32:
      case Type::kFloat64: {
        // The header only admits integer types where integers are read; this keeps the cast defined.
        const double value = scalar(type);
        return std::abs(value) < 1e18 ? static_cast<long long>(value) : 0;
      }
    }
    return 0;
  }

  void skip(Type type, long long count) {
    if (count < 0 || static_cast<unsigned long long>(count) > remaining() / size_of(type)) throw UnexpectedEnd{};
    at_ += static_cast<std::size_t>(count) * size_of(type);
  }

  std::size_t remaining() const { return static_cast<std::size_t>(end_ - at_); }
  std::string where() const { return "byte offset " + std::to_string(at_ - begin_); }
  bool only_whitespace_left() { return at_ == end_; }

 private:
  template <typename T>
  T load() {
    if (remaining() < sizeof(T)) throw UnexpectedEnd{};
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, at_, sizeof(T));
    if constexpr (kSwap) std::reverse(bytes, bytes + sizeof(T));
    at_ += sizeof(T);
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  const char* begin_;
  const char* at_;
  const char* end_;
};

// What a vertex property becomes.
enum class Role { kX, kY, kZ, kRed, kGreen, kBlue, kU, kV, kNx, kNy, kNz, kScalar, kSkip };

// The names texture coordinates go by in PLY files (MeshLab, Blender, VCG write the first ones).
constexpr std::pair<const char*, const char*> kTextureNames[] = {
    {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};

bool has_scalar(const Element& element, std::string_view name) {
  return std::any_of(element.properties.begin(), element.properties.end(),
                     [&](const Property& p) { return p.name == name && !p.is_list; });
}

// The role of a vertex property named `name` among the texture and normal roles, kScalar if none.
Role attribute_role(const Element& element, const std::string& name) {
  for (const auto& [u, v] : kTextureNames)
    if (has_scalar(element, u) && has_scalar(element, v)) {
      if (name == u) return Role::kU;
      if (name == v) return Role::kV;
      break;
    }
  if (has_scalar(element, "nx") && has_scalar(element, "ny") && has_scalar(element, "nz")) {
    if (name == "nx") return Role::kNx;
    if (name == "ny") return Role::kNy;
    if (name == "nz") return Role::kNz;
  }
  return Role::kScalar;
}

struct VertexLayout {
  std::vector<Role> roles;
  std::vector<Eigen::VectorXd*> scalars;  // per property; null unless the role is kScalar
};

template <class Cursor>
class PlyReader {
 public:
  PlyReader(const Source& source, const Header& header, ReadReport& report)
      : source_(source), header_(header), report_(report), cursor_(source, header.data_start) {}

  RawMesh read() {
    bool has_vertices = false, has_faces = false;
    for (const Element& element : header_.elements) {
      int done = 0;
      try {
        if (element.name == "vertex") {
          if (std::exchange(has_vertices, true)) source_.fail("more than one 'vertex' element");
          read_vertices(element, done);
        } else if (element.name == "face") {
          if (std::exchange(has_faces, true)) source_.fail("more than one 'face' element");
          read_faces(element, done);
        } else {
          skip_element(element, done);
          report_.notes.push_back("skipped element '" + element.name + "' (" + std::to_string(element.count) +
                                  " records)");
        }
      } catch (const UnexpectedEnd&) {
        source_.fail("unexpected end of file after " + std::to_string(done) + " of " +
                     std::to_string(element.count) + " '" + element.name + "' elements");
      }
    }
    if (!has_vertices) source_.fail("no 'vertex' element");
    // Per-vertex values: every corner uses its vertex's row.
    if (raw_.TC.rows() > 0) raw_.corner_tc = raw_.polygon_indices;
    if (raw_.N.rows() > 0) raw_.corner_n = raw_.polygon_indices;
    if (!cursor_.only_whitespace_left()) report_.notes.push_back("ignored data after the last element");
    return std::move(raw_);
  }

 private:
  VertexLayout vertex_layout(const Element& element) {
    VertexLayout layout;
    const auto uchar_named = [&](const char* name) {
      return std::any_of(element.properties.begin(), element.properties.end(), [&](const Property& p) {
        return p.name == name && !p.is_list && p.type == Type::kUint8;
      });
    };
    const bool has_colors = uchar_named("red") && uchar_named("green") && uchar_named("blue");
    bool has_xyz[3] = {false, false, false};
    for (const Property& p : element.properties) {
      Role role = Role::kScalar;
      if (p.is_list) role = Role::kSkip;
      else if (p.name == "x") role = Role::kX;
      else if (p.name == "y") role = Role::kY;
      else if (p.name == "z") role = Role::kZ;
      else if (has_colors && p.name == "red") role = Role::kRed;
      else if (has_colors && p.name == "green") role = Role::kGreen;
      else if (has_colors && p.name == "blue") role = Role::kBlue;
      else role = attribute_role(element, p.name);
      if (role <= Role::kZ) has_xyz[static_cast<int>(role)] = true;
      if (role == Role::kSkip) report_.notes.push_back("skipped vertex list property '" + p.name + "'");
      layout.roles.push_back(role);
      layout.scalars.push_back(role == Role::kScalar ? &raw_.vertex_scalars[p.name] : nullptr);
    }
    for (int k = 0; k < 3; ++k)
      if (!has_xyz[k]) source_.fail(std::string("element 'vertex' has no scalar property '") + "xyz"[k] + "'");
    return layout;
  }

  std::size_t min_record_bytes(const Element& element) const {
    return header_.encoding == Encoding::kAscii ? element.min_ascii_bytes() : element.min_binary_bytes();
  }

  void read_vertices(const Element& element, int& done) {
    const VertexLayout layout = vertex_layout(element);
    // Never more rows than the remaining bytes can hold: a lying header cannot allocate gigabytes.
    const auto rows = static_cast<Eigen::Index>(
        safe_reserve(element.count, cursor_.remaining(), min_record_bytes(element)));
    raw_.V.resize(rows, 3);
    const auto has_role = [&](Role role) {
      return std::find(layout.roles.begin(), layout.roles.end(), role) != layout.roles.end();
    };
    if (has_role(Role::kRed)) raw_.vertex_colors.resize(rows, 3);
    if (has_role(Role::kU)) raw_.TC.resize(rows, 2);
    if (has_role(Role::kNx)) raw_.N.resize(rows, 3);
    for (Eigen::VectorXd* s : layout.scalars)
      if (s) s->resize(rows);
    const std::size_t n = element.properties.size();
    for (; done < element.count; ++done) {
      if (done >= raw_.V.rows()) throw UnexpectedEnd{};
      for (std::size_t p = 0; p < n; ++p) {
        const Property& property = element.properties[p];
        const Role role = layout.roles[p];
        if (role == Role::kSkip) {
          cursor_.skip(property.type, cursor_.integer(property.count_type));
        } else if (role <= Role::kZ) {
          raw_.V(done, static_cast<int>(role)) = cursor_.scalar(property.type);
        } else if (role == Role::kScalar) {
          (*layout.scalars[p])(done) = cursor_.scalar(property.type);
        } else if (role == Role::kU || role == Role::kV) {
          raw_.TC(done, static_cast<int>(role) - static_cast<int>(Role::kU)) = cursor_.scalar(property.type);
        } else if (role >= Role::kNx) {
          raw_.N(done, static_cast<int>(role) - static_cast<int>(Role::kNx)) = cursor_.scalar(property.type);
        } else {
          raw_.vertex_colors(done, static_cast<int>(role) - static_cast<int>(Role::kRed)) =
              static_cast<std::uint8_t>(cursor_.integer(property.type));
        }
      }
    }
  }

  const Property* index_list(const Element& element) const {
    for (const Property& p : element.properties)
      if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) return &p;
    return nullptr;
  }

  void read_faces(const Element& element, int& done) {
    const Property* indices = index_list(element);
    if (!indices) source_.fail("element 'face' has no 'vertex_indices' list property");
    if (!is_integral(indices->type)) source_.fail("'vertex_indices' must have an integer type");
    for (const Property& p : element.properties)
      if (&p != indices) report_.notes.push_back("skipped face property '" + p.name + "'");
    const std::size_t reserve = safe_reserve(element.count, cursor_.remaining(), min_record_bytes(element));
    raw_.polygon_offsets.reserve(reserve + 1);
    raw_.polygon_indices.reserve(3 * reserve);
    for (; done < element.count; ++done) {
      for (const Property& p : element.properties) {
        if (&p != indices) {
          skip_property(p);
          continue;
        }
        const long long corners = cursor_.integer(p.count_type);
        if (corners < 0)
          source_.fail("'face' element " + std::to_string(done) + ": negative list length (" + cursor_.where() + ")");
        for (long long k = 0; k < corners; ++k) {
          const long long index = cursor_.integer(p.type);
          if (index < INT_MIN || index > INT_MAX)
            source_.fail("'face' element " + std::to_string(done) + ": vertex index " + std::to_string(index) +
                         " out of range (" + cursor_.where() + ")");
          raw_.polygon_indices.push_back(static_cast<int>(index));
        }
      }
      if (raw_.polygon_indices.size() > static_cast<std::size_t>(INT_MAX)) source_.fail("too many face corners");
      raw_.polygon_offsets.push_back(static_cast<int>(raw_.polygon_indices.size()));
    }
  }

  void skip_property(const Property& p) {
    if (p.is_list) cursor_.skip(p.type, cursor_.integer(p.count_type));
    else cursor_.skip(p.type, 1);
  }

  void skip_element(const Element& element, int& done) {
    for (; done < element.count; ++done)
      for (const Property& p : element.properties) skip_property(p);
  }

  const Source& source_;
  const Header& header_;
  ReadReport& report_;
  Cursor cursor_;
  RawMesh raw_;
};

template <class Cursor>
RawMesh read_with(const Source& source, const Header& header, ReadReport& report) {
  return PlyReader<Cursor>(source, header, report).read();
}

}  // namespace

RawMesh read_ply(const Source& source, ReadReport& report) {
  const Header header = parse_header(source);
  constexpr bool kLittleHost = std::endian::native == std::endian::little;
  switch (header.encoding) {
    case Encoding::kAscii: return read_with<AsciiCursor>(source, header, report);
    case Encoding::kLittleEndian: return read_with<BinaryCursor<!kLittleHost>>(source, header, report);
    case Encoding::kBigEndian: return read_with<BinaryCursor<kLittleHost>>(source, header, report);
  }
  source.fail("unknown PLY encoding");
}

}  // namespace fairsurf::io_detail
