#include <fairsurf/mesh/errors.h>
#include <fairsurf/patch/patch_refinement.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace fairsurf {
namespace {

struct PatchTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PatchMesh = OpenMesh::TriMesh_ArrayKernelT<PatchTraits>;
using Vec = OpenMesh::Vec3d;

// OpenMesh reports failed face insertions on its error stream; the library never prints, so the
// stream is muted while the patch is built and the failure is thrown instead.
class MuteOpenMeshErrors {
 public:
  MuteOpenMeshErrors() : was_enabled_(::omerr().is_enabled()) { ::omerr().disable(); }
  ~MuteOpenMeshErrors() {
    if (was_enabled_) ::omerr().enable();
  }
  MuteOpenMeshErrors(const MuteOpenMeshErrors&) = delete;
  MuteOpenMeshErrors& operator=(const MuteOpenMeshErrors&) = delete;

 private:
  bool was_enabled_;
};

// A triangle with an angle above this (160°) is a sliver: its cotangent weights (cot 177° ≈ −19)
// make the ∆ of the fairing indefinite. A flip that removes one may turn a border triangle up to
// kSliverFlipDihedral (120°) against the mesh. Liepa's triangulation of a flat hole that meets the
// mesh at about a right angle keeps its largest dihedral low with such slivers along the border (a
// 120-edge hemisphere of data/: 91.4°, with 60 border triangles of 177°); the flips that remove them
// give 96–102°, the border faces' own tilt, and without them ∆³ blew the patch out through the cap.
constexpr double kSliverAngle = 160 * std::numbers::pi / 180;
constexpr double kSliverFlipDihedral = 120 * std::numbers::pi / 180;

double angle_between(const Vec& u, const Vec& v) { return std::atan2(OpenMesh::cross(u, v).norm(), OpenMesh::dot(u, v)); }

// The largest interior angle of the triangle (p, q, r).
double largest_angle(const Vec& p, const Vec& q, const Vec& r) {
  return std::max({angle_between(q - p, r - p), angle_between(r - q, p - q), angle_between(p - r, q - r)});
}

// The local patch: OpenMesh connectivity, its vertices' global indices and their scales σ.
class Refiner {
 public:
  Refiner(const Vertices& V, const Faces& F, const Faces& patch, const PatchRefinementOptions& options)
      : options_(options), num_input_vertices_(static_cast<int>(V.rows())) {
    build(V, patch);
    mesh_edges_between_patch_vertices(V, F);
    initial_scales();
  }

  void refine(RefinedPatch& report) {
    split_rounds(report);
    // Counted as a round: max_rounds = 0 leaves the triangulation as it is.
    if (const int added = report.rounds < options_.max_rounds ? add_vertices_where_they_fit() : 0; added > 0) {
      report.splits += added;
      ++report.rounds;
      flip_until_delaunay();
      split_rounds(report);
    }
    for (int sweep = 0; sweep < options_.relaxation_sweeps; ++sweep) {
      relax_tangentially();
      flip_until_delaunay();
    }
    report.flips = flips_;
  }

  void write(const Vertices& V, const Faces& F, RefinedPatch& out) const {
    const int added = static_cast<int>(mesh_.n_vertices()) - static_cast<int>(global_.size());
    out.V.resize(V.rows() + added, 3);
    out.V.topRows(V.rows()) = V;
    for (const auto vh : mesh_.vertices()) {
      const int g = global(vh.idx());
      const Vec& p = mesh_.point(vh);
      out.V.row(g) << p[0], p[1], p[2];
      if (!mesh_.is_boundary(vh)) out.free_vertices.push_back(g);
    }
    std::sort(out.free_vertices.begin(), out.free_vertices.end());
    out.F.resize(F.rows() + static_cast<int>(mesh_.n_faces()), 3);
    out.F.topRows(F.rows()) = F;
    out.first_patch_face = static_cast<int>(F.rows());
    for (const auto fh : mesh_.faces()) {
      int k = 0;
      for (const auto vh : mesh_.fv_range(fh)) out.F(out.first_patch_face + fh.idx(), k++) = global(vh.idx());
    }
  }

