#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_attributes.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fairsurf {
namespace {

void pad_rows(Faces& FX, Eigen::Index rows) {
  if (FX.rows() == 0 || FX.rows() >= rows) return;
  const Eigen::Index old = FX.rows();
  FX.conservativeResize(rows, 3);
  FX.bottomRows(rows - old).setConstant(-1);
}

// For each vertex, the lowest vertex at the same position (bitwise, so NaN positions are equal to
// themselves): faces are matched by positions, which repair never changes, not by indices, which
// merging and splitting do.
std::vector<int> position_classes(const Vertices& V) {
  struct Hash {
    std::size_t operator()(const std::array<std::uint64_t, 3>& a) const {
      return a[0] * 0x9E3779B97F4A7C15ULL ^ (a[1] + 0x632BE59BD9B4E019ULL) * 31 ^ a[2];
    }
  };
  std::unordered_map<std::array<std::uint64_t, 3>, int, Hash> first;
  std::vector<int> cls(static_cast<std::size_t>(V.rows()));
  for (int v = 0; v < V.rows(); ++v) {
    std::array<std::uint64_t, 3> key;
    for (int k = 0; k < 3; ++k) {
      const double x = V(v, k) == 0.0 ? 0.0 : V(v, k);  // -0 and +0 are one position
      std::memcpy(&key[k], &x, sizeof x);
    }
    cls[v] = first.emplace(key, v).first->second;
  }
  return cls;
}

using FaceKey = std::array<int, 3>;

FaceKey sorted_key(int a, int b, int c) {
  FaceKey key{a, b, c};
  std::sort(key.begin(), key.end());
  return key;
}

// The face of `from` each face of `to` takes its values from (-1: none), and which corner of it
// each corner matches.
struct FaceMatch {
  std::vector<int> face;
  std::vector<std::array<int, 3>> corner;
};

FaceMatch match_faces(const Mesh& from, std::span<const int> vertex_source, const Mesh& to) {
  const std::vector<int> cls = position_classes(from.V);
  const auto class_of_to = [&](int v) {
    const int s = v >= 0 && v < static_cast<int>(vertex_source.size()) ? vertex_source[v] : -1;
    return s >= 0 && s < static_cast<int>(cls.size()) ? cls[s] : -1;
  };
  std::vector<std::pair<FaceKey, int>> keyed;
  keyed.reserve(static_cast<std::size_t>(from.num_faces()));
  for (int g = 0; g < from.num_faces(); ++g) {
    const auto c = [&](int k) { return from.F(g, k) >= 0 && from.F(g, k) < from.num_vertices() ? cls[from.F(g, k)] : -1; };
    keyed.push_back({sorted_key(c(0), c(1), c(2)), g});
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<char> used(keyed.size(), 0);
  FaceMatch match{std::vector<int>(static_cast<std::size_t>(to.num_faces()), -1),
                  std::vector<std::array<int, 3>>(static_cast<std::size_t>(to.num_faces()), {-1, -1, -1})};
  for (int f = 0; f < to.num_faces(); ++f) {
    const std::array<int, 3> c{class_of_to(to.F(f, 0)), class_of_to(to.F(f, 1)), class_of_to(to.F(f, 2))};
    const FaceKey key = sorted_key(c[0], c[1], c[2]);
    auto it = std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(key, -1));
    while (it != keyed.end() && it->first == key && used[it - keyed.begin()]) ++it;
    if (it == keyed.end() || it->first != key || key[0] < 0) continue;
    used[it - keyed.begin()] = 1;
    const int g = it->second;
    match.face[f] = g;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        if (cls[from.F(g, l)] == c[k]) {
          match.corner[f][k] = l;
          break;
        }
  }
  return match;
}

Faces carried(const Faces& FX, const FaceMatch& match) {
  Faces out(static_cast<Eigen::Index>(match.face.size()), 3);
  for (std::size_t f = 0; f < match.face.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = match.face[f], l = match.corner[f][k];
      out(static_cast<Eigen::Index>(f), k) = g >= 0 && l >= 0 ? FX(g, l) : -1;
    }
  return out;
}

// Each polygon of `from` keeps its number in `to` only if every one of its triangles was carried.
Eigen::VectorXi carried_polygons(const Eigen::VectorXi& face_polygon, const FaceMatch& match) {
  std::unordered_map<int, int> lost;  // polygon -> triangles of it not carried
  for (Eigen::Index g = 0; g < face_polygon.size(); ++g) ++lost[face_polygon[g]];
  for (const int g : match.face)
    if (g >= 0) --lost[face_polygon[g]];
  Eigen::VectorXi out(static_cast<Eigen::Index>(match.face.size()));
  for (std::size_t f = 0; f < match.face.size(); ++f) {
    const int g = match.face[f];
    out[static_cast<Eigen::Index>(f)] = g >= 0 && lost[face_polygon[g]] == 0 ? face_polygon[g] : -1;
  }
  return out;
}

Faces shifted(const Faces& FX, Eigen::Index faces, Eigen::Index offset) {
  if (FX.rows() == 0) return Faces::Constant(faces, 3, -1);
  return FX.unaryExpr([&](int i) { return i < 0 ? -1 : static_cast<int>(i + offset); });
}

template <class Table>
void join_tables(const Table& a, const Table& b, Table& out) {
  out.resize(a.rows() + b.rows(), a.cols());
  out.topRows(a.rows()) = a;
  out.bottomRows(b.rows()) = b;
}

}  // namespace

