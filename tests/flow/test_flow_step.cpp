// The flow's Jacobian assembly (src/flow/flow_step.cpp): the symbolic-once, in-place assembly of J_FF
// against the plain Eigen sparse products of the formulas in flow.h, for the sixth-order flow with
// two functions and for the three baselines, on a jittered sphere with a partial free region; the
// pattern must stay identical between steps (the solver keeps its analysis) and have the 3-ring
// stencil's 37 non-zeros a row on a valence-6 grid.
#include "../src/flow/flow_step.h"

#include "analytic_meshes.h"

#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace fairsurf {
namespace {

using flow_detail::FlowProblem;
using flow_detail::FlowState;
using flow_detail::JacobianWorkspace;

SparseRowMatrix diagonal(const Eigen::VectorXd& values) {
  SparseRowMatrix D(values.size(), values.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < values.size(); ++i) entries.emplace_back(i, i, values[i]);
  D.setFromTriplets(entries.begin(), entries.end());
  return D;
}

// #F by #V: row k picks free vertex k.
SparseRowMatrix selection(const Region& region, int num_vertices) {
  SparseRowMatrix S(region.num_free(), num_vertices);
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < region.num_free(); ++k) entries.emplace_back(k, region.free_vertices[k], 1.0);
  S.setFromTriplets(entries.begin(), entries.end());
  return S;
}

// J_FF by the formulas of flow.h, one Eigen sparse product at a time.
Eigen::MatrixXd reference_jacobian(const FlowProblem& problem, const FlowState& state) {
  const SurfaceOperators& ops = state.ops;
  const SparseRowMatrix& L = ops.laplace;
  const int n = static_cast<int>(L.rows());
  const SparseRowMatrix S = selection(*problem.region, n);
  const SparseRowMatrix St = S.transpose();
  SparseRowMatrix A_H, A_K;
  normal_weighted(L, ops.geometry.normal, A_H);
  normal_weighted(ops.giaquinta, ops.geometry.normal, A_K);
  SparseRowMatrix J(S.rows(), S.rows());
  switch (problem.kind) {
    case FlowKind::sixth_order:
      for (const EnergyTerms& t : state.evaluation.terms) {
        const SparseRowMatrix R = SparseRowMatrix(L * diagonal(t.values.f_H)) +
                                 2.0 * SparseRowMatrix(ops.giaquinta * diagonal(t.values.f_K)) +
                                 diagonal(euler_lagrange_factor(ops.geometry, t.values));
        SparseRowMatrix W(n, n);
        for (int k = 0; k < 3; ++k) {
          const Eigen::VectorXd w = 2.0 * ops.geometry.H.cwiseProduct(t.gradient_f.col(k)) -
                                    2.0 * t.second_gradient_f.col(k);
          W += SparseRowMatrix(diagonal(w) * ops.gradient[k]);
        }
        const SparseRowMatrix P = SparseRowMatrix(R * L) - W;
        const SparseRowMatrix Q = SparseRowMatrix(0.5 * diagonal(t.values.f_H) * A_H) +
                                 SparseRowMatrix(diagonal(t.values.f_K) * A_K);
        J += SparseRowMatrix(SparseRowMatrix(S * P) * SparseRowMatrix(Q * St));
      }
      break;
    case FlowKind::mean_curvature: J = SparseRowMatrix(S * A_H) * St; break;
    case FlowKind::surface_diffusion:
    case FlowKind::willmore: J = -0.5 * SparseRowMatrix(S * L) * SparseRowMatrix(A_H * St); break;
  }
  return Eigen::MatrixXd(J);
}

struct Case {
  Mesh mesh;
  Topology topo;
  Region region;
  FlowProblem problem;
  FlowState state;
};

void prepare(Case& s, FlowKind kind, const std::vector<int>& free) {
  s.topo = build_topology(s.mesh.F, static_cast<int>(s.mesh.V.rows()));
  s.region = make_region(s.topo, free);
  s.problem.kind = kind;
  s.problem.region = &s.region;
  s.problem.energy_weight = Eigen::VectorXd::Ones(s.mesh.V.rows());
  flow_detail::initialize_geometry(s.mesh.V, s.mesh.F, s.topo, FitOptions{}, {}, s.state);
  if (kind == FlowKind::sixth_order) {
    s.problem.functions = parse_energy_functions({"H", "K"});
    s.problem.scale.curvature = curvature_scale(s.state.ops.geometry.H, s.state.ops.geometry.K);
  }
  flow_detail::evaluate_flow_terms(s.problem, s.state);
}