 private:
  int global(int local) const {
    return local < static_cast<int>(global_.size())
               ? global_[local]
               : num_input_vertices_ + local - static_cast<int>(global_.size());
  }

  void build(const Vertices& V, const Faces& patch) {
    std::vector<int> local(V.rows(), -1);
    std::unordered_set<long long> directed;
    MuteOpenMeshErrors mute;
    for (int f = 0; f < patch.rows(); ++f) {
      std::vector<PatchMesh::VertexHandle> corners;
      for (int k = 0; k < 3; ++k) {
        const int v = patch(f, k), w = patch(f, (k + 1) % 3);
        if (v < 0 || v >= V.rows())
          throw InvalidArgument("refine_patch: patch face " + std::to_string(f) + " has vertex index " +
                                std::to_string(v) + " outside [0, " + std::to_string(V.rows()) + ")");
        if (!directed.insert(static_cast<long long>(v) * V.rows() + w).second)
          throw InvalidMeshError("refine_patch: patch edge " + std::to_string(v) + "-" +
                                 std::to_string(w) + " is used twice in the same direction");
        if (local[v] < 0) {
          local[v] = static_cast<int>(global_.size());
          global_.push_back(v);
          mesh_.add_vertex(Vec(V(v, 0), V(v, 1), V(v, 2)));
        }
        corners.push_back(PatchMesh::VertexHandle(local[v]));
      }
      if (!mesh_.add_face(corners).is_valid())
        throw InvalidMeshError("refine_patch: patch face " + std::to_string(f) +
                               " makes the patch non-manifold");
    }
  }

  static long long undirected_key(int a, int b) {
    return (static_cast<long long>(std::min(a, b)) << 32) | static_cast<unsigned>(std::max(a, b));
  }

  // The edges of the mesh outside the patch between two patch vertices. A flip must not create
  // one: OpenMesh only sees the patch, and the edge would have four faces (a border vertex of a
  // hole can be joined to another by a mesh edge across the hole's neighbourhood).
  // Also keeps the unit normal of the mesh face on each directed such edge, for the dihedral angle
  // across the patch's border.
  void mesh_edges_between_patch_vertices(const Vertices& V, const Faces& F) {
    std::vector<int> local(num_input_vertices_, -1);
    for (int i = 0; i < static_cast<int>(global_.size()); ++i) local[global_[i]] = i;
    for (int f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = local[F(f, k)], b = local[F(f, (k + 1) % 3)];
        if (a < 0 || b < 0) continue;
        outside_edges_.insert(undirected_key(a, b));
        const Vec p0(V(F(f, 0), 0), V(F(f, 0), 1), V(F(f, 0), 2)), p1(V(F(f, 1), 0), V(F(f, 1), 1), V(F(f, 1), 2)),
            p2(V(F(f, 2), 0), V(F(f, 2), 1), V(F(f, 2), 2));
        outside_normals_[directed_key(a, b)] = OpenMesh::cross(p1 - p0, p2 - p0);
      }
  }

  static long long directed_key(int a, int b) { return (static_cast<long long>(a) << 32) | static_cast<unsigned>(b); }

  // Largest dihedral angle between the triangle (u, v, w) and the mesh faces across its edges (0 if
  // none of its edges is on the patch's border).
  double border_dihedral(int u, int v, int w) const {
    const Vec pu = mesh_.point(PatchMesh::VertexHandle(u)), pv = mesh_.point(PatchMesh::VertexHandle(v)),
              pw = mesh_.point(PatchMesh::VertexHandle(w));
    const Vec normal = OpenMesh::cross(pv - pu, pw - pu);
    double angle = 0.0;
    for (const auto& [a, b] : {std::pair{u, v}, std::pair{v, w}, std::pair{w, u}}) {
      const auto it = outside_normals_.find(directed_key(b, a));
      if (it != outside_normals_.end()) angle = std::max(angle, angle_between(normal, it->second));
    }
    return angle;
  }

