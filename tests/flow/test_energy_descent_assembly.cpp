// The energy descent's Gauss–Newton model (src/flow/energy_descent.cpp), assembled in place on a
// pattern found once, against the formulas of energy_descent.h as plain Eigen sparse products:
// N = Σ_l Σ_c B_lcᵀ B_lc and g = Σ_l Σ_c B_lcᵀ √(wA) ∇_c f_l with B_lc = √(wA) G_c Q_l S. On a jittered
// sphere with a partial free region, two functions, a watched energy that stops three rings out and
// 2-ring fits at the fixed vertices (wider stencils); then at moved positions, where the pattern
// must stay the same (the solver keeps its analysis) and the values must follow.
#include "../src/flow/energy_descent.h"

#include "analytic_meshes.h"

#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace fairsurf {
namespace {

using ColumnMatrix = Eigen::SparseMatrix<double>;

struct Reference {
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
};

Reference reference_model(const flow_detail::FlowProblem& problem, const flow_detail::FlowState& state) {
  const SurfaceOperators& ops = state.ops;
  const Region& region = *problem.region;
  const int n = static_cast<int>(ops.laplace.rows());
  ColumnMatrix S(n, region.num_free());
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < region.num_free(); ++k) entries.emplace_back(region.free_vertices[k], k, 1.0);
  S.setFromTriplets(entries.begin(), entries.end());
  SparseRowMatrix A_H, A_K;
  normal_weighted(ops.laplace, ops.geometry.normal, A_H);
  normal_weighted(ops.giaquinta, ops.geometry.normal, A_K);
  const Eigen::VectorXd root_weight = problem.energy_weight.cwiseProduct(ops.geometry.area).cwiseSqrt();
  Reference ref{Eigen::MatrixXd::Zero(region.num_free(), region.num_free()),
                Eigen::VectorXd::Zero(region.num_free())};
  for (const EnergyTerms& t : state.evaluation.terms) {
    const ColumnMatrix Q =
        ColumnMatrix((0.5 * t.values.f_H).asDiagonal() * A_H + t.values.f_K.asDiagonal() * A_K) * S;
    for (int c = 0; c < 3; ++c) {
      const ColumnMatrix B = root_weight.asDiagonal() * ColumnMatrix(ops.gradient[c]) * Q;
      ref.normal += Eigen::MatrixXd(ColumnMatrix(B.transpose() * B));
      ref.gradient += B.transpose() * root_weight.cwiseProduct(t.gradient_f.col(c));
    }
  }
  return ref;
}

double relative_gap(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference) {
  return (value - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

TEST(GaussNewtonAssembly, MatchesSparseProductsAndKeepsItsPatternBetweenStates) {
  Mesh mesh = test::jittered_sphere(3, 1.0, 0.3);
  const Topology topo = build_topology(mesh.F, static_cast<int>(mesh.V.rows()));
  std::vector<int> free;
  for (int v = 0; v < mesh.V.rows(); ++v)
    if (mesh.V(v, 2) > 0.3) free.push_back(v);
  const Region region = make_region(topo, free);
  flow_detail::FlowProblem problem;
  problem.region = &region;
  problem.energy_weight = Eigen::VectorXd::Zero(mesh.V.rows());
  const std::vector<int> watched = k_ring(topo, free, 3);
  for (int v : watched) problem.energy_weight[v] = 1.0;
  ASSERT_LT(watched.size(), static_cast<std::size_t>(mesh.V.rows()));  // some rows are not watched
  std::vector<int> fixed_rings;  // fitted over their 2-rings
  std::set_difference(watched.begin(), watched.end(), region.free_vertices.begin(), region.free_vertices.end(),
                      std::back_inserter(fixed_rings));
  flow_detail::FlowState state;
  flow_detail::initialize_geometry(mesh.V, mesh.F, topo, FitOptions{}, fixed_rings, state);
  problem.functions = parse_energy_functions({"H", "K"});
  problem.scale.curvature = curvature_scale(state.ops.geometry.H, state.ops.geometry.K);
  flow_detail::evaluate_flow_terms(problem, state);

  flow_detail::GaussNewtonModel model;
  flow_detail::assemble_gauss_newton(problem, state, model);
  Reference ref = reference_model(problem, state);
  ASSERT_EQ(model.normal.rows(), region.num_free());
  EXPECT_TRUE(model.normal.isCompressed());
  EXPECT_LT(relative_gap(Eigen::MatrixXd(model.normal), ref.normal), 1e-13);
  EXPECT_LT(relative_gap(model.gradient, ref.gradient), 1e-13);
  for (int k = 0; k < region.num_free(); ++k) {
    EXPECT_EQ(model.mass[k], state.ops.geometry.area[region.free_vertices[k]]);
    EXPECT_NE(model.normal.coeffRef(k, k), 0.0) << "diagonal entry " << k << " not stored";
  }

  const std::vector<int> outer(model.normal.outerIndexPtr(), model.normal.outerIndexPtr() + model.normal.rows() + 1);
  const std::vector<int> inner(model.normal.innerIndexPtr(),
                               model.normal.innerIndexPtr() + model.normal.nonZeros());
  const Eigen::MatrixXd before(model.normal);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> offset(-0.01, 0.01);
  Vertices X = mesh.V;
  for (int v : free)
    for (int k = 0; k < 3; ++k) X(v, k) += offset(rng);
  flow_detail::update_geometry(X, state);
  flow_detail::evaluate_flow_terms(problem, state);
  flow_detail::assemble_gauss_newton(problem, state, model);
  ref = reference_model(problem, state);
  EXPECT_LT(relative_gap(Eigen::MatrixXd(model.normal), ref.normal), 1e-13);
  EXPECT_LT(relative_gap(model.gradient, ref.gradient), 1e-13);
  EXPECT_GT((Eigen::MatrixXd(model.normal) - before).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_TRUE(std::equal(outer.begin(), outer.end(), model.normal.outerIndexPtr()));
  ASSERT_EQ(static_cast<Eigen::Index>(inner.size()), model.normal.nonZeros());
  EXPECT_TRUE(std::equal(inner.begin(), inner.end(), model.normal.innerIndexPtr()));
}

}  // namespace
}  // namespace fairsurf
