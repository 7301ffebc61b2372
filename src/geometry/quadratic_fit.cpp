#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/mesh/errors.h>

#include "parallel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace fairsurf {
namespace {

using Vector5d = Eigen::Matrix<double, 5, 1>;
using Matrix5d = Eigen::Matrix<double, 5, 5>;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Frame {
  Eigen::Vector3d normal, e1, e2;
  bool valid = false;
};

// Working storage for one vertex's fit, reused from vertex to vertex by one thread, so that fitting
// allocates nothing once the largest neighbourhood has been seen and every gathered quantity is
// computed once.
struct FitScratch {
  std::vector<Eigen::Vector3d> face_normals;  // (b − a) × (c − a) of the faces incident to i
  std::vector<Eigen::Vector3d> offsets;       // x_j − x_i for j ∈ N(i), in N(i)'s order
  std::vector<Eigen::Vector2d> uv;            // (u_j, v_j), unscaled
  // w_j b_j: scaled design rows b_j = (u/s, v/s, u²/s², uv/s², v²/s²) times w_j = s²/r_j²
  std::vector<Vector5d> weighted_rows;
};

// Unnormalized normal of face f: twice its area times its unit normal.
Eigen::Vector3d face_cross(int f, const Vertices& V, const Faces& F) {
  const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
  return (b - a).cross(c - a);
}

// Reads what vertex i's fit needs from V: its incident faces' normals and its neighbours' offsets.
void gather(int i, const Vertices& V, const Faces& F, std::span<const int> incident,
            std::span<const int> neighbours, FitScratch& scratch) {
  scratch.face_normals.clear();
  for (int f : incident) scratch.face_normals.push_back(face_cross(f, V, F));
  const Eigen::Vector3d xi = V.row(i);
  scratch.offsets.clear();
  for (int j : neighbours) scratch.offsets.push_back(V.row(j).transpose() - xi);
}

// N0 from the incident faces (area-weighted: unnormalized cross products), e1 from the first
// neighbour whose edge has a non-negligible tangential part.
Frame local_frame(const FitScratch& scratch) {
  Frame frame;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double total = 0.0;
  for (const Eigen::Vector3d& cross : scratch.face_normals) {
    sum += cross;
    total += cross.norm();
  }
  const double norm = sum.norm();
  if (!(norm > 1e-12 * total)) return frame;
  frame.normal = sum / norm;
  for (const Eigen::Vector3d& d : scratch.offsets) {
    const Eigen::Vector3d p = d - d.dot(frame.normal) * frame.normal;
    if (p.norm() > 1e-8 * d.norm()) {
      frame.e1 = p.normalized();
      frame.e2 = frame.normal.cross(frame.e1);
      frame.valid = true;
      return frame;
    }
  }
  return frame;
}

// Inverse of a symmetric positive definite 5 × 5 matrix by Cholesky, M = LLᵀ, M⁻¹ = L⁻ᵀL⁻¹; false
// if M is not numerically positive definite. Written out because Eigen's generic triangular solvers
// dominate the cost at this size.
bool cholesky_inverse(const Matrix5d& M, Matrix5d& inverse) {
  Matrix5d L = Matrix5d::Zero();
  for (int j = 0; j < 5; ++j) {
    double d = M(j, j);
    for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
    if (!(d > 0.0)) return false;
    L(j, j) = std::sqrt(d);
    for (int i = j + 1; i < 5; ++i) {
      double v = M(i, j);
      for (int k = 0; k < j; ++k) v -= L(i, k) * L(j, k);
      L(i, j) = v / L(j, j);
    }
  }
  Matrix5d Linv = Matrix5d::Zero();  // lower triangular
  for (int j = 0; j < 5; ++j) {
    Linv(j, j) = 1.0 / L(j, j);
    for (int i = j + 1; i < 5; ++i) {
      double v = 0.0;
      for (int k = j; k < i; ++k) v -= L(i, k) * Linv(k, j);
      Linv(i, j) = v / L(i, i);
    }
  }
  inverse.noalias() = Linv.transpose() * Linv;
  return true;
}

struct LocalSystem {
  Matrix5d inverse;  // M⁻¹ of the scaled normal matrix
  double inv_s = 0.0;
  double condition = kInfinity;
  bool singular = true;
};

// Scaled weighted normal matrix M = Σ w b bᵀ, its inverse and the condition number
// sqrt(‖M‖₁‖M⁻¹‖₁) of the scaled least-squares problem; leaves the weighted design rows w_j b_j
// in `scratch`. Column scaling keeps M's condition near that of the geometry (≈ 10–100 on good
// meshes), so the normal equations lose nothing that matters, and a fixed-size 5 × 5 Cholesky is
// several times cheaper than an eigen-decomposition or QR.
void assemble_system(const Frame& frame, double singular_tolerance, FitScratch& scratch,
                     LocalSystem& system) {
  double sum_r2 = 0.0;
  scratch.uv.clear();
  for (const Eigen::Vector3d& d : scratch.offsets) {
    const double u = d.dot(frame.e1), v = d.dot(frame.e2);
    scratch.uv.emplace_back(u, v);
    sum_r2 += u * u + v * v;
  }
  system.singular = true;
  system.condition = kInfinity;
  if (!(sum_r2 > 0.0)) return;
  system.inv_s = 1.0 / std::sqrt(sum_r2 / static_cast<double>(scratch.offsets.size()));
  scratch.weighted_rows.clear();
  Matrix5d M = Matrix5d::Zero();
  for (const Eigen::Vector2d& uv : scratch.uv) {
    const double u = uv.x() * system.inv_s, v = uv.y() * system.inv_s;
    const double r2 = u * u + v * v;
    const Vector5d b(u, v, u * u, u * v, v * v);
    const Vector5d& wb = scratch.weighted_rows.emplace_back((r2 > 0.0 ? 1.0 / r2 : 0.0) * b);
    M.noalias() += wb * b.transpose();
  }
  if (!cholesky_inverse(M, system.inverse)) return;
  const double norm_product = M.cwiseAbs().colwise().sum().maxCoeff() *
                              system.inverse.cwiseAbs().colwise().sum().maxCoeff();
  if (!std::isfinite(norm_product) || norm_product * singular_tolerance >= 1.0) return;
  system.singular = false;
  system.condition = std::sqrt(norm_product);
}

// A face incident to i (normals in `scratch`) or, for 2-ring fits, to a 1-ring neighbour projects
// onto (e1, e2) with negative orientation.
bool has_fold(int i, const Vertices& V, const QuadraticFits& fits, const Frame& frame,
              const FitScratch& scratch) {
  for (const Eigen::Vector3d& cross : scratch.face_normals)
    if (cross.dot(frame.normal) < 0.0) return true;
  for (int f : fits.outer_faces.row(i))
    if (face_cross(f, V, fits.faces).dot(frame.normal) < 0.0) return true;
  return false;
}

void store_frame(QuadraticFits& fits, int i, const Frame& frame) {
  fits.frame_normal.row(i) = frame.normal;
  fits.frame_tangent1.row(i) = frame.e1;
  fits.frame_tangent2.row(i) = frame.e2;
}

void clear_frame(QuadraticFits& fits, int i) {
  fits.frame_normal.row(i).setZero();
  fits.frame_tangent1.row(i).setZero();
  fits.frame_tangent2.row(i).setZero();
}

double* columns_of(QuadraticFits& fits, int i) {
  return fits.coefficients.data() + 5 * static_cast<std::ptrdiff_t>(fits.neighbours.offsets[i]);
}

// What a vertex without a fit stores besides its frame: C_i = 0 and an infinite condition.
void store_no_fit(QuadraticFits& fits, int i, FitStatus status) {
  std::fill(columns_of(fits, i), columns_of(fits, i) + 5 * fits.neighbours.size(i), 0.0);
  fits.condition[i] = kInfinity;
  fits.status[i] = status;
}

// Writes every per-vertex output of vertex i (frame, C_i, condition, status), so that the buffers
// need no initialization: the parallel fit is their first touch.
void fit_vertex(int i, const Vertices& V, QuadraticFits& fits, FitScratch& scratch,
                LocalSystem& system) {
  if (fits.neighbourhood[i] == Neighbourhood::kNotFitted) {
    clear_frame(fits, i);
    return store_no_fit(fits, i, FitStatus::kNotFitted);
  }
  const auto neighbours = fits.neighbours.row(i);
  gather(i, V, fits.faces, fits.vertex_faces.row(i), neighbours, scratch);
  const Frame frame = local_frame(scratch);
  if (frame.valid)
    store_frame(fits, i, frame);
  else
    clear_frame(fits, i);
  if (neighbours.size() < QuadraticFits::kTerms)
    return store_no_fit(fits, i, FitStatus::kTooFewNeighbours);
  if (!frame.valid) return store_no_fit(fits, i, FitStatus::kDegenerate);
  assemble_system(frame, fits.options.singular_tolerance, scratch, system);
  if (system.singular) return store_no_fit(fits, i, FitStatus::kDegenerate);
  fits.condition[i] = system.condition;
  // C = D⁻¹ M⁻¹ Bₛᵀ W with D = diag(s, s, s², s², s²) undoing the column scaling.
  const double is = system.inv_s;
  const Vector5d unscale(is, is, is * is, is * is, is * is);
  double* C = columns_of(fits, i);
  for (const Vector5d& wb : scratch.weighted_rows) {
    Eigen::Map<Vector5d> column(C);
    column = (system.inverse * wb).cwiseProduct(unscale);
    C += 5;
  }
  if (has_fold(i, V, fits, frame, scratch))
    fits.status[i] = FitStatus::kFold;
  else if (system.condition > fits.options.max_condition)
    fits.status[i] = FitStatus::kIllConditioned;
  else
    fits.status[i] = FitStatus::kOk;
}

// A vertex is on the border when an incident edge does not have exactly two faces.
std::vector<char> irregular_edge_vertices(const Topology& topo) {
  std::vector<char> flags(topo.num_vertices, 0);
  for (int e = 0; e < topo.edges.rows(); ++e)
    if (topo.edge_faces.size(e) != 2) flags[topo.edges(e, 0)] = flags[topo.edges(e, 1)] = 1;
  return flags;
}

// The neighbourhood each vertex gets from the topology alone: the 1-ring unless the vertex is on the
// border or has valence < 5 (the 1-ring's conditioning is checked after fitting).
std::vector<Neighbourhood> topological_neighbourhoods(const Topology& topo,
                                                      const std::vector<char>& fitted) {
  const auto border = irregular_edge_vertices(topo);
  std::vector<Neighbourhood> choice(topo.num_vertices, Neighbourhood::kNotFitted);
#pragma omp parallel for if (detail::worth_parallel(topo.num_vertices)) schedule(static)
  for (int i = 0; i < topo.num_vertices; ++i) {
    if (!fitted[i]) continue;
    if (border[i])
      choice[i] = Neighbourhood::kTwoRingBorder;
    else if (topo.vertex_vertices.size(i) < 5)
      choice[i] = Neighbourhood::kTwoRingLowValence;
    else
      choice[i] = Neighbourhood::kOneRing;
  }
  return choice;
}

bool uses_two_rings(Neighbourhood reason) {
  return reason != Neighbourhood::kNotFitted && reason != Neighbourhood::kOneRing;
}

// Fills a CSR whose row i is produced by row_of(i, scratch) (sorted, deduplicated into scratch).
template <class RowOf>
Csr build_rows(int n, RowOf row_of) {
  Csr csr;
  csr.offsets.assign(n + 1, 0);
#pragma omp parallel if (detail::worth_parallel(n))
  {
    std::vector<int> scratch;
#pragma omp for schedule(dynamic, 512)
    for (int i = 0; i < n; ++i) {
      row_of(i, scratch);
      csr.offsets[i + 1] = static_cast<int>(scratch.size());
    }
  }
  std::partial_sum(csr.offsets.begin(), csr.offsets.end(), csr.offsets.begin());
  csr.indices.resize(csr.offsets.back());
#pragma omp parallel if (detail::worth_parallel(n))
  {
    std::vector<int> scratch;
#pragma omp for schedule(dynamic, 512)
    for (int i = 0; i < n; ++i) {
      row_of(i, scratch);
      std::copy(scratch.begin(), scratch.end(), csr.indices.begin() + csr.offsets[i]);
    }
  }
  return csr;
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Builds N(i) and the fold-check faces from fits.neighbourhood, and sizes every per-vertex buffer.
void allocate_neighbourhoods(QuadraticFits& fits, const Topology& topo) {
  const int n = topo.num_vertices;
  const auto& reason = fits.neighbourhood;
  const Csr& ring = topo.vertex_vertices;
  const Faces& F = fits.faces;
  fits.neighbours = build_rows(n, [&](int i, std::vector<int>& row) {
    row.clear();
    if (reason[i] == Neighbourhood::kNotFitted) return;
    row.assign(ring.row(i).begin(), ring.row(i).end());
    if (!uses_two_rings(reason[i])) return;
    for (int j : ring.row(i)) row.insert(row.end(), ring.row(j).begin(), ring.row(j).end());
    sort_unique(row);
    row.erase(std::remove(row.begin(), row.end(), i), row.end());
  });
  fits.outer_faces = build_rows(n, [&](int i, std::vector<int>& row) {
    row.clear();
    if (!uses_two_rings(reason[i])) return;
    for (int j : ring.row(i))
      row.insert(row.end(), topo.vertex_faces.row(j).begin(), topo.vertex_faces.row(j).end());
    sort_unique(row);
    std::erase_if(row, [&](int f) { return F(f, 0) == i || F(f, 1) == i || F(f, 2) == i; });
  });
  // Left uninitialized: fit_vertex writes every entry, in parallel, which first-touches the pages.
  fits.coefficients.resize(5 * static_cast<Eigen::Index>(fits.neighbours.indices.size()));
  fits.frame_normal.resize(n, 3);
  fits.frame_tangent1.resize(n, 3);
  fits.frame_tangent2.resize(n, 3);
  fits.condition.resize(n);
  fits.status.resize(n);
}

}  // namespace

const char* to_string(Neighbourhood reason) {
  switch (reason) {
    case Neighbourhood::kNotFitted: return "not fitted";
    case Neighbourhood::kOneRing: return "1-ring";
    case Neighbourhood::kTwoRingLowValence: return "2-ring (valence < 5)";
    case Neighbourhood::kTwoRingBorder: return "2-ring (border)";
    case Neighbourhood::kTwoRingIllConditioned: return "2-ring (ill-conditioned 1-ring)";
    case Neighbourhood::kTwoRingRequested: return "2-ring (requested)";
  }
  return "unknown";
}

const char* to_string(FitStatus status) {
  switch (status) {
    case FitStatus::kOk: return "ok";
    case FitStatus::kNotFitted: return "not fitted";
    case FitStatus::kTooFewNeighbours: return "too few neighbours";
    case FitStatus::kDegenerate: return "degenerate";
    case FitStatus::kFold: return "fold";
    case FitStatus::kIllConditioned: return "ill-conditioned";
  }
  return "unknown";
}

std::vector<int> QuadraticFits::status_counts() const {
  std::vector<int> counts(static_cast<int>(FitStatus::kIllConditioned) + 1, 0);
  for (FitStatus s : status) ++counts[static_cast<int>(s)];
  return counts;
}

QuadraticFits fit_quadratics(const Vertices& V, const Faces& F, const Topology& topo,
                             const FitOptions& options, std::span<const int> vertices,
                             std::span<const int> two_ring_vertices) {
  const int n = static_cast<int>(V.rows());
  if (topo.num_vertices != n || topo.num_faces != F.rows())
    throw InvalidArgument("fit_quadratics: the topology was built for " +
                          std::to_string(topo.num_vertices) + " vertices and " +
                          std::to_string(topo.num_faces) + " faces, the mesh has " +
                          std::to_string(n) + " and " + std::to_string(F.rows()));
  if (!V.allFinite()) throw InvalidMeshError("fit_quadratics: a vertex coordinate is not finite");
  std::vector<char> fitted(n, vertices.empty() ? 1 : 0);
  for (int v : vertices) {
    if (v < 0 || v >= n)
      throw InvalidArgument("fit_quadratics: vertex " + std::to_string(v) + " out of range [0, " +
                            std::to_string(n) + ")");
    fitted[v] = 1;
  }

  QuadraticFits fits;
  fits.options = options;
  fits.faces = F;
  fits.vertex_faces = topo.vertex_faces;
  fits.neighbourhood = topological_neighbourhoods(topo, fitted);
  for (int v : two_ring_vertices) {
    if (v < 0 || v >= n)
      throw InvalidArgument("fit_quadratics: two-ring vertex " + std::to_string(v) + " out of range [0, " +
                            std::to_string(n) + ")");
    if (fits.neighbourhood[v] == Neighbourhood::kOneRing) fits.neighbourhood[v] = Neighbourhood::kTwoRingRequested;
  }
  allocate_neighbourhoods(fits, topo);
  refit_quadratics(fits, V);
  // 1-rings whose fit is ill-conditioned (or singular) switch to the 2-ring; usually none do, so
  // fitting optimistically costs one fit per vertex instead of two.
  bool switched = false;
  for (int i = 0; i < n; ++i)
    if (fits.neighbourhood[i] == Neighbourhood::kOneRing &&
        !(fits.condition[i] <= options.max_one_ring_condition)) {
      fits.neighbourhood[i] = Neighbourhood::kTwoRingIllConditioned;
      switched = true;
    }
  if (switched) {
    allocate_neighbourhoods(fits, topo);
    refit_quadratics(fits, V);
  }
  return fits;
}

void refit_quadratics(QuadraticFits& fits, const Vertices& V) {
  const int n = fits.num_vertices();
  if (V.rows() != n)
    throw InvalidArgument("refit_quadratics: " + std::to_string(V.rows()) +
                          " positions for fits over " + std::to_string(n) + " vertices");
#pragma omp parallel if (detail::worth_parallel(n))
  {
    FitScratch scratch;
    LocalSystem system;
#pragma omp for schedule(dynamic, 512)
    for (int i = 0; i < n; ++i) fit_vertex(i, V, fits, scratch, system);
  }
}

}  // namespace fairsurf
