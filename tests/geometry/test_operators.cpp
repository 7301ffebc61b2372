// method.md §8.1–8.2 for the operators: exact discrete identities, signs, convergence orders against
// analytic values, the normal-weighted matrices of §5, and in-place re-evaluation.
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "analytic_meshes.h"
#include "convergence.h"
#include "test_support.h"

using namespace fairsurf;
using fairsurf::test::observed_order;
using fairsurf::test::report_convergence;

namespace {

struct Evaluated {
  Topology topo;
  QuadraticFits fits;
  SurfaceOperators ops;
};

Evaluated evaluate(const Mesh& m) {
  Evaluated e;
  e.topo = build_topology(m.F, m.num_vertices());
  e.fits = fit_quadratics(m.V, m.F, e.topo);
  e.ops = compute_operators(e.fits, m.V);
  return e;
}

// max_i ‖(L x)_i − 2 c_i n_i‖ relative to max_i |2 c_i| (at least `scale`), over the vertices
// with a fit. (L x)_i is evaluated in stencil form, Σ_j w_ij (x_j − x_i): the product L * V would add
// a cancellation error of order ε·|x|/h², which has nothing to do with the identity.
double identity_defect(const SparseRowMatrix& L, const Eigen::VectorXd& c, const Evaluated& e,
                       const Vertices& V, double scale) {
  double worst = 0.0;
  for (int i = 0; i < V.rows(); ++i) {
    if (e.fits.status[i] != FitStatus::kOk) continue;
    Eigen::RowVector3d stencil = Eigen::RowVector3d::Zero();
    for (SparseRowMatrix::InnerIterator it(L, i); it; ++it)
      if (it.index() != i) stencil += it.value() * (V.row(it.index()) - V.row(i));
    const Eigen::RowVector3d expected = 2.0 * c[i] * e.ops.geometry.normal.row(i);
    worst = std::max(worst, (stencil - expected).norm());
    scale = std::max(scale, std::abs(2.0 * c[i]));
  }
  return worst / scale;
}

void expect_identities(const Mesh& m, const std::string& name) {
  const Evaluated e = evaluate(m);
  // □x = 2Kn is measured against the curvature scale H² too: K vanishes on a cylinder.
  const double H2 = e.ops.geometry.H.cwiseAbs2().maxCoeff();
  const double laplace = identity_defect(e.ops.laplace, e.ops.geometry.H, e, m.V, 0.0);
  const double giaquinta = identity_defect(e.ops.giaquinta, e.ops.geometry.K, e, m.V, 2.0 * H2);
  std::printf("[identity] %s: |L∆x − 2Hn| %.2e, |L□x − 2Kn| %.2e (relative)\n", name.c_str(),
              laplace, giaquinta);
  EXPECT_LT(laplace, 1e-12) << name;
  EXPECT_LT(giaquinta, 1e-12) << name;
  EXPECT_EQ(e.fits.status_counts()[static_cast<int>(FitStatus::kOk)], m.num_vertices()) << name;
}

}  // namespace

TEST(Operators, DiscreteIdentitiesHoldToRoundOffOnAnalyticMeshes) {
  expect_identities(test::icosphere(3, 2.0), "icosphere");
  expect_identities(test::jittered_sphere(3, 1.0, 0.3), "jittered sphere");
  expect_identities(test::ellipsoid(3, 1.0, 0.7, 0.4), "ellipsoid");
  expect_identities(test::torus_grid(48, 16, 1.0, 0.4, 0.2).mesh, "jittered torus");
  expect_identities(test::open_cylinder(24, 10, 1.0, 2.0), "open cylinder");
  expect_identities(test::saddle_patch(12, 1.0), "saddle");
}

