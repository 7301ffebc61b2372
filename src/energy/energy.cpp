#include <fairsurf/energy/energy.h>
#include <fairsurf/mesh/errors.h>

namespace fairsurf {
namespace {

void resize_if_needed(Eigen::VectorXd& v, Eigen::Index n) {
  if (v.size() != n) v.resize(n);
}
void resize_if_needed(Eigen::MatrixX3d& m, Eigen::Index n) {
  if (m.rows() != n) m.resize(n, 3);
}

// f, ∆f, ∇f and ◇f of one function from the operators.
void evaluate_terms(const SurfaceOperators& ops, const EnergyFunction& function,
                    const EnergyScale& scale, EnergyTerms& t) {
  const SurfaceGeometry& geo = ops.geometry;
  const Eigen::Index n = geo.H.size();
  function.evaluate(geo.H, geo.K, scale, t.values);
  resize_if_needed(t.laplace_f, n);
  resize_if_needed(t.gradient_f, n);
  resize_if_needed(t.second_gradient_f, n);
  t.laplace_f.noalias() = ops.laplace * t.values.f;
  for (int c = 0; c < 3; ++c) {
    t.gradient_f.col(c).noalias() = ops.gradient[c] * t.values.f;
    t.second_gradient_f.col(c).noalias() = ops.second_gradient[c] * t.values.f;
  }
}

// EL += 2H‖∇f‖² − 2⟨∇f, ◇f⟩ − c ∆f − 2□(f_K ∆f) − ∆(f_H ∆f) for one function.
void add_euler_lagrange(const SurfaceOperators& ops, const EnergyTerms& t, Eigen::VectorXd& el) {
  const auto H = ops.geometry.H.array();
  const Eigen::VectorXd c = euler_lagrange_factor(ops.geometry, t.values);
  el.array() += 2.0 * H * t.gradient_f.rowwise().squaredNorm().array() -
                (2.0 * t.gradient_f.array() * t.second_gradient_f.array()).rowwise().sum() -
                c.array() * t.laplace_f.array();
  const Eigen::VectorXd fH_laplace = t.values.f_H.cwiseProduct(t.laplace_f);
  const Eigen::VectorXd fK_laplace = t.values.f_K.cwiseProduct(t.laplace_f);
  el.noalias() -= ops.laplace * fH_laplace;
  el.noalias() -= 2.0 * (ops.giaquinta * fK_laplace);
}

}  // namespace

Eigen::VectorXd euler_lagrange_factor(const SurfaceGeometry& geo, const EnergyValues& values) {
  const auto H = geo.H.array(), K = geo.K.array();
  return (4.0 * H * K * values.f_K.array() + 2.0 * (2.0 * H * H - K) * values.f_H.array()).matrix();
}

void evaluate_energy(const SurfaceOperators& ops, const EnergyFunctions& functions,
                     const EnergyScale& scale, EnergyEvaluation& out, bool with_euler_lagrange) {
  if (functions.empty()) throw InvalidArgument("evaluate_energy: no energy function given");
  const Eigen::Index n = ops.geometry.H.size();
  out.terms.resize(functions.size());
  resize_if_needed(out.density, n);
  out.density.setZero();
  if (with_euler_lagrange) {
    resize_if_needed(out.euler_lagrange, n);
    out.euler_lagrange.setZero();
  } else {
    out.euler_lagrange.resize(0);
  }
  for (std::size_t l = 0; l < functions.size(); ++l) {
    evaluate_terms(ops, functions[l], scale, out.terms[l]);
    out.density += out.terms[l].gradient_f.rowwise().squaredNorm();
    if (with_euler_lagrange) add_euler_lagrange(ops, out.terms[l], out.euler_lagrange);
  }
  out.energy = ops.geometry.area.dot(out.density);
}

double discrete_energy(const SurfaceOperators& ops, const EnergyFunctions& functions,
                       const EnergyScale& scale) {
  EnergyEvaluation evaluation;
  evaluate_energy(ops, functions, scale, evaluation, false);
  return evaluation.energy;
}

}  // namespace fairsurf
