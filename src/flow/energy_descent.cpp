#include "energy_descent.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace fairsurf::flow_detail {
namespace {

// S_r per watched row and N's pattern, from the operators' shared pattern P (ops.laplace's).
void build_pattern(const FlowProblem& problem, const SparseRowMatrix& P, GaussNewtonModel& model) {
  const Region& region = *problem.region;
  const int n = static_cast<int>(P.rows());
  const int num_free = region.num_free();
  GaussNewtonPattern& pattern = model.pattern;
  pattern = GaussNewtonPattern{};
  pattern.num_vertices = n;
  const int* outer = P.outerIndexPtr();
  const int* inner = P.innerIndexPtr();
  pattern.support_offsets.push_back(0);
  std::vector<int> row;
  std::vector<std::vector<int>> columns(num_free);  // N's pattern, row by row
  for (int r = 0; r < n; ++r) {
    if (!(problem.energy_weight[r] > 0)) continue;
    row.clear();
    for (int p = outer[r]; p < outer[r + 1]; ++p)
      for (int q = outer[inner[p]]; q < outer[inner[p] + 1]; ++q)
        if (const int f = region.free_index[inner[q]]; f >= 0) row.push_back(f);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    if (row.empty()) continue;
    pattern.rows.push_back(r);
    pattern.support.insert(pattern.support.end(), row.begin(), row.end());
    pattern.support_offsets.push_back(static_cast<int>(pattern.support.size()));
    for (int a : row) columns[a].insert(columns[a].end(), row.begin(), row.end());
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (int a = 0; a < num_free; ++a) {
    auto& c = columns[a];
    c.push_back(a);  // every diagonal entry stored, so that adding the mass keeps N's pattern
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    for (int b : c) entries.emplace_back(a, b, 0.0);
  }
  model.normal.resize(num_free, num_free);
  model.normal.setFromTriplets(entries.begin(), entries.end());
  model.normal.makeCompressed();
  model.slot.assign(num_free, -1);
  int widest = 0;
  for (std::size_t i = 0; i + 1 < pattern.support_offsets.size(); ++i)
    widest = std::max(widest, pattern.support_offsets[i + 1] - pattern.support_offsets[i]);
  model.rows_of_b.assign(3 * static_cast<std::size_t>(widest), 0.0);
}

// Adds row r of B_l0..2 (`b`: three rows of length |S_r|, S_r = `support`) to N and g.
void add_row(const double* b, std::span<const int> support, const double* weighted_gradient,
             GaussNewtonModel& model) {
  const int m = static_cast<int>(support.size());
  const int* outer = model.normal.outerIndexPtr();
  const int* inner = model.normal.innerIndexPtr();
  double* N = model.normal.valuePtr();
  for (int i = 0; i < m; ++i) {
    const int a = support[i];
    const double b0 = b[i], b1 = b[m + i], b2 = b[2 * m + i];
    model.gradient[a] += b0 * weighted_gradient[0] + b1 * weighted_gradient[1] + b2 * weighted_gradient[2];
    int p = outer[a];  // N's row a holds S_r's columns, both ascending: one merge walk
    for (int j = 0; j < m; ++j) {
      while (inner[p] != support[j]) ++p;
      N[p] += b0 * b[j] + b1 * b[m + j] + b2 * b[2 * m + j];
    }
  }
}

}  // namespace

void assemble_gauss_newton(const FlowProblem& problem, const FlowState& state, GaussNewtonModel& model) {
  const SurfaceOperators& ops = state.ops;
  const SurfaceGeometry& geo = ops.geometry;
  const Region& region = *problem.region;
  const int n = static_cast<int>(geo.area.size());
  if (problem.functions.empty())
    throw InvalidArgument("assemble_gauss_newton: the energy descent needs the sixth-order energy");
  if (model.pattern.num_vertices != n) build_pattern(problem, ops.laplace, model);
  const GaussNewtonPattern& pattern = model.pattern;

  normal_weighted(ops.laplace, geo.normal, model.A_H);
  normal_weighted(ops.giaquinta, geo.normal, model.A_K);
  const int* outer = ops.laplace.outerIndexPtr();
  const int* inner = ops.laplace.innerIndexPtr();
  const double* A_H = model.A_H.valuePtr();
  const double* A_K = model.A_K.valuePtr();
  const double* G[3] = {ops.gradient[0].valuePtr(), ops.gradient[1].valuePtr(), ops.gradient[2].valuePtr()};
  model.q.resize(ops.laplace.nonZeros());
  std::fill(model.normal.valuePtr(), model.normal.valuePtr() + model.normal.nonZeros(), 0.0);
  model.gradient.setZero(region.num_free());

  for (const EnergyTerms& terms : state.evaluation.terms) {
    // Q_l = ½ diag(f_H) A_H + diag(f_K) A_K on the shared pattern.
    for (int k = 0; k < n; ++k)
      for (int p = outer[k]; p < outer[k + 1]; ++p)
        model.q[p] = 0.5 * terms.values.f_H[k] * A_H[p] + terms.values.f_K[k] * A_K[p];
    for (std::size_t i = 0; i < pattern.rows.size(); ++i) {
      const int r = pattern.rows[i];
      const std::span<const int> support(pattern.support.data() + pattern.support_offsets[i],
                                         pattern.support.data() + pattern.support_offsets[i + 1]);
      const int m = static_cast<int>(support.size());
      for (int j = 0; j < m; ++j) model.slot[support[j]] = j;
      double* b = model.rows_of_b.data();
      std::fill(b, b + 3 * m, 0.0);
      // Row r of G_c Q_l, restricted to the free columns.
      for (int p = outer[r]; p < outer[r + 1]; ++p) {
        const int k = inner[p];
        const double g0 = G[0][p], g1 = G[1][p], g2 = G[2][p];
        for (int q = outer[k]; q < outer[k + 1]; ++q) {
          const int f = region.free_index[inner[q]];
          if (f < 0) continue;
          const int j = model.slot[f];
          b[j] += g0 * model.q[q];
          b[m + j] += g1 * model.q[q];
          b[2 * m + j] += g2 * model.q[q];
        }
      }
      const double root_weight = std::sqrt(problem.energy_weight[r] * geo.area[r]);
      for (int j = 0; j < 3 * m; ++j) b[j] *= root_weight;
      const double weighted_gradient[3] = {root_weight * terms.gradient_f(r, 0), root_weight * terms.gradient_f(r, 1),
                                           root_weight * terms.gradient_f(r, 2)};
      add_row(b, support, weighted_gradient, model);
      for (int j = 0; j < m; ++j) model.slot[support[j]] = -1;
    }
  }
  model.mass.resize(region.num_free());
  for (int k = 0; k < region.num_free(); ++k) model.mass[k] = geo.area[region.free_vertices[k]];
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