TEST(Operators, GradientOfThePositionIsTheTangentProjector) {
  // ∇x_d = g^αβ (t_α)_d t_β, so (G_c x_d)_i = δ_cd − n_c n_d exactly.
  const Mesh m = test::jittered_sphere(3, 1.0, 0.3);
  const Evaluated e = evaluate(m);
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    const Eigen::MatrixX3d GX = e.ops.gradient[c] * m.V;
    for (int i = 0; i < m.num_vertices(); ++i)
      for (int d = 0; d < 3; ++d) {
        const Eigen::RowVector3d n = e.ops.geometry.normal.row(i);
        worst = std::max(worst, std::abs(GX(i, d) - ((c == d ? 1.0 : 0.0) - n[c] * n[d])));
      }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(Operators, SignsOnSphereCylinderAndSaddle) {
  const double R = 2.0;
  {
    const Evaluated e = evaluate(test::icosphere(4, R));
    for (int i = 0; i < e.topo.num_vertices; ++i) {
      ASSERT_NEAR(e.ops.geometry.H[i], -1.0 / R, 2e-3);
      ASSERT_NEAR(e.ops.geometry.K[i], 1.0 / (R * R), 2e-3);
      ASSERT_NEAR(e.ops.geometry.k1[i], -1.0 / R, 5e-2);
      ASSERT_GT(e.ops.geometry.normal.row(i).dot(e.ops.geometry.normal.row(i)), 0.999);
    }
  }
  {
    const Mesh m = test::open_cylinder(64, 40, R, 4.0);
    const Evaluated e = evaluate(m);
    const auto border = boundary_vertex_flags(e.topo);
    for (int i = 0; i < m.num_vertices(); ++i) {
      ASSERT_NEAR(e.ops.geometry.H[i], -1.0 / (2 * R), border[i] ? 2e-2 : 1e-3) << i;
      ASSERT_NEAR(e.ops.geometry.K[i], 0.0, border[i] ? 2e-2 : 1e-3) << i;
      ASSERT_NEAR(e.ops.geometry.k1[i], 0.0, border[i] ? 5e-2 : 1e-2) << i;
      ASSERT_NEAR(e.ops.geometry.k2[i], -1.0 / R, border[i] ? 5e-2 : 1e-2) << i;
      // Outward: the normal points away from the axis.
      ASSERT_GT(e.ops.geometry.normal.row(i).head<2>().dot(m.V.row(i).head<2>()), 0.0);
    }
  }
  {
    const int n = 12;
    const Evaluated e = evaluate(test::saddle_patch(n, 1.0));
    const int origin = (n / 2) * (n + 1) + n / 2;
    // z = x² − y² with normal +z: b = diag(2, −2), so H = 0 and K = −4 exactly (a quadratic).
    EXPECT_NEAR(e.ops.geometry.H[origin], 0.0, 1e-12);
    EXPECT_NEAR(e.ops.geometry.K[origin], -4.0, 1e-12);
    EXPECT_NEAR(e.ops.geometry.k1[origin], 2.0, 1e-12);
    EXPECT_NEAR(e.ops.geometry.k2[origin], -2.0, 1e-12);
  }
}

namespace {

struct CurvatureErrors {
  double h, H, K;
  int vertices;
};

CurvatureErrors curvature_errors(const Mesh& m, const std::function<double(int)>& exact_H,
                                 const std::function<double(int)>& exact_K) {
  const Evaluated e = evaluate(m);
  CurvatureErrors out{mean_edge_length(m.V, e.topo), 0.0, 0.0, m.num_vertices()};
  for (int i = 0; i < m.num_vertices(); ++i) {
    out.H = std::max(out.H, std::abs(e.ops.geometry.H[i] - exact_H(i)));
    out.K = std::max(out.K, std::abs(e.ops.geometry.K[i] - exact_K(i)));
  }
  return out;
}

// Runs curvature_errors over the meshes and checks that H and K converge at order ≈ 2.
void expect_second_order_curvatures(const std::string& name, const std::vector<Mesh>& meshes,
                                    const std::function<double(const Mesh&, int)>& exact_H,
                                    const std::function<double(const Mesh&, int)>& exact_K) {
  std::vector<double> h, eH, eK;
  std::vector<int> nv;
  for (const Mesh& m : meshes) {
    const auto e = curvature_errors(
        m, [&](int i) { return exact_H(m, i); }, [&](int i) { return exact_K(m, i); });
    h.push_back(e.h), eH.push_back(e.H), eK.push_back(e.K), nv.push_back(e.vertices);
  }
  const double pH = report_convergence(name + " max|H − H*|", nv, h, eH);
  const double pK = report_convergence(name + " max|K − K*|", nv, h, eK);
  EXPECT_NEAR(pH, 2.0, 0.3) << name;
  EXPECT_NEAR(pK, 2.0, 0.3) << name;
}

}  // namespace

TEST(Operators, CurvaturesConvergeAtSecondOrderOnSpheres) {
  auto sphere_H = [](const Mesh&, int) { return -1.0; };
  auto sphere_K = [](const Mesh&, int) { return 1.0; };
  expect_second_order_curvatures("icosphere", {test::icosphere(3), test::icosphere(4), test::icosphere(5)},
                                 sphere_H, sphere_K);
  // method.md §8.2 reference: H error 4.3e-4 on the 10k icosphere.
  const auto e = curvature_errors(test::icosphere(5), [](int) { return -1.0; }, [](int) { return 1.0; });
  EXPECT_LT(e.H, 1e-3);
  expect_second_order_curvatures(
      "jittered sphere",
      {test::jittered_sphere(3, 1.0, 0.25), test::jittered_sphere(4, 1.0, 0.25),
       test::jittered_sphere(5, 1.0, 0.25)},
      sphere_H, sphere_K);
}

TEST(Operators, CurvaturesConvergeAtSecondOrderOnAnEllipsoid) {
  const double a = 1.0, b = 0.8, c = 0.6;
  auto point = [](const Mesh& m, int i) { return Eigen::Vector3d(m.V.row(i)); };
  expect_second_order_curvatures(
      "ellipsoid", {test::ellipsoid(3, a, b, c), test::ellipsoid(4, a, b, c), test::ellipsoid(5, a, b, c)},
      [&](const Mesh& m, int i) { return test::ellipsoid_mean_curvature(point(m, i), a, b, c); },
      [&](const Mesh& m, int i) { return test::ellipsoid_gaussian_curvature(point(m, i), a, b, c); });
}

namespace {

// A smooth function on the torus of radii R, r and its exact ∆, □, ∇ and ◇ (method.md §2 in the
// (u, v) parametrization: g = diag(ρ², r²), b = diag(−ρ cos v, −r), ρ = R + r cos v).
struct TorusFunction {
  double R, r;
  double f(double u, double v) const { return std::cos(2 * u) * std::sin(v) + 0.5 * std::cos(2 * v); }
  double fu(double u, double v) const { return -2 * std::sin(2 * u) * std::sin(v); }
  double fuu(double u, double v) const { return -4 * std::cos(2 * u) * std::sin(v); }
  double fv(double u, double v) const { return std::cos(2 * u) * std::cos(v) - std::sin(2 * v); }
  double fvv(double u, double v) const { return -std::cos(2 * u) * std::sin(v) - 2 * std::cos(2 * v); }
  double rho(double v) const { return R + r * std::cos(v); }
  double laplace(double u, double v) const {
    const double p = rho(v);
    return fuu(u, v) / (p * p) + fvv(u, v) / (r * r) - std::sin(v) * fv(u, v) / (p * r);
  }
  double giaquinta(double u, double v) const {
    const double p = rho(v);
    return -fuu(u, v) / (p * p * r) + (std::sin(v) * fv(u, v) - std::cos(v) * fvv(u, v)) / (p * r * r);
  }
  Eigen::Vector3d tu(double u, double v) const { return rho(v) * Eigen::Vector3d(-std::sin(u), std::cos(u), 0); }
  Eigen::Vector3d tv(double u, double v) const {
    return r * Eigen::Vector3d(-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v));
  }
  Eigen::Vector3d gradient(double u, double v) const {
    const double p = rho(v);
    return fu(u, v) / (p * p) * tu(u, v) + fv(u, v) / (r * r) * tv(u, v);
  }
  Eigen::Vector3d second_gradient(double u, double v) const {
    const double p = rho(v);
    return -fu(u, v) / (p * p * r) * tu(u, v) - std::cos(v) * fv(u, v) / (p * r * r) * tv(u, v);
  }
};

struct OperatorErrors {
  double h, laplace, giaquinta, gradient, second_gradient;
  int vertices;
};

// Errors of ∆f, □f, ∇f, ◇f at every vertex, summarized by their maximum (`rms` false) or their
// root mean square (`rms` true: on jittered meshes the maximum is a tail statistic of the random
// configurations and grows with their number).
OperatorErrors torus_operator_errors(int n, int m, double jitter, bool rms) {
  const TorusFunction tf{1.0, 0.4};
  const auto torus = test::torus_grid(n, m, tf.R, tf.r, jitter);
  const Evaluated e = evaluate(torus.mesh);
  const int nv = torus.mesh.num_vertices();
  Eigen::VectorXd f(nv);
  for (int i = 0; i < nv; ++i) f[i] = tf.f(torus.uv(i, 0), torus.uv(i, 1));
  const Eigen::VectorXd Lf = e.ops.laplace * f, Bf = e.ops.giaquinta * f;
  Eigen::MatrixX3d Gf(nv, 3), Df(nv, 3);
  for (int c = 0; c < 3; ++c) Gf.col(c) = e.ops.gradient[c] * f, Df.col(c) = e.ops.second_gradient[c] * f;
  Eigen::MatrixX4d err(nv, 4);
  for (int i = 0; i < nv; ++i) {
    const double u = torus.uv(i, 0), v = torus.uv(i, 1);
    err.row(i) << Lf[i] - tf.laplace(u, v), Bf[i] - tf.giaquinta(u, v),
        (Gf.row(i).transpose() - tf.gradient(u, v)).norm(),
        (Df.row(i).transpose() - tf.second_gradient(u, v)).norm();
  }
  const Eigen::RowVector4d summary = rms ? Eigen::RowVector4d(err.colwise().norm() / std::sqrt(nv))
                                         : Eigen::RowVector4d(err.cwiseAbs().colwise().maxCoeff());
  return {mean_edge_length(torus.mesh.V, e.topo), summary[0], summary[1], summary[2], summary[3], nv};
}

struct OperatorOrders {
  double laplace, giaquinta, gradient, second_gradient;
};

OperatorOrders torus_operator_orders(const std::string& name, double jitter, bool rms) {
  std::vector<double> h, eL, eB, eG, eD;
  std::vector<int> nv;
  for (int m : {16, 32, 64}) {
    const auto e = torus_operator_errors(2 * m, m, jitter, rms);
    h.push_back(e.h), eL.push_back(e.laplace), eB.push_back(e.giaquinta);
    eG.push_back(e.gradient), eD.push_back(e.second_gradient), nv.push_back(e.vertices);
  }
  const std::string norm = rms ? " rms" : " max";
  return {report_convergence(name + norm + "|∆f − ∆f*|", nv, h, eL),
          report_convergence(name + norm + "|□f − □f*|", nv, h, eB),
          report_convergence(name + norm + "|∇f − ∇f*|", nv, h, eG),
          report_convergence(name + norm + "|◇f − ◇f*|", nv, h, eD)};
}

}  // namespace

