// Private to the io module: the per-format readers and writers that io.cpp dispatches to, and the
// small scanning helpers they share. Readers work on the whole file in memory, so every count in a
// header can be checked against the bytes that are really there before anything is allocated.
#pragma once

#include <fairsurf/io/io.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fairsurf::io_detail {

/// The file being read: its name for messages and its bytes.
struct Source {
  std::string name;
  std::string_view bytes;

  /// Throws ParseError "read_raw: <name>: <what>".
  [[noreturn]] void fail(const std::string& what) const;
  /// 1-based line number of byte offset `pos`; counted only when a message needs it.
  int line_at(std::size_t pos) const;
};

/// Whole-token number parsing (a leading '+' is accepted; "nan" and "inf" are values).
bool parse_double(std::string_view token, double& value);
bool parse_float(std::string_view token, float& value);
bool parse_int64(std::string_view token, long long& value);

/// Whitespace-separated tokens of a text file, aware of line ends so that readers can ignore the
/// rest of a record's line (OFF colours, STL solid names). Optionally treats '#' as a comment start.
class TextScanner {
 public:
  TextScanner(std::string_view text, std::size_t pos, bool hash_comments)
      : text_(text), pos_(pos), hash_comments_(hash_comments) {}
  /// The next token, crossing line ends; empty at the end of the text.
  std::string_view next();
  /// The next token on the current line; empty at the end of the line.
  std::string_view next_on_line();
  /// Moves past the end of the current line.
  void skip_line();
  /// Byte offset of the next unread character.
  std::size_t position() const { return pos_; }
  /// Bytes left to read.
  std::size_t remaining() const { return text_.size() - pos_; }

 private:
  void skip_blanks(bool cross_lines);
  std::string_view text_;
  std::size_t pos_;
  bool hash_comments_;
};

/// A growing #V by 3 coordinate buffer, turned into Vertices at the end.
Vertices to_vertices(const std::vector<double>& xyz);

/// A count read from a header, capped by what `available` bytes can hold at `min_bytes_each` bytes
/// per record: the amount that is safe to reserve.
std::size_t safe_reserve(long long count, std::size_t available, std::size_t min_bytes_each);

/// Adds "ignored N <what>" style notes, one per distinct kind, in first-seen order.
class IgnoredNotes {
 public:
  void add(const std::string& kind, int line);
  void flush(std::vector<std::string>& notes) const;

 private:
  struct Entry {
    std::string kind;
    int count;
    int first_line;
  };
  std::vector<Entry> entries_;
};

RawMesh read_obj(const Source& source, ReadReport& report);
RawMesh read_off(const Source& source, ReadReport& report);
RawMesh read_ply(const Source& source, ReadReport& report);
RawMesh read_stl(const Source& source, ReadReport& report);

/// Appends `value` with `digits` significant digits ("nan", "inf" for non-finite values).
void append_number(std::string& out, double value, int digits = 17);
void append_number(std::string& out, long long value);

/// The faces a writer gives back: the mesh's polygons (face_polygon) where they are intact, its
/// triangles elsewhere. Corner c of polygon p is offsets[p] + c in the three corner arrays.
struct OutputPolygons {
  std::vector<int> offsets{0};
  std::vector<int> vertex;  ///< vertex index of each corner
  std::vector<int> tc;      ///< row of TC of each corner, -1: none (all -1 without FTC)
  std::vector<int> normal;  ///< row of N of each corner, -1: none (all -1 without FN)

  int size() const { return static_cast<int>(offsets.size()) - 1; }
  int corners(int p) const { return offsets[p + 1] - offsets[p]; }
};

/// Rebuilds the polygons of face_polygon: a run of consecutive triangles that holds every triangle
/// of its polygon and forms its fan (or the fan reversed, as orienting flips it), with the same
/// texture/normal index wherever two of them share a corner, becomes one polygon again; any other
/// triangle stays a triangle.
OutputPolygons output_polygons(const Mesh& mesh);

/// Appends one ASCII line "n i j k ..." per polygon: the face lists of OFF and ASCII PLY are the same.
void append_polygon_lines(const OutputPolygons& polygons, std::string& out);

using Table = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
/// One value per vertex from per-corner indices FX into a table of `rows` rows: `of_vertex[v]` is
/// the row every corner of v uses (-1 for a vertex of no face). False when a corner of a face has
/// none, or when two corners of a vertex use rows with different values (a seam, a crease).
bool per_vertex_rows(const Mesh& mesh, const Faces& FX, const Eigen::Ref<const Table>& table,
                     std::vector<int>& of_vertex);

void write_obj(const Mesh& mesh, std::string& out, std::vector<std::string>& notes);
void write_off(const Mesh& mesh, std::string& out, std::vector<std::string>& notes);
void write_ply(const Mesh& mesh, bool binary, std::string& out, std::vector<std::string>& notes);
void write_stl(const Mesh& mesh, bool binary, std::string& out, std::vector<std::string>& notes);

}  // namespace fairsurf::io_detail