// max |J − J_ref| / max |J_ref| of the in-place assembly.
double relative_gap(const SparseRowMatrix& J, const Eigen::MatrixXd& reference) {
  return (Eigen::MatrixXd(J) - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

class JacobianAssembly : public ::testing::TestWithParam<FlowKind> {};

TEST_P(JacobianAssembly, MatchesSparseProductsAndKeepsPatternBetweenSteps) {
  const FlowKind kind = GetParam();
  Case s;
  s.mesh = test::jittered_sphere(3, 1.0, 0.3);
  std::vector<int> free;
  for (int v = 0; v < s.mesh.V.rows(); ++v)
    if (s.mesh.V(v, 2) > 0.3) free.push_back(v);
  prepare(s, kind, free);

  JacobianWorkspace work;
  SparseRowMatrix J;
  flow_detail::assemble_jacobian(s.problem, s.state, work, J);
  const double gap = relative_gap(J, reference_jacobian(s.problem, s.state));
  ASSERT_EQ(J.rows(), s.region.num_free());
  EXPECT_TRUE(J.isCompressed());

  // A second state at moved positions (same connectivity): same pattern, new values.
  const std::vector<int> outer(J.outerIndexPtr(), J.outerIndexPtr() + J.rows() + 1);
  const std::vector<int> inner(J.innerIndexPtr(), J.innerIndexPtr() + J.nonZeros());
  const Eigen::VectorXd before = Eigen::Map<const Eigen::VectorXd>(J.valuePtr(), J.nonZeros());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> offset(-0.01, 0.01);
  Vertices X = s.mesh.V;
  for (int v : free)
    for (int k = 0; k < 3; ++k) X(v, k) += offset(rng);
  flow_detail::update_geometry(X, s.state);
  flow_detail::evaluate_flow_terms(s.problem, s.state);
  flow_detail::assemble_jacobian(s.problem, s.state, work, J);
  const double moved_gap = relative_gap(J, reference_jacobian(s.problem, s.state));
  const double change =
      (Eigen::Map<const Eigen::VectorXd>(J.valuePtr(), J.nonZeros()) - before).cwiseAbs().maxCoeff();
  std::printf("[assembly] %s, %d free of %d: %.1f non-zeros a row, gap to Eigen products %.1e, "
              "%.1e after a move (values changed by %.2g)\n",
              to_string(kind), s.region.num_free(), static_cast<int>(s.mesh.V.rows()),
              static_cast<double>(J.nonZeros()) / J.rows(), gap, moved_gap, change);
  EXPECT_LT(gap, 1e-13);
  EXPECT_LT(moved_gap, 1e-13);
  EXPECT_GT(change, 0.0);
  EXPECT_TRUE(std::equal(outer.begin(), outer.end(), J.outerIndexPtr()));
  ASSERT_EQ(static_cast<Eigen::Index>(inner.size()), J.nonZeros());
  EXPECT_TRUE(std::equal(inner.begin(), inner.end(), J.innerIndexPtr()));
}

INSTANTIATE_TEST_SUITE_P(Flows, JacobianAssembly,
                         ::testing::Values(FlowKind::sixth_order, FlowKind::mean_curvature,
                                           FlowKind::surface_diffusion, FlowKind::willmore),
                         [](const auto& info) {
                           std::string name = to_string(info.param);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// On a valence-6 grid with every vertex free, J's pattern is the k-ring of the flow's order:
// 37 (3 rings), 19 (2 rings) and 7 (1 ring) non-zeros in every row.
TEST(JacobianAssembly, RingStencilOnRegularTorus) {
  for (const auto& [kind, expected] : {std::pair{FlowKind::sixth_order, 37},
                                       std::pair{FlowKind::surface_diffusion, 19},
                                       std::pair{FlowKind::mean_curvature, 7}}) {
    Case s;
    s.mesh = test::torus_grid(24, 12, 1.0, 0.4).mesh;
    std::vector<int> all(s.mesh.V.rows());
    for (int v = 0; v < static_cast<int>(all.size()); ++v) all[v] = v;
    prepare(s, kind, all);
    JacobianWorkspace work;
    SparseRowMatrix J;
    flow_detail::assemble_jacobian(s.problem, s.state, work, J);
    int smallest = static_cast<int>(J.cols()), largest = 0;
    for (int i = 0; i < J.rows(); ++i) {
      smallest = std::min(smallest, J.outerIndexPtr()[i + 1] - J.outerIndexPtr()[i]);
      largest = std::max(largest, J.outerIndexPtr()[i + 1] - J.outerIndexPtr()[i]);
    }
    std::printf("[assembly] %s on a 24 by 12 torus grid: %d to %d non-zeros a row\n", to_string(kind),
                smallest, largest);
    EXPECT_EQ(smallest, expected);
    EXPECT_EQ(largest, expected);
    EXPECT_LT(relative_gap(J, reference_jacobian(s.problem, s.state)), 1e-13);
  }
}

}  // namespace
}  // namespace fairsurf