TEST(Operators, SingleOperatorsConvergeAtSecondOrderOnRegularTorusGrids) {
  const auto p = torus_operator_orders("regular torus", 0.0, false);
  EXPECT_NEAR(p.laplace, 2.0, 0.3);
  EXPECT_NEAR(p.giaquinta, 2.0, 0.3);
  EXPECT_NEAR(p.gradient, 2.0, 0.3);
  EXPECT_NEAR(p.second_gradient, 2.0, 0.3);
}

TEST(Operators, SingleOperatorsConvergeAtLeastAtFirstOrderOnJitteredTori) {
  // Parameters jittered by up to ±0.25 grid spacings: the mesh stays irregular under refinement.
  const auto p = torus_operator_orders("jittered torus", 0.25, true);
  EXPECT_GE(p.laplace, 0.8);
  EXPECT_GE(p.giaquinta, 0.8);
  EXPECT_GE(p.gradient, 1.5);
  EXPECT_GE(p.second_gradient, 0.8);
}

TEST(Operators, NormalWeightedMatricesLinearizeHAndKWithFrozenStencils) {
  // method.md §5: for x' = x + d n with the stencils frozen, ½ n_i·(L∆x')_i = H_i + ½(A_H d)_i and
  // ½ n_i·(L□x')_i = K_i + ½(A_K d)_i, exactly (the stencils are linear in the positions).
  const auto torus = test::torus_grid(40, 20, 1.0, 0.4, 0.2);
  const Mesh& m = torus.mesh;
  const Evaluated e = evaluate(m);
  const Vertices& n = e.ops.geometry.normal;
  Eigen::VectorXd d(m.num_vertices());
  for (int i = 0; i < d.size(); ++i) d[i] = 0.01 * std::sin(torus.uv(i, 0)) * std::cos(2 * torus.uv(i, 1));
  const Vertices moved = m.V + d.asDiagonal() * n;
  SparseRowMatrix A_H, A_K;
  normal_weighted(e.ops.laplace, n, A_H);
  normal_weighted(e.ops.giaquinta, n, A_K);
  ASSERT_EQ(A_H.nonZeros(), e.ops.laplace.nonZeros());
  const Eigen::MatrixX3d LX = e.ops.laplace * moved, BX = e.ops.giaquinta * moved;
  const Eigen::VectorXd AHd = A_H * d, AKd = A_K * d;
  double worst_H = 0.0, worst_K = 0.0;
  for (int i = 0; i < d.size(); ++i) {
    worst_H = std::max(worst_H, std::abs(0.5 * n.row(i).dot(LX.row(i)) - e.ops.geometry.H[i] - 0.5 * AHd[i]));
    worst_K = std::max(worst_K, std::abs(0.5 * n.row(i).dot(BX.row(i)) - e.ops.geometry.K[i] - 0.5 * AKd[i]));
  }
  EXPECT_LT(worst_H, 1e-12 * e.ops.geometry.H.cwiseAbs().maxCoeff());
  EXPECT_LT(worst_K, 1e-12 * e.ops.geometry.K.cwiseAbs().maxCoeff());
  // Same pattern, diagonal untouched, storage reused on the next call.
  const double* values = A_H.valuePtr();
  normal_weighted(e.ops.laplace, n, A_H);
  EXPECT_EQ(A_H.valuePtr(), values);
  EXPECT_EQ((Eigen::VectorXd(A_H.diagonal()) - Eigen::VectorXd(e.ops.laplace.diagonal())).norm(), 0.0);
  EXPECT_THROW(normal_weighted(e.ops.laplace, Vertices(3, 3), A_H), InvalidArgument);
}

