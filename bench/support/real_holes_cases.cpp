#include "real_holes_cases.h"

#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <optional>
#include <span>

namespace fairsurf::bench {
namespace {

constexpr int kMaxBlendLoop = 200;  // border edges; larger loops make the default run too slow

// A clean closed mesh and the ball centres of docs/fill.md (cases/real_holes.md's first).
struct MeshCase {
  std::string name, file;
  std::vector<Eigen::Vector3d> centres;  // nearest vertices are used; more are added by rule
};

std::vector<MeshCase> mesh_cases() {
  return {{"spot", "spot.obj",
           {{0.112515, -0.451919, 0.0935688}, {0.312594, 0.674309, -0.341185}, {-0.178799, 0.187723, 0.48375}}},
          {"blub", "blub.obj",
           {{0.00697216, -0.181279, -1.03702}, {-0.565203, -0.333718, 0.0970017}, {0.176282, 0.148983, -0.699856}}},
          {"bunny", "stanford_bunny_remesh_closed.obj", {{-0.417303, 0.45242, 0.224485}}},
          {"airplane", "airplane.obj", {}},
          {"torus", "torus.obj", {}},
          // A raw scan: irregular triangles, slivers among them, and the scanner's own noise.
          {"hammer", "hammer_rawscan.obj", {{0.09738, 0.250714, -2.971089}}}};
}

int nearest_vertex(const Mesh& mesh, const Eigen::Vector3d& p) {
  int best = 0;
  for (int v = 1; v < mesh.num_vertices(); ++v)
    if ((mesh.V.row(v).transpose() - p).squaredNorm() < (mesh.V.row(best).transpose() - p).squaredNorm())
      best = v;
  return best;
}

// The vertex farthest along `direction`.
int extreme_vertex(const Mesh& mesh, const Eigen::Vector3d& direction) {
  int best = 0;
  for (int v = 1; v < mesh.num_vertices(); ++v)
    if (mesh.V.row(v).dot(direction) > mesh.V.row(best).dot(direction)) best = v;
  return best;
}

// The given centres, then the vertices farthest along three fixed skew directions, until there are
// three (--quick: one).
std::vector<int> centre_vertices(const MeshCase& c, const Mesh& mesh, bool quick) {
  const std::size_t wanted = quick ? 1 : 3;
  const Eigen::Vector3d directions[] = {{1, 0.3, 0.1}, {-0.2, 1, 0.5}, {0.3, -0.6, 1}};
  std::vector<int> centres;
  for (const auto& p : c.centres)
    if (centres.size() < wanted) centres.push_back(nearest_vertex(mesh, p));
  for (int k = 0; centres.size() < wanted; ++k) centres.push_back(extreme_vertex(mesh, directions[k].normalized()));
  return centres;
}

Loaded loaded(const MeshCase& c, Mesh mesh, bool quick) {
  const double h = mean_edge_length(mesh);
  std::vector<int> centres = centre_vertices(c, mesh, quick);
  GridSurfaceDistance smooth(butterfly_refined(mesh, kSmoothLevels), h / 2);
  return {c.name, std::move(mesh), h, std::move(centres), std::move(smooth)};
}

}  // namespace

namespace {

// The bundled cases whose file name contains `filter` (all if empty) and whose file is present; a
// missing one is skipped with a printed note.
std::vector<std::pair<MeshCase, std::filesystem::path>> bundled_cases(const std::string& filter) {
  std::vector<std::pair<MeshCase, std::filesystem::path>> out;
  for (const MeshCase& c : mesh_cases()) {
    if (!filter.empty() && c.file.find(filter) == std::string::npos) continue;
    const std::filesystem::path path = std::filesystem::path(FAIRSURF_DATA_DIR) / c.file;
    if (std::filesystem::exists(path))
      out.emplace_back(c, path);
    else
      std::printf("%s: not found in %s, skipped\n", c.file.c_str(), FAIRSURF_DATA_DIR);
  }
  return out;
}

}  // namespace

std::vector<Loaded> load_meshes(const std::string& filter, bool quick) {
  std::vector<Loaded> out;
  for (const auto& [c, path] : bundled_cases(filter)) out.push_back(loaded(c, read_mesh(path), quick));
  return out;
}

std::vector<ClosedMesh> read_bundled_meshes(const std::string& filter) {
  std::vector<ClosedMesh> out;
  for (const auto& [c, path] : bundled_cases(filter)) {
    Mesh mesh = read_mesh(path);
    const double h = mean_edge_length(mesh);
    out.push_back({c.name, std::move(mesh), h});
  }
  return out;
}

ClosedMesh read_closed_mesh(const std::filesystem::path& path) {
  Mesh mesh = read_mesh(path);
  if (mesh.num_faces() == 0) throw InvalidArgument(path.string() + ": no faces");
  const std::size_t loops = loops_of(mesh).size();
  if (loops > 0)
    throw InvalidArgument(path.string() + ": has " + std::to_string(loops) + " boundary loop" +
                          (loops > 1 ? "s" : "") + "; the protocol cuts holes out of a closed mesh (close it first, "
                          "for example with fairsurf fill)");
  const double h = mean_edge_length(mesh);
  return {path.stem().string(), std::move(mesh), h};
}

Loaded load_mesh_file(const std::filesystem::path& path, bool quick) {
  ClosedMesh closed = read_closed_mesh(path);
  return loaded({closed.name, path.string(), {}}, std::move(closed.mesh), quick);
}

DistanceStats measure(const Truth& truth, const Vertices& V, const std::vector<int>& rows, double h) {
  DistanceStats stats = distance_stats(truth.faceted, V, rows, h);
  double sum = 0;
  for (int v : rows) sum += truth.smooth(V.row(v).transpose()) / h;
  if (!rows.empty()) stats.smooth_mean = sum / static_cast<double>(rows.size());
  return stats;
}

double removed_mean(const Truth& truth, const Mesh& filled, double h) {
  if (truth.removed.rows() == 0) return std::numeric_limits<double>::quiet_NaN();
  const SurfaceDistance distance(filled, truth.centre);
  double sum = 0;
  for (int i = 0; i < truth.removed.rows(); ++i) sum += distance(truth.removed.row(i).transpose());
  return sum / static_cast<double>(truth.removed.rows()) / h;
}

namespace {

// The vertices of m sorted by their coordinate `axis`.
std::vector<int> sorted_along(const Mesh& mesh, int axis) {
  std::vector<int> order(mesh.num_vertices());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return mesh.V(a, axis) < mesh.V(b, axis); });
  return order;
}

