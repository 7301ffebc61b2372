// method.md §3 for the fits: neighbourhood choice with its reason, exactness on quadratics, the
// reported ill-posed cases (too few neighbours, collinear neighbours, a fold, an ill-conditioned
// 1-ring), subsets, and re-fitting into the same buffers.
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analytic_meshes.h"
#include "test_support.h"

using namespace fairsurf;

namespace {

struct Fitted {
  Topology topo;
  QuadraticFits fits;
};

Fitted fit(const Mesh& m, const FitOptions& options = {}) {
  Fitted f;
  f.topo = build_topology(m.F, m.num_vertices());
  f.fits = fit_quadratics(m.V, m.F, f.topo, options);
  return f;
}

// A planar grid whose quads are split along alternating diagonals: interior valences alternate
// between 4 and 8. Vertex (i, j) has index j·(n+1) + i, centred on the origin.
Mesh checkerboard_grid(int n, double h) {
  Mesh m = test::regular_grid(n, n, h);
  m.V.col(0).array() -= 0.5 * n * h;
  m.V.col(1).array() -= 0.5 * n * h;
  for (int j = 0, f = 0; j < n; ++j)
    for (int i = 0; i < n; ++i, f += 2) {
      if ((i + j) % 2 == 0) continue;
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.F.row(f) << a, b, c;
      m.F.row(f + 1) << b, d, c;
    }
  return m;
}

// Lifts a planar mesh onto the graph z = p x² + q y².
void lift_to_paraboloid(Mesh& m, double p, double q) {
  for (int v = 0; v < m.num_vertices(); ++v)
    m.V(v, 2) = p * m.V(v, 0) * m.V(v, 0) + q * m.V(v, 1) * m.V(v, 1);
}

}  // namespace

TEST(QuadraticFit, NeighbourhoodsFollowValenceAndBorder) {
  const Mesh m = test::open_cylinder(16, 6, 1.0, 1.0);
  const Fitted f = fit(m);
  const auto border = boundary_vertex_flags(f.topo);
  for (int i = 0; i < m.num_vertices(); ++i) {
    if (border[i]) {
      EXPECT_EQ(f.fits.neighbourhood[i], Neighbourhood::kTwoRingBorder);
      EXPECT_EQ(f.fits.neighbours.size(i), static_cast<int>(k_ring(f.topo, std::vector<int>{i}, 2).size()) - 1);
    } else {
      EXPECT_EQ(f.fits.neighbourhood[i], Neighbourhood::kOneRing);
      EXPECT_EQ(f.fits.neighbours.size(i), 6);
    }
    EXPECT_EQ(f.fits.status[i], FitStatus::kOk) << i;
  }
  // Valence 4 and 8 alternate on a checkerboard grid; valence 4 takes the 2-ring.
  const Mesh c = checkerboard_grid(6, 1.0);
  const Fitted g = fit(c);
  const int centre = 3 * 7 + 3, beside = centre + 1;
  ASSERT_EQ(g.topo.vertex_vertices.size(centre) + g.topo.vertex_vertices.size(beside), 12);
  const int four = g.topo.vertex_vertices.size(centre) == 4 ? centre : beside;
  const int eight = four == centre ? beside : centre;
  EXPECT_EQ(g.fits.neighbourhood[four], Neighbourhood::kTwoRingLowValence);
  EXPECT_EQ(g.fits.neighbours.size(four), 20);  // the 5 by 5 block around it, less its corners
  EXPECT_EQ(g.fits.neighbourhood[eight], Neighbourhood::kOneRing);
}

TEST(QuadraticFit, QuadraticGraphsAreReproducedExactlyAtTheOrigin) {
  // At the apex of z = p x² + q y² the frame is (x, y, z) by symmetry, so the fit is exact:
  // with the normal +z, b = diag(2p, 2q), H = p + q, K = 4pq.
  const double p = 0.7, q = -0.3;
  int checked = 0;
  for (const bool checkerboard : {false, true}) {
    Mesh m = checkerboard ? checkerboard_grid(6, 0.1) : test::regular_grid(6, 6, 0.1);
    if (!checkerboard) m.V.leftCols(2).array() -= 0.3;
    lift_to_paraboloid(m, p, q);
    const Fitted f = fit(m);
    const SurfaceGeometry g = compute_geometry(f.fits, m.V);
    for (int origin : {3 * 7 + 3, 3 * 7 + 4}) {
      if (std::abs(m.V(origin, 0)) > 1e-12 || std::abs(m.V(origin, 1)) > 1e-12) continue;
      // Valence 4 or 8 on the checkerboard, 6 on the regular grid: both neighbourhoods are exact.
      EXPECT_NEAR(g.H[origin], p + q, 1e-12);
      EXPECT_NEAR(g.K[origin], 4 * p * q, 1e-12);
      EXPECT_NEAR(g.k1[origin], 2 * p, 1e-12);
      EXPECT_NEAR(g.k2[origin], 2 * q, 1e-12);
      EXPECT_NEAR(g.normal(origin, 2), 1.0, 1e-14);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2);
}

TEST(QuadraticFit, TooFewNeighboursIsReportedAndZeroed) {
  Mesh m;  // a tetrahedron: every 2-ring has 3 vertices
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.F.resize(4, 3);
  m.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  const Fitted f = fit(m);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(f.fits.neighbourhood[i], Neighbourhood::kTwoRingLowValence);
    EXPECT_EQ(f.fits.status[i], FitStatus::kTooFewNeighbours);
  }
  EXPECT_TRUE(f.fits.coefficients.isZero());
  const SurfaceOperators ops = compute_operators(f.fits, m.V);
  EXPECT_TRUE(ops.geometry.H.allFinite());
  EXPECT_EQ(Eigen::MatrixXd(ops.laplace).cwiseAbs().sum(), 0.0);
  EXPECT_EQ(f.fits.status_counts()[static_cast<int>(FitStatus::kTooFewNeighbours)], 4);
}