  // σ of border vertices from their border edges; of interior vertices from all their edges.
  void initial_scales() {
    const int n = static_cast<int>(global_.size());
    scale_.assign(n, options_.target_edge_length);
    if (options_.target_edge_length > 0.0) return;
    for (const auto vh : mesh_.vertices()) {
      const bool border = mesh_.is_boundary(vh);
      double sum = 0.0;
      int count = 0;
      for (const auto heh : mesh_.voh_range(vh))
        if (!border || mesh_.is_boundary(mesh_.edge_handle(heh)))
          sum += mesh_.calc_edge_length(heh), ++count;
      scale_[vh.idx()] = sum / std::max(1, count);
    }
  }

  void split_rounds(RefinedPatch& report) {
    for (; report.rounds < options_.max_rounds; ++report.rounds) {
      const int splits = split_round();
      if (splits == 0) break;
      report.splits += splits;
      flip_until_delaunay();
    }
  }

  struct BareDisk {
    std::vector<std::pair<int, int>> border;  // (from, to) halfedges in face order
    PatchMesh::EdgeHandle longest;            // its longest inner edge
    double area = 0.0;
  };

  // A hole that Liepa's rounds left without an interior vertex where the surrounding mesh would have
  // one (a one-ring hole: the vertex in its middle is missing) gets one at the midpoint of its longest
  // inner edge. Liepa's split test misses such a vertex where the triangulation is a fan of long thin
  // triangles, whose centroids lie near a corner, and a patch without an interior vertex stays flat:
  // no fairing can bend it. A disk of n border and i interior vertices has n − 2 + 2i triangles; the
  // disk's area A over the mean area ā of the mesh faces across its border counts the triangles the
  // mesh would put there, and the vertex goes in when that count is nearer n than n − 2:
  // A ≥ (n − 1) ā. A missing face or two stays flat, and so does a thin slit. Each disk of the patch
  // (holes filled jointly) is weighed on its own; the split rounds that follow may add more.
  int add_vertices_where_they_fit() {
    int added = 0;
    for (const BareDisk& disk : disks_without_interior_vertices()) {
      if (!vertex_fits(disk)) continue;
      const auto h = mesh_.halfedge_handle(disk.longest, 0);
      const int a = mesh_.from_vertex_handle(h).idx(), b = mesh_.to_vertex_handle(h).idx();
      const auto middle =
          mesh_.add_vertex((mesh_.point(PatchMesh::VertexHandle(a)) + mesh_.point(PatchMesh::VertexHandle(b))) / 2);
      scale_.push_back((scale_[a] + scale_[b]) / 2);
      mesh_.split(disk.longest, middle);
      ++added;
    }
    return added;
  }

  // Every connected piece of the patch that is a disk with no interior vertex: n border edges,
  // n vertices, n − 2 triangles.
  std::vector<BareDisk> disks_without_interior_vertices() const {
    std::vector<char> seen(mesh_.n_faces(), 0);
    std::vector<BareDisk> disks;
    for (const auto start : mesh_.faces()) {
      if (seen[start.idx()]) continue;
      BareDisk disk;
      std::unordered_set<int> vertices;
      int faces = 0;
      bool interior_vertex = false;
      double longest = 0.0;
      std::vector<PatchMesh::FaceHandle> stack{start};
      seen[start.idx()] = 1;
      while (!stack.empty()) {
        const auto fh = stack.back();
        stack.pop_back();
        ++faces;
        auto fv = mesh_.cfv_iter(fh);
        const Vec p0 = mesh_.point(*fv), p1 = mesh_.point(*++fv), p2 = mesh_.point(*++fv);
        disk.area += OpenMesh::cross(p1 - p0, p2 - p0).norm() / 2;
        for (const auto heh : mesh_.fh_range(fh)) {
          const auto from = mesh_.from_vertex_handle(heh);
          vertices.insert(from.idx());
          interior_vertex = interior_vertex || !mesh_.is_boundary(from);
          const auto across = mesh_.opposite_halfedge_handle(heh);
          if (mesh_.is_boundary(across)) {
            disk.border.emplace_back(from.idx(), mesh_.to_vertex_handle(heh).idx());
            continue;
          }
          if (const double length = mesh_.calc_edge_length(heh); length > longest)
            longest = length, disk.longest = mesh_.edge_handle(heh);
          const auto nb = mesh_.face_handle(across);
          if (!seen[nb.idx()]) seen[nb.idx()] = 1, stack.push_back(nb);
        }
      }
      const int n = static_cast<int>(disk.border.size());
      if (!interior_vertex && n >= 4 && static_cast<int>(vertices.size()) == n && faces == n - 2)
        disks.push_back(std::move(disk));
    }
    return disks;
  }