bool has_corner_attributes(const Mesh& mesh) {
  return mesh.FTC.rows() > 0 || mesh.FN.rows() > 0 || mesh.face_polygon.size() > 0;
}

int pad_face_attributes(Mesh& mesh) {
  if (!has_corner_attributes(mesh)) return 0;
  const Eigen::Index rows = mesh.F.rows();
  const Eigen::Index old = std::max({mesh.FTC.rows(), mesh.FN.rows(), mesh.face_polygon.size()});
  pad_rows(mesh.FTC, rows);
  pad_rows(mesh.FN, rows);
  if (mesh.face_polygon.size() > 0 && mesh.face_polygon.size() < rows) {
    mesh.face_polygon.conservativeResize(rows);
    mesh.face_polygon.tail(rows - old).setConstant(-1);
  }
  return static_cast<int>(rows - old);
}

void carry_face_attributes(const Mesh& from, std::span<const int> vertex_source, Mesh& to) {
  if (!has_corner_attributes(from)) return;
  const FaceMatch match = match_faces(from, vertex_source, to);
  if (from.FTC.rows() == from.num_faces() && from.FTC.rows() > 0) {
    to.TC = from.TC;
    to.FTC = carried(from.FTC, match);
  }
  if (from.FN.rows() == from.num_faces() && from.FN.rows() > 0) {
    to.N = from.N;
    to.FN = carried(from.FN, match);
  }
  if (from.face_polygon.size() == from.num_faces() && from.face_polygon.size() > 0)
    to.face_polygon = carried_polygons(from.face_polygon, match);
}

void concatenate_attributes(const Mesh& first, const Mesh& second, Mesh& out) {
  const Eigen::Index f1 = first.F.rows(), f2 = second.F.rows();
  if (first.FTC.rows() > 0 || second.FTC.rows() > 0) {
    join_tables(first.TC, second.TC, out.TC);
    out.FTC.resize(f1 + f2, 3);
    out.FTC << shifted(first.FTC, f1, 0), shifted(second.FTC, f2, first.TC.rows());
  }
  if (first.FN.rows() > 0 || second.FN.rows() > 0) {
    join_tables(first.N, second.N, out.N);
    out.FN.resize(f1 + f2, 3);
    out.FN << shifted(first.FN, f1, 0), shifted(second.FN, f2, first.N.rows());
  }
  if (first.face_polygon.size() > 0 || second.face_polygon.size() > 0) {
    const int offset = first.face_polygon.size() > 0 ? first.face_polygon.maxCoeff() + 1 : 0;
    out.face_polygon = Eigen::VectorXi::Constant(f1 + f2, -1);
    if (first.face_polygon.size() > 0) out.face_polygon.head(f1) = first.face_polygon;
    if (second.face_polygon.size() > 0)
      out.face_polygon.tail(f2) = second.face_polygon.unaryExpr([&](int p) { return p < 0 ? -1 : p + offset; });
  }
}

int refresh_moved_normals(Mesh& mesh, const Vertices& before) {
  if (mesh.FN.rows() == 0) return 0;
  if (before.rows() > mesh.V.rows() || mesh.FN.rows() != mesh.F.rows())
    throw InvalidArgument("refresh_moved_normals: the mesh and its earlier positions do not match");
  const auto moved = [&](int v) { return v >= before.rows() || mesh.V.row(v) != before.row(v); };
  std::vector<char> stale(static_cast<std::size_t>(mesh.N.rows()), 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.FN(f, k) >= 0 && moved(mesh.F(f, k))) stale[mesh.FN(f, k)] = 1;
  Vertices sum = Vertices::Zero(mesh.N.rows(), 3);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::RowVector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::RowVector3d area_normal = (b - a).cross(c - a);  // twice the area, along the normal
    for (int k = 0; k < 3; ++k)
      if (mesh.FN(f, k) >= 0 && stale[mesh.FN(f, k)]) sum.row(mesh.FN(f, k)) += area_normal;
  }
  int recomputed = 0;
  for (Eigen::Index r = 0; r < mesh.N.rows(); ++r) {
    const double length = sum.row(r).norm();
    if (!stale[r] || !(length > 0)) continue;
    mesh.N.row(r) = sum.row(r) / length;
    ++recomputed;
  }
  return recomputed;
}

}  // namespace fairsurf