TEST(Operators, UpdateInPlaceEqualsAFreshEvaluation) {
  const Mesh m = test::ellipsoid(3, 1.0, 0.8, 0.6);
  Evaluated e = evaluate(m);
  const double* values = e.ops.laplace.valuePtr();
  const int* columns = e.ops.giaquinta.innerIndexPtr();
  Vertices moved = m.V;
  for (int i = 0; i < moved.rows(); ++i) moved.row(i) *= 1.0 + 0.03 * std::cos(2.0 * moved(i, 0));
  refit_quadratics(e.fits, moved);
  update_operators(e.fits, moved, e.ops);
  EXPECT_EQ(e.ops.laplace.valuePtr(), values);
  EXPECT_EQ(e.ops.giaquinta.innerIndexPtr(), columns);
  const Topology topo = build_topology(m.F, m.num_vertices());
  const SurfaceOperators fresh = compute_operators(fit_quadratics(moved, m.F, topo), moved);
  EXPECT_EQ((fresh.laplace - e.ops.laplace).norm(), 0.0);
  EXPECT_EQ((fresh.giaquinta - e.ops.giaquinta).norm(), 0.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ((fresh.gradient[c] - e.ops.gradient[c]).norm(), 0.0);
    EXPECT_EQ((fresh.second_gradient[c] - e.ops.second_gradient[c]).norm(), 0.0);
  }
  EXPECT_EQ((fresh.geometry.H - e.ops.geometry.H).norm(), 0.0);
  EXPECT_EQ((fresh.geometry.area - e.ops.geometry.area).norm(), 0.0);
  // The vertex areas are topology.h's.
  EXPECT_EQ((vertex_areas(moved, m.F) - e.ops.geometry.area).norm(), 0.0);
  // Operators from other fits are refused.
  const Mesh other = test::icosphere(2);
  const Evaluated o = evaluate(other);
  EXPECT_THROW(update_operators(o.fits, other.V, e.ops), InvalidArgument);
}

