// Mesh I/O entry points: format dispatch by extension, triangulation of polygon soups, and atomic
// writes (temporary file beside the target, then rename).
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>

#include "io_formats.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>
#include <utility>

namespace fairsurf {
namespace {

enum class Format { kObj, kOff, kPly, kStl };

Format format_of(const std::filesystem::path& path, const char* function) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") return Format::kObj;
  if (ext == ".off") return Format::kOff;
  if (ext == ".ply") return Format::kPly;
  if (ext == ".stl") return Format::kStl;
  throw IoError(std::string(function) + ": " + path.string() + ": unknown extension '" +
                path.extension().string() + "' (supported: .obj, .off, .ply, .stl)");
}

std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw IoError("read_raw: " + path.string() + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("read_raw: " + path.string() + ": cannot open (" + std::strerror(errno) + ")");
  std::string bytes;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < 0) throw IoError("read_raw: " + path.string() + ": cannot determine the file size");
  bytes.resize(static_cast<std::size_t>(size));
  in.read(bytes.data(), size);
  if (in.gcount() != size) throw IoError("read_raw: " + path.string() + ": read failed");
  return bytes;
}

std::string error_text(int error) { return std::strerror(error); }

// Owns the temporary file until it has been renamed onto the target; removes it otherwise.
class TemporaryFile {
 public:
  TemporaryFile(const std::filesystem::path& target, const std::string& caller) : caller_(caller) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
      // Built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string here.
      std::string name(".");
      name.append(target.filename().string()).append(".tmp.").append(std::to_string(::getpid()));
      name.append(".").append(std::to_string(counter++));
      path_ = dir / name;
      // 0666 lets the process umask decide the permissions, as for any newly created file.
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ < 0 && errno != EEXIST) break;
    }
    if (fd_ < 0)
      throw IoError(caller_ + ": " + target.string() + ": cannot create a temporary file in '" +
                    dir.string() + "' (" + error_text(errno) + ")");
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(path_.c_str());
  }

  /// Writes everything, flushes it to disk and renames the file onto `target`.
  void commit(const std::string& bytes, const std::filesystem::path& target) {
    const auto fail = [&](const char* step) {
      throw IoError(caller_ + ": " + target.string() + ": " + step + " failed (" + error_text(errno) + ")");
    };
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) fail("write");
      done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd_) != 0) fail("fsync");
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("close");
    if (::rename(path_.c_str(), target.c_str()) != 0) fail("rename");
    committed_ = true;
  }

 private:
  std::string caller_;
  std::filesystem::path path_;
  int fd_ = -1;
  bool committed_ = false;
};

void check_writable(const Mesh& mesh) {
  const auto n = mesh.V.rows();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.F(f, k) < 0 || mesh.F(f, k) >= n)
        throw InvalidArgument("write_mesh: face " + std::to_string(f) + " has vertex index " +
                              std::to_string(mesh.F(f, k)) + " outside [0, " + std::to_string(n) + ")");
  for (const auto& [name, values] : mesh.vertex_scalars)
    if (values.size() != n)
      throw InvalidArgument("write_mesh: vertex scalar '" + name + "' has " + std::to_string(values.size()) +
                            " values for " + std::to_string(n) + " vertices");
  if (mesh.vertex_colors.rows() != 0 && mesh.vertex_colors.rows() != n)
    throw InvalidArgument("write_mesh: " + std::to_string(mesh.vertex_colors.rows()) + " vertex colours for " +
                          std::to_string(n) + " vertices");
}

// FTC and FN: empty or one row per face, each index a row of its table or -1; face_polygon: empty
// or one entry per face.
void check_corner_attributes(const Mesh& mesh) {
  const auto check = [&](const Faces& FX, Eigen::Index rows, const char* name, const char* table) {
    if (FX.rows() == 0) return;
    if (FX.rows() != mesh.F.rows())
      throw InvalidArgument(std::string("write_mesh: ") + name + " has " + std::to_string(FX.rows()) +
                            " rows for " + std::to_string(mesh.F.rows()) + " faces");
    for (Eigen::Index f = 0; f < FX.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (FX(f, k) < -1 || FX(f, k) >= rows)
          throw InvalidArgument(std::string("write_mesh: ") + name + " row " + std::to_string(f) + " has index " +
                                std::to_string(FX(f, k)) + " outside [-1, " + std::to_string(rows) + ") of " + table);
  };
  check(mesh.FTC, mesh.TC.rows(), "FTC", "TC");
  check(mesh.FN, mesh.N.rows(), "FN", "N");
  if (mesh.face_polygon.size() != 0 && mesh.face_polygon.size() != mesh.F.rows())
    throw InvalidArgument("write_mesh: face_polygon has " + std::to_string(mesh.face_polygon.size()) +
                          " entries for " + std::to_string(mesh.F.rows()) + " faces");
}

}  // namespace

RawMesh read_raw(const std::filesystem::path& path, ReadReport* report) {
  const Format format = format_of(path, "read_raw");
  const std::string bytes = read_file(path);
  const io_detail::Source source{path.string(), bytes};
  ReadReport local;
  ReadReport& out = report ? *report : local;
  switch (format) {
    case Format::kObj: return io_detail::read_obj(source, out);
    case Format::kOff: return io_detail::read_off(source, out);
    case Format::kPly: return io_detail::read_ply(source, out);
    case Format::kStl: return io_detail::read_stl(source, out);
  }
  throw IoError("read_raw: " + path.string() + ": unsupported format");
}