TEST(QuadraticFit, CollinearNeighboursAreDegenerate) {
  // A fan from the apex to six collinear points: the tangent plane contains them all, so the
  // projected neighbours lie on one line (v constant) and the five coefficients are not determined.
  Mesh m;
  m.V.resize(7, 3);
  m.V.row(0) << 0, 0, 0;
  for (int k = 0; k < 6; ++k) m.V.row(k + 1) << -2.5 + k, 1.0, 0.0;
  m.F.resize(5, 3);
  for (int k = 0; k < 5; ++k) m.F.row(k) << 0, k + 2, k + 1;
  const Fitted f = fit(m);
  EXPECT_EQ(f.fits.neighbourhood[0], Neighbourhood::kTwoRingBorder);
  EXPECT_EQ(f.fits.neighbours.size(0), 6);
  EXPECT_EQ(f.fits.status[0], FitStatus::kDegenerate);
  EXPECT_TRUE(std::isinf(f.fits.condition[0]));
  const SurfaceGeometry g = compute_geometry(f.fits, m.V);
  EXPECT_EQ(g.H[0], 0.0);
  EXPECT_NEAR(std::abs(g.normal(0, 2)), 1.0, 1e-14);  // N0 is still reported
}

TEST(QuadraticFit, FoldIsReported) {
  // Interior vertex of a flat grid; one neighbour is lifted and pushed across it, so two faces of
  // the fan project onto the tangent plane with reversed orientation.
  Mesh m = test::regular_grid(4, 4, 1.0);
  const int centre = 2 * 5 + 2, right = centre + 1;
  m.V.row(right) << 1.4, 2.0, 0.2;  // projects beyond the centre (2, 2), onto the left side
  const Fitted f = fit(m);
  EXPECT_EQ(f.fits.neighbourhood[centre], Neighbourhood::kOneRing);
  EXPECT_EQ(f.fits.status[centre], FitStatus::kFold);
  EXPECT_GT(f.fits.frame_normal(centre, 2), 0.0);
  EXPECT_TRUE(compute_geometry(f.fits, m.V).H.allFinite());
  // Flattening it again is seen by a re-fit on the same connectivity.
  m.V.row(right) << 3.0, 2.0, 0.0;
  QuadraticFits fits = f.fits;
  refit_quadratics(fits, m.V);
  EXPECT_EQ(fits.status[centre], FitStatus::kOk);
}

TEST(QuadraticFit, IllConditionedOneRingSwitchesToTheTwoRing) {
  // Squeezing a grid in y makes every 1-ring nearly collinear: condition ≈ 1/ε².
  Mesh m = test::regular_grid(6, 6, 1.0);
  m.V.col(1) *= 1e-3;
  lift_to_paraboloid(m, 0.1, 0.2);
  FitOptions options;
  const Fitted f = fit(m, options);
  const int centre = 3 * 7 + 3;
  EXPECT_EQ(f.fits.neighbourhood[centre], Neighbourhood::kTwoRingIllConditioned);
  EXPECT_EQ(f.fits.neighbours.size(centre), 18);
  EXPECT_GT(f.fits.condition[centre], 1e3);
  // A stricter flag threshold reports it; the fit itself is kept (finite).
  options.max_condition = 100.0;
  const Fitted g = fit(m, options);
  EXPECT_EQ(g.fits.status[centre], FitStatus::kIllConditioned);
  EXPECT_TRUE(std::isfinite(g.fits.condition[centre]));
  EXPECT_FALSE(g.fits.coefficients.isZero());
}