TEST(Operators, StencilRowsAnnihilateConstantsAndHaveTheNeighbourhoodPattern) {
  const Mesh m = test::open_cylinder(20, 8, 1.0, 1.0);
  const Evaluated e = evaluate(m);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m.num_vertices());
  EXPECT_LT((e.ops.laplace * ones).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((e.ops.giaquinta * ones).cwiseAbs().maxCoeff(), 1e-10);
  for (int i = 0; i < m.num_vertices(); ++i) {
    std::vector<int> expected(e.fits.neighbours.row(i).begin(), e.fits.neighbours.row(i).end());
    expected.insert(std::lower_bound(expected.begin(), expected.end(), i), i);
    std::vector<int> actual;
    for (SparseRowMatrix::InnerIterator it(e.ops.gradient[1], i); it; ++it) actual.push_back(it.index());
    ASSERT_EQ(actual, expected) << i;
  }
}

TEST(Operators, DiscreteIdentitiesHoldToRoundOffOnBundledMeshes) {
  for (const char* name : {"spot.obj", "torus.obj", "sphere_16k.off", "blub.obj", "hemisphere.off"}) {
    const Mesh m = read_mesh(test::data_path(name));
    const Evaluated e = evaluate(m);
    const double H2 = e.ops.geometry.H.cwiseAbs2().maxCoeff();
    const double laplace = identity_defect(e.ops.laplace, e.ops.geometry.H, e, m.V, 0.0);
    const double giaquinta = identity_defect(e.ops.giaquinta, e.ops.geometry.K, e, m.V, 2.0 * H2);
    const auto counts = e.fits.status_counts();
    std::printf("[identity] %s: |L∆x − 2Hn| %.2e, |L□x − 2Kn| %.2e (relative), %d of %d fits ok\n",
                name, laplace, giaquinta, counts[0], m.num_vertices());
    EXPECT_LT(laplace, 1e-12) << name;
    EXPECT_LT(giaquinta, 1e-12) << name;
    EXPECT_GT(counts[0], 0.99 * m.num_vertices()) << name;
  }
}

