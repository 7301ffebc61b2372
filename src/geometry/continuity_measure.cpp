#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace fairsurf {
namespace {

// Fitted normals and mean curvatures at `vertices` on the faces of one side only. The side keeps
// every vertex (`all`: each its own parent index), so its connectivity derives from the mesh's.
SurfaceGeometry one_sided_geometry(const Vertices& V, const Faces& F, const Topology& mesh_topo,
                                   const std::vector<int>& all, const std::vector<char>& side,
                                   const std::vector<int>& vertices, std::vector<FitStatus>& status) {
  Faces part(std::count(side.begin(), side.end(), 1), 3);
  for (Eigen::Index f = 0, row = 0; f < F.rows(); ++f)
    if (side[f]) part.row(row++) = F.row(f);
  const Topology topo = derive_topology(mesh_topo, part, all);
  const QuadraticFits fits = fit_quadratics(V, part, topo, {}, vertices);
  status = fits.status;
  return compute_geometry(fits, V);
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
  std::vector<char> is_free(V.rows(), 0), inside(F.rows(), 0), outside(F.rows(), 0);
  for (int v : free_vertices) is_free[v] = 1;
  std::vector<char> border(V.rows(), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const bool touches = is_free[F(f, 0)] || is_free[F(f, 1)] || is_free[F(f, 2)];
    (touches ? inside : outside)[f] = 1;
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

  std::vector<int> all(V.rows());
  std::iota(all.begin(), all.end(), 0);
  std::vector<FitStatus> in_status, out_status;
  const SurfaceGeometry in = one_sided_geometry(V, F, topo, all, inside, border_vertices, in_status);
  const SurfaceGeometry out = one_sided_geometry(V, F, topo, all, outside, border_vertices, out_status);
  ContinuityMeasure m;
  for (int v : border_vertices) {
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