TEST(QuadraticFit, SubsetFitsOnlyTheListedVertices) {
  const Mesh m = test::icosphere(2);
  const Fitted all = fit(m);
  const std::vector<int> subset{0, 5, 17, 100};
  const QuadraticFits some = fit_quadratics(m.V, m.F, all.topo, {}, subset);
  int fitted = 0;
  for (int i = 0; i < m.num_vertices(); ++i) {
    const bool listed = std::find(subset.begin(), subset.end(), i) != subset.end();
    fitted += listed;
    EXPECT_EQ(some.status[i], listed ? FitStatus::kOk : FitStatus::kNotFitted);
    EXPECT_EQ(some.neighbours.size(i), listed ? all.fits.neighbours.size(i) : 0);
  }
  EXPECT_EQ(fitted, 4);
  const SurfaceOperators a = compute_operators(all.fits, m.V), s = compute_operators(some, m.V);
  for (int i : subset) {
    EXPECT_DOUBLE_EQ(s.geometry.H[i], a.geometry.H[i]);
    EXPECT_EQ((Eigen::RowVectorXd(s.laplace.row(i)) - Eigen::RowVectorXd(a.laplace.row(i))).norm(), 0.0);
  }
  int expected = 0;
  for (int i : subset) expected += all.topo.vertex_vertices.size(i) + 1;
  EXPECT_EQ(s.laplace.nonZeros(), expected);
  EXPECT_THROW(fit_quadratics(m.V, m.F, all.topo, {}, std::vector<int>{m.num_vertices()}),
               InvalidArgument);
}

// FlowOptions::two_ring_boundary_fits: listed vertices are fitted over their 2-ring. On a noisy sphere
// the wider fit averages the noise: its mean curvature is closer to the sphere's on average.
TEST(QuadraticFit, RequestedTwoRingFitsReadTheSurfaceOverTwoRings) {
  const Mesh m = test::icosphere(3);
  Mesh noisy = m;
  std::mt19937 random(7);
  std::normal_distribution<double> deviate(0.0, 0.01);  // radial, about a tenth of an edge
  for (int v = 0; v < m.num_vertices(); ++v) noisy.V.row(v) *= 1.0 + deviate(random);
  const Fitted one = fit(noisy);
  std::vector<int> listed;
  for (int v = 0; v < m.num_vertices(); v += 3) listed.push_back(v);
  const QuadraticFits two = fit_quadratics(noisy.V, noisy.F, one.topo, {}, {}, listed);
  const SurfaceOperators a = compute_operators(one.fits, noisy.V), b = compute_operators(two, noisy.V);
  double error_one = 0, error_two = 0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const bool is_listed = v % 3 == 0;
    EXPECT_EQ(two.neighbourhood[v], is_listed ? Neighbourhood::kTwoRingRequested : one.fits.neighbourhood[v]);
    EXPECT_EQ(two.neighbours.size(v), is_listed ? static_cast<int>(k_ring(one.topo, std::vector<int>{v}, 2).size()) - 1
                                                : one.fits.neighbours.size(v));
    if (!is_listed) {
      EXPECT_DOUBLE_EQ(b.geometry.H[v], a.geometry.H[v]);
      continue;
    }
    error_one += std::abs(std::abs(a.geometry.H[v]) - 1.0);
    error_two += std::abs(std::abs(b.geometry.H[v]) - 1.0);
  }
  EXPECT_LT(error_two, 0.5 * error_one);
  EXPECT_STREQ(to_string(Neighbourhood::kTwoRingRequested), "2-ring (requested)");
  EXPECT_THROW(fit_quadratics(m.V, m.F, one.topo, {}, {}, std::vector<int>{-1}), InvalidArgument);
}

TEST(QuadraticFit, RefitReusesBuffersAndMatchesAFreshFit) {
  Mesh m = test::jittered_sphere(3, 1.0, 0.2);
  Fitted f = fit(m);
  const double* coefficients = f.fits.coefficients.data();
  const int* neighbours = f.fits.neighbours.indices.data();
  Vertices moved = m.V;
  for (int i = 0; i < moved.rows(); ++i) moved.row(i) *= 1.0 + 0.05 * std::sin(3.0 * moved(i, 2));
  refit_quadratics(f.fits, moved);
  EXPECT_EQ(f.fits.coefficients.data(), coefficients);
  EXPECT_EQ(f.fits.neighbours.indices.data(), neighbours);
  const QuadraticFits fresh = fit_quadratics(moved, m.F, f.topo);
  ASSERT_EQ(fresh.neighbours.indices, f.fits.neighbours.indices);
  EXPECT_EQ((fresh.coefficients - f.fits.coefficients).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((fresh.condition - f.fits.condition).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(refit_quadratics(f.fits, Vertices(3, 3)), InvalidArgument);
}

TEST(QuadraticFit, RejectsMismatchedTopologyAndNonFinitePositions) {
  Mesh m = test::icosphere(1);
  const Topology topo = build_topology(m.F, m.num_vertices());
  const Mesh other = test::icosphere(2);
  try {
    fit_quadratics(other.V, other.F, topo);
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("fit_quadratics: ", 0), 0u) << e.what();
  }
  m.V(3, 1) = std::nan("");
  EXPECT_THROW(fit_quadratics(m.V, m.F, topo), InvalidMeshError);
}