namespace {

// Checks the polygons of `raw` and counts the triangles their fans make; notes the fanned ones.
std::size_t count_fan_triangles(const RawMesh& raw, ReadReport* report, bool& has_polygons) {
  const std::size_t polygons = raw.polygon_offsets.size() - 1;
  std::size_t triangles = 0;
  int fanned = 0;
  for (std::size_t p = 0; p < polygons; ++p) {
    const int corners = raw.polygon_offsets[p + 1] - raw.polygon_offsets[p];
    if (corners < 3)
      throw ParseError("triangulate: polygon " + std::to_string(p) + " has " + std::to_string(corners) +
                       (corners == 1 ? " corner" : " corners") + " (at least 3 needed)");
    triangles += static_cast<std::size_t>(corners - 2);
    fanned += corners > 3;
  }
  has_polygons = fanned > 0;
  if (report && fanned > 0) {
    const int added = static_cast<int>(triangles - polygons);
    report->polygons_triangulated += fanned;
    report->triangles_added += added;
    report->notes.push_back("triangulated " + std::to_string(fanned) + " polygons with more than 3 corners "
                            "into fans (" + std::to_string(added) + " extra triangles)");
  }
  return triangles;
}

// Fans the per-corner array `corner` (vertex, texture or normal indices) like the polygons of `raw`;
// entries outside [0, table_rows) become -1 unless table_rows < 0 (vertex indices stay unchecked).
Faces fan(const RawMesh& raw, const std::vector<int>& corner, std::size_t triangles, Eigen::Index table_rows) {
  const auto checked = [&](int i) { return table_rows < 0 || (i >= 0 && i < table_rows) ? i : -1; };
  Faces out(static_cast<Eigen::Index>(triangles), 3);
  Eigen::Index f = 0;
  for (std::size_t p = 0; p + 1 < raw.polygon_offsets.size(); ++p) {
    const int* c = corner.data() + raw.polygon_offsets[p];
    const int corners = raw.polygon_offsets[p + 1] - raw.polygon_offsets[p];
    for (int k = 1; k + 1 < corners; ++k) out.row(f++) << checked(c[0]), checked(c[k]), checked(c[k + 1]);
  }
  return out;
}

// Everything of `mesh` that triangulate derives from the polygons: F, FTC, FN, face_polygon.
void fan_polygons(const RawMesh& raw, ReadReport* report, Mesh& mesh) {
  bool has_polygons = false;
  const std::size_t triangles = count_fan_triangles(raw, report, has_polygons);
  mesh.F = fan(raw, raw.polygon_indices, triangles, -1);
  if (raw.corner_tc.size() == raw.polygon_indices.size() && !raw.corner_tc.empty())
    mesh.FTC = fan(raw, raw.corner_tc, triangles, raw.TC.rows());
  if (raw.corner_n.size() == raw.polygon_indices.size() && !raw.corner_n.empty())
    mesh.FN = fan(raw, raw.corner_n, triangles, raw.N.rows());
  if (!has_polygons) return;
  mesh.face_polygon.resize(static_cast<Eigen::Index>(triangles));
  Eigen::Index f = 0;
  for (std::size_t p = 0; p + 1 < raw.polygon_offsets.size(); ++p)
    for (int k = raw.polygon_offsets[p] + 2; k < raw.polygon_offsets[p + 1]; ++k)
      mesh.face_polygon[f++] = static_cast<int>(p);
}

}  // namespace

Mesh triangulate(const RawMesh& raw, ReadReport* report) {
  Mesh mesh;
  fan_polygons(raw, report, mesh);
  mesh.V = raw.V;
  mesh.vertex_scalars = raw.vertex_scalars;
  mesh.vertex_colors = raw.vertex_colors;
  if (mesh.FTC.rows() > 0) mesh.TC = raw.TC;
  if (mesh.FN.rows() > 0) mesh.N = raw.N;
  return mesh;
}

Mesh triangulate(RawMesh&& raw, ReadReport* report) {
  Mesh mesh;
  fan_polygons(raw, report, mesh);
  mesh.V = std::move(raw.V);
  mesh.vertex_scalars = std::move(raw.vertex_scalars);
  mesh.vertex_colors = std::move(raw.vertex_colors);
  if (mesh.FTC.rows() > 0) mesh.TC = std::move(raw.TC);
  if (mesh.FN.rows() > 0) mesh.N = std::move(raw.N);
  return mesh;
}

Mesh read_mesh(const std::filesystem::path& path, ReadReport* report) {
  return triangulate(read_raw(path, report), report);
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options,
                WriteReport* report) {
  const Format format = format_of(path, "write_mesh");
  check_writable(mesh);
  check_corner_attributes(mesh);
  std::string bytes;
  std::vector<std::string> notes;
  switch (format) {
    case Format::kObj: io_detail::write_obj(mesh, bytes, notes); break;
    case Format::kOff: io_detail::write_off(mesh, bytes, notes); break;
    case Format::kPly: io_detail::write_ply(mesh, options.binary, bytes, notes); break;
    case Format::kStl: io_detail::write_stl(mesh, options.binary, bytes, notes); break;
  }
  write_file_atomically(path, bytes, "write_mesh");
  if (report) report->notes.insert(report->notes.end(), notes.begin(), notes.end());
}

void write_file_atomically(const std::filesystem::path& path, const std::string& bytes,
                           const std::string& caller) {
  TemporaryFile temporary(path, caller);
  temporary.commit(bytes, path);
}

}  // namespace fairsurf