  // Whether the disk holds the area of the triangles a vertex in it would make.
  bool vertex_fits(const BareDisk& disk) const {
    const int n = static_cast<int>(disk.border.size());
    double mesh_area = 0.0;
    for (const auto& [a, b] : disk.border) {
      const auto across = outside_normals_.find(directed_key(b, a));
      if (across == outside_normals_.end()) return false;
      mesh_area += across->second.norm() / 2 / n;
    }
    return disk.area >= (n - 1) * mesh_area;
  }

  int split_round() {
    const int num_faces = static_cast<int>(mesh_.n_faces());
    int splits = 0;
    for (int f = 0; f < num_faces; ++f) {
      const PatchMesh::FaceHandle fh(f);
      Vec c(0, 0, 0);
      double sigma_c = 0.0;
      for (const auto vh : mesh_.fv_range(fh)) c += mesh_.point(vh) / 3.0, sigma_c += scale_[vh.idx()] / 3.0;
      bool split = true;
      for (const auto vh : mesh_.fv_range(fh)) {
        const double d = options_.density_factor * (c - mesh_.point(vh)).norm();
        split = split && d > sigma_c && d > scale_[vh.idx()];
      }
      if (!split) continue;
      const auto vh = mesh_.add_vertex(c);
      scale_.push_back(sigma_c);
      mesh_.split(fh, vh);
      ++splits;
      std::vector<PatchMesh::EdgeHandle> around;
      for (const auto heh : mesh_.voh_range(vh)) around.push_back(mesh_.edge_handle(mesh_.next_halfedge_handle(heh)));
      for (const auto eh : around) flip_if_not_delaunay(eh);
    }
    return splits;
  }

