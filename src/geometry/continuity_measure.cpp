#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fairsurf {
namespace {

// The part of the mesh the fits at the border vertices see. A fit reaches its vertex's 2-ring and no
// farther (quadratic_fit.h), so the faces among the vertices within 2 rings of the border hold every
// neighbourhood they take: the connectivity and the fits cost in proportion to the border, and only
// flat passes over the mesh's arrays remain in proportion to the mesh (each hole of a joint group of
// hundreds had two connectivities derived over the whole group's neighbourhood).
struct NearBorder {
  std::vector<int> vertices;  ///< the mesh's vertices within 2 rings of the border, ascending
  Vertices V;                 ///< their positions
  Faces F;                    ///< the faces among them, in the mesh's order, over local indices
  std::vector<char> inside;   ///< per face of F: it touches a free vertex
  std::vector<int> border;    ///< the border vertices, local
};

NearBorder near_border(const Vertices& V, const Faces& F, const Topology& topo, const std::vector<int>& border,
                       const std::vector<char>& inside) {
  NearBorder near;
  near.vertices = k_ring(topo, border, 2);
  std::vector<int> local(V.rows(), -1);
  near.V.resize(static_cast<Eigen::Index>(near.vertices.size()), 3);
  for (std::size_t i = 0; i < near.vertices.size(); ++i) {
    local[near.vertices[i]] = static_cast<int>(i);
    near.V.row(static_cast<Eigen::Index>(i)) = V.row(near.vertices[i]);
  }
  std::vector<Eigen::Index> faces;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (local[F(f, 0)] >= 0 && local[F(f, 1)] >= 0 && local[F(f, 2)] >= 0) faces.push_back(f);
  near.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (int k = 0; k < 3; ++k) near.F(static_cast<Eigen::Index>(i), k) = local[F(faces[i], k)];
    near.inside.push_back(inside[faces[i]]);
  }
  for (int v : border) near.border.push_back(local[v]);
  return near;
}

// Fitted normals and mean curvatures at the border vertices on the faces of one side only (those
// touching a free vertex, or the others), whose connectivity derives from the mesh's.
SurfaceGeometry one_sided_geometry(const NearBorder& near, const Topology& mesh_topo, bool inside,
                                   std::vector<FitStatus>& status) {
  Faces part(std::count(near.inside.begin(), near.inside.end(), static_cast<char>(inside)), 3);
  for (Eigen::Index f = 0, row = 0; f < near.F.rows(); ++f)
    if (near.inside[f] == static_cast<char>(inside)) part.row(row++) = near.F.row(f);
  const Topology topo = derive_topology(mesh_topo, part, near.vertices);
  const QuadraticFits fits = fit_quadratics(near.V, part, topo, {}, near.border);
  status = fits.status;
  return compute_geometry(fits, near.V);
}

bool usable(FitStatus s) { return s == FitStatus::kOk || s == FitStatus::kIllConditioned; }

}  // namespace

ContinuityMeasure measure_continuity(const Vertices& V, const Faces& F, std::span<const int> free_vertices,
                                     std::span<const int> at) {
  return measure_continuity(V, F, build_topology(F, static_cast<int>(V.rows())), free_vertices, at);
}

ContinuityMeasure measure_continuity(const Vertices& V, const Faces& F, const Topology& topo,
                                     std::span<const int> free_vertices, std::span<const int> at) {
  if (topo.num_vertices != V.rows() || topo.num_faces != F.rows())
    throw InvalidArgument("measure_continuity: the topology was built for another mesh");
  std::vector<char> is_free(V.rows(), 0), inside(F.rows(), 0);
  for (int v : free_vertices) is_free[v] = 1;
  std::vector<char> border(V.rows(), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const bool touches = is_free[F(f, 0)] || is_free[F(f, 1)] || is_free[F(f, 2)];
    inside[f] = touches;
    if (touches)
      for (int k = 0; k < 3; ++k)
        if (!is_free[F(f, k)]) border[F(f, k)] = 1;
  }
  if (!at.empty()) {
    std::vector<char> listed(V.rows(), 0);
    for (int v : at) {
      if (v < 0 || v >= V.rows())
        throw InvalidArgument("measure_continuity: vertex " + std::to_string(v) + " is out of range");
      listed[v] = 1;
    }
    for (Eigen::Index v = 0; v < V.rows(); ++v) border[v] = border[v] && listed[v];
  }
  std::vector<int> border_vertices;
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    if (border[v]) border_vertices.push_back(static_cast<int>(v));

  const NearBorder near = near_border(V, F, topo, border_vertices, inside);
  std::vector<FitStatus> in_status, out_status;
  const SurfaceGeometry in = one_sided_geometry(near, topo, true, in_status);
  const SurfaceGeometry out = one_sided_geometry(near, topo, false, out_status);
  ContinuityMeasure m;
  for (int v : near.border) {
    if (!usable(in_status[v]) || !usable(out_status[v])) continue;
    const double cosine = std::clamp(in.normal.row(v).dot(out.normal.row(v)), -1.0, 1.0);
    const double angle = std::acos(cosine), jump = std::abs(in.H[v] - out.H[v]);
    ++m.border_vertices;
    m.max_normal_angle = std::max(m.max_normal_angle, angle);
    m.mean_normal_angle += angle;
    m.max_mean_curvature_jump = std::max(m.max_mean_curvature_jump, jump);
    m.mean_mean_curvature_jump += jump;
  }
  if (m.border_vertices > 0) {
    m.mean_normal_angle /= m.border_vertices;
    m.mean_mean_curvature_jump /= m.border_vertices;
  }
  return m;
}

}  // namespace fairsurf