TEST(Operators, FrozenStencilLinearizationMissesTheMetricTermOfTheFirstVariation) {
  // With refitted stencils, δH = (2H² − K)d + ½∆d (method.md §1), while the frozen-stencil ½A_H d is
  // ½∆d − (2H² − K)d (the stencil's metric does not see the normal motion, and n·∆n = −(4H² − 2K)).
  // Measured here so that the flow can rely on the difference: δH − ½A_H d = 2(2H² − K)d + O(h²).
  const Mesh m = test::icosphere(4, 1.0);
  Evaluated e = evaluate(m);
  SparseRowMatrix A_H;
  normal_weighted(e.ops.laplace, e.ops.geometry.normal, A_H);
  Eigen::VectorXd d(m.num_vertices());
  for (int i = 0; i < d.size(); ++i) d[i] = 1.0 + 0.5 * m.V(i, 2);
  const double eps = 1e-6;
  const Vertices moved = m.V + eps * d.asDiagonal() * e.ops.geometry.normal;
  refit_quadratics(e.fits, moved);
  const SurfaceGeometry g = compute_geometry(e.fits, moved);
  const Eigen::VectorXd& H = e.ops.geometry.H;
  const Eigen::VectorXd& K = e.ops.geometry.K;
  const Eigen::VectorXd dH = (g.H - H) / eps;
  const Eigen::VectorXd metric = 2.0 * (2.0 * H.array().square() - K.array()).matrix().cwiseProduct(d);
  const Eigen::VectorXd half_AHd = 0.5 * (A_H * d);
  EXPECT_LT((dH - half_AHd - metric).cwiseAbs().maxCoeff(), 1e-2);
  EXPECT_GT((dH - half_AHd).cwiseAbs().minCoeff(), 0.5);  // the term is not small
}