  // Flips the edge a-b of the triangles (a, b, c) and (b, a, d) to c-d when the angles at c and d
  // sum to more than π, unless the flip would turn a triangle over.
  bool flip_if_not_delaunay(PatchMesh::EdgeHandle eh) {
    if (mesh_.is_boundary(eh)) return false;
    const auto h0 = mesh_.halfedge_handle(eh, 0), h1 = mesh_.halfedge_handle(eh, 1);
    const Vec a = mesh_.point(mesh_.from_vertex_handle(h0)), b = mesh_.point(mesh_.to_vertex_handle(h0));
    const Vec c = mesh_.point(mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h0)));
    const Vec d = mesh_.point(mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h1)));
    if (angle_between(a - c, b - c) + angle_between(a - d, b - d) <= std::numbers::pi + 1e-10) return false;
    const Vec old_normal = OpenMesh::cross(b - a, c - a) + OpenMesh::cross(a - b, d - b);
    if (OpenMesh::dot(OpenMesh::cross(a - c, d - c), old_normal) <= 0.0 ||
        OpenMesh::dot(OpenMesh::cross(b - d, c - d), old_normal) <= 0.0)
      return false;
    const int ai = mesh_.from_vertex_handle(h0).idx(), bi = mesh_.to_vertex_handle(h0).idx();
    const int ci = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h0)).idx();
    const int di = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h1)).idx();
    if (outside_edges_.contains(undirected_key(ci, di))) return false;
    // Nor may it fold a triangle against the mesh across the border beyond a right angle and beyond
    // what the two triangles had (a Delaunay flip on a curved patch can turn a border triangle
    // over; the flow then starts from a crease at the border) — unless it removes a sliver, which
    // may go to kSliverFlipDihedral.
    const double folded = std::max(border_dihedral(ai, di, ci), border_dihedral(di, bi, ci));
    const double before = std::max(border_dihedral(ai, bi, ci), border_dihedral(bi, ai, di));
    if (folded > std::max(std::numbers::pi / 2, before)) {
      const bool removes_sliver = std::max(largest_angle(a, b, c), largest_angle(b, a, d)) > kSliverAngle;
      if (!removes_sliver || folded > std::max(kSliverFlipDihedral, before)) return false;
    }
    if (!mesh_.is_flip_ok(eh)) return false;  // c-d is already an edge; checked last, it walks a fan
    mesh_.flip(eh);
    ++flips_;
    return true;
  }

  // Flips until every interior edge is Delaunay: a work list seeded with every edge, to which the
  // four outer edges of each flipped quadrilateral return, so each round costs O(#E + flips).
  // The cap guards against cycling on strongly curved (non-planar) patches.
  void flip_until_delaunay() {
    std::vector<PatchMesh::EdgeHandle> work(mesh_.edges().begin(), mesh_.edges().end());
    std::vector<char> queued(mesh_.n_edges(), 1);
    const long long cap = 100LL * static_cast<long long>(mesh_.n_edges());
    for (long long step = 0; !work.empty() && step < cap; ++step) {
      const auto eh = work.back();
      work.pop_back();
      queued[eh.idx()] = 0;
      if (!flip_if_not_delaunay(eh)) continue;
      const auto h = mesh_.halfedge_handle(eh, 0);
      for (const auto side : {mesh_.next_halfedge_handle(h), mesh_.prev_halfedge_handle(h),
                              mesh_.next_halfedge_handle(mesh_.opposite_halfedge_handle(h)),
                              mesh_.prev_halfedge_handle(mesh_.opposite_halfedge_handle(h))}) {
        const auto e = mesh_.edge_handle(side);
        if (!queued[e.idx()]) queued[e.idx()] = 1, work.push_back(e);
      }
    }
  }

  void relax_tangentially() {
    std::vector<Vec> moved(mesh_.n_vertices());
    for (const auto vh : mesh_.vertices()) {
      moved[vh.idx()] = mesh_.point(vh);
      if (mesh_.is_boundary(vh)) continue;
      Vec centroid(0, 0, 0), normal(0, 0, 0);
      int valence = 0;
      for (const auto nb : mesh_.vv_range(vh)) centroid += mesh_.point(nb), ++valence;
      for (const auto fh : mesh_.vf_range(vh)) {
        auto fv = mesh_.cfv_iter(fh);
        const Vec p0 = mesh_.point(*fv), p1 = mesh_.point(*++fv), p2 = mesh_.point(*++fv);
        normal += OpenMesh::cross(p1 - p0, p2 - p0);
      }
      Vec step = centroid / valence - mesh_.point(vh);
      if (normal.norm() > 0.0) step -= OpenMesh::dot(step, normal) / normal.sqrnorm() * normal;
      moved[vh.idx()] += step;
    }
    for (const auto vh : mesh_.vertices()) mesh_.set_point(vh, moved[vh.idx()]);
  }

  PatchRefinementOptions options_;
  int num_input_vertices_;
  PatchMesh mesh_;
  std::vector<int> global_;     // global index of each input patch vertex (local order)
  std::vector<double> scale_;   // σ per local vertex
  std::unordered_set<long long> outside_edges_;  // mesh edges between input patch vertices (local)
  std::unordered_map<long long, Vec> outside_normals_;  // per directed such edge: its mesh face's normal
  int flips_ = 0;
};

}  // namespace

RefinedPatch refine_patch(const Vertices& V, const Faces& F, const Faces& patch,
                          const PatchRefinementOptions& options) {
  if (!(options.density_factor > 0.0) || options.target_edge_length < 0.0 || options.max_rounds < 0 ||
      options.relaxation_sweeps < 0)
    throw InvalidArgument("refine_patch: density_factor must be positive and target_edge_length, "
                          "max_rounds and relaxation_sweeps non-negative");
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (F(f, k) < 0 || F(f, k) >= V.rows())
        throw InvalidArgument("refine_patch: mesh face " + std::to_string(f) + " has vertex index " +
                              std::to_string(F(f, k)) + " outside [0, " + std::to_string(V.rows()) + ")");
  Refiner refiner(V, F, patch, options);
  RefinedPatch out;
  refiner.refine(out);
  refiner.write(V, F, out);
  return out;
}

}  // namespace fairsurf
