#include "energy_descent.h"

#include <fairsurf/mesh/errors.h>

#include <vector>

namespace fairsurf::flow_detail {
namespace {

using ColumnMatrix = Eigen::SparseMatrix<double>;

// #V by #F: column k selects free vertex k.
ColumnMatrix free_columns(const Region& region, int num_vertices) {
  ColumnMatrix S(num_vertices, region.num_free());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(region.free_vertices.size());
  for (int k = 0; k < region.num_free(); ++k) entries.emplace_back(region.free_vertices[k], k, 1.0);
  S.setFromTriplets(entries.begin(), entries.end());
  return S;
}

}  // namespace

void assemble_gauss_newton(const FlowProblem& problem, const FlowState& state, GaussNewtonModel& model) {
  const SurfaceOperators& ops = state.ops;
  const SurfaceGeometry& geo = ops.geometry;
  const Region& region = *problem.region;
  const int n = static_cast<int>(geo.area.size());
  if (problem.functions.empty())
    throw InvalidArgument("assemble_gauss_newton: the energy descent needs the sixth-order energy");

  SparseRowMatrix A_H, A_K;
  normal_weighted(ops.laplace, geo.normal, A_H);
  normal_weighted(ops.giaquinta, geo.normal, A_K);
  const ColumnMatrix S = free_columns(region, n);
  const Eigen::VectorXd weight = problem.energy_weight.cwiseProduct(geo.area);
  const Eigen::VectorXd root_weight = weight.cwiseSqrt();

  ColumnMatrix N(region.num_free(), region.num_free());
  Eigen::VectorXd g = Eigen::VectorXd::Zero(region.num_free());
  for (const EnergyTerms& terms : state.evaluation.terms) {
    const Eigen::VectorXd& f_H = terms.values.f_H;
    const Eigen::VectorXd& f_K = terms.values.f_K;
    const ColumnMatrix Q_free =
        ColumnMatrix((0.5 * f_H).asDiagonal() * A_H + f_K.asDiagonal() * A_K) * S;
    for (int c = 0; c < 3; ++c) {
      const ColumnMatrix B = root_weight.asDiagonal() * ColumnMatrix(ops.gradient[c]) * Q_free;
      N += ColumnMatrix(B.transpose() * B);
      g += B.transpose() * root_weight.cwiseProduct(terms.gradient_f.col(c));
    }
  }
  model.mass.resize(region.num_free());
  for (int k = 0; k < region.num_free(); ++k) model.mass[k] = geo.area[region.free_vertices[k]];
  // Every diagonal entry stored, so that adding the mass keeps N's pattern.
  ColumnMatrix identity(region.num_free(), region.num_free());
  identity.setIdentity();
  model.normal = N + 0.0 * identity;
  model.normal.makeCompressed();
  model.gradient = g;
}

void form_descent_matrix(const GaussNewtonModel& model, double tau, SparseRowMatrix& step) {
  if (step.rows() != model.normal.rows() || step.nonZeros() != model.normal.nonZeros()) step = model.normal;
  const int* outer = model.normal.outerIndexPtr();
  const int* inner = model.normal.innerIndexPtr();
  const double* values = model.normal.valuePtr();
  double* out = step.valuePtr();
  for (Eigen::Index i = 0; i < model.normal.rows(); ++i)
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      out[p] = values[p] + (inner[p] == i ? model.mass[i] / (2 * tau) : 0.0);
}

}  // namespace fairsurf::flow_detail