// The plane through the vertex at quantile `q` of `order` (sorted_along `axis`), where its slab leaves
// two loops of at most kMaxBlendLoop edges.
std::optional<Slab> slab_at(const Loaded& m, const std::vector<int>& order, int axis, double q) {
  const int vertex = order[static_cast<std::size_t>(q * (order.size() - 1))];
  const CutMesh cut = cut_slab(m.mesh, vertex, Eigen::Vector3d::Unit(axis), 2 * m.h);
  const auto loops = loops_of(cut.mesh);
  if (loops.size() == 2 && std::max(loops[0].size(), loops[1].size()) <= kMaxBlendLoop) return Slab{vertex, axis};
  return std::nullopt;
}

constexpr double kSlabQuantiles[] = {0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9, 0.95};
constexpr double kMoreSlabQuantiles[] = {0.27, 0.42, 0.58, 0.73};

}  // namespace

std::vector<Slab> blend_slabs(const Loaded& m, std::size_t wanted) {
  std::vector<Slab> slabs;
  for (int axis = 0; axis < 3 && slabs.size() < wanted; ++axis) {
    const std::vector<int> order = sorted_along(m.mesh, axis);
    for (double q : kSlabQuantiles)
      if (const std::optional<Slab> slab = slab_at(m, order, axis, q)) {
        slabs.push_back(*slab);
        break;  // one plane per axis
      }
  }
  return slabs;
}

std::vector<Slab> every_blend_slab(const Loaded& m) {
  std::vector<Slab> slabs;
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<int> order = sorted_along(m.mesh, axis);
    for (const auto& quantiles : {std::span<const double>(kSlabQuantiles), std::span<const double>(kMoreSlabQuantiles)})
      for (double q : quantiles)
        if (const std::optional<Slab> slab = slab_at(m, order, axis, q)) slabs.push_back(*slab);
  }
  return slabs;
}

}  // namespace fairsurf::bench
