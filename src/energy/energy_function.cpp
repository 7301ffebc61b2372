// fairsurf — the f(H, K) catalogue, user formulas (muparser) and the well-posedness check.
#include <fairsurf/energy/energy_function.h>

#include <fairsurf/mesh/errors.h>

#include "parallel.h"

#include <muParser.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fairsurf {

namespace {

constexpr const char* kBuiltinNames = "H, K, H2, absHpH:p, 4absHH+2K, k1, k2";
constexpr const char* kAbsHpHPrefix = "absHpH:";
constexpr double kRelativeStep = 1e-3;  // finite-difference step, relative to the local curvature

enum class Builtin { H, K, H2, absHpH, absHH4_2K, k1, k2 };

/// √(x² + ε²): the regularized |x|.
double soft_abs(double x, double epsilon) { return std::sqrt(x * x + epsilon * epsilon); }

/// √(H² − K + ε²) with H² − K clamped at 0, and its derivatives in H and K.
struct SoftDiscriminant {
  double s, s_H, s_K;
  SoftDiscriminant(double H, double K, double epsilon)
      : s(std::sqrt(std::max(H * H - K, 0.0) + epsilon * epsilon)), s_H(H / s), s_K(-0.5 / s) {}
};

EnergyValue evaluate_builtin(Builtin kind, double p, double H, double K, double epsilon) {
  switch (kind) {
    case Builtin::H: return {H, 1.0, 0.0};
    case Builtin::K: return {K, 0.0, 1.0};
    case Builtin::H2: return {H * H, 2.0 * H, 0.0};
    case Builtin::absHpH: {  // (H² + ε²)^{p/2} H
      const double a = soft_abs(H, epsilon), ap = std::pow(a, p);
      return {ap * H, ap + p * H * H * ap / (a * a), 0.0};
    }
    case Builtin::absHH4_2K: {  // 4 √(H² + ε²) H + 2K
      const double a = soft_abs(H, epsilon);
      return {4.0 * a * H + 2.0 * K, 4.0 * a + 4.0 * H * H / a, 2.0};
    }
    case Builtin::k1: {
      const SoftDiscriminant d(H, K, epsilon);
      return {H + d.s, 1.0 + d.s_H, d.s_K};
    }
    case Builtin::k2: {
      const SoftDiscriminant d(H, K, epsilon);
      return {H - d.s, 1.0 - d.s_H, -d.s_K};
    }
  }
  return {};
}

/// One muparser instance with the variables it is bound to; one per thread.
struct FormulaSlot {
  double H = 0, K = 0, eps = 0, kappa = 1;
  mu::Parser parser;

  explicit FormulaSlot(const std::string& formula) {
    parser.DefineVar("H", &H);
    parser.DefineVar("K", &K);
    parser.DefineVar("eps", &eps);
    parser.DefineVar("kappa", &kappa);
    parser.SetExpr(formula);
  }

  double at(double h, double k) {
    H = h;
    K = k;
    return parser.Eval();
  }

  /// f and its five-point central differences (exact for polynomials of degree ≤ 4).
  EnergyValue evaluate(double h, double k, const EnergyScale& scale) {
    eps = scale.epsilon();
    kappa = scale.curvature;
    const double m = std::max({std::abs(h), std::sqrt(std::abs(k)), scale.curvature});
    const double dh = kRelativeStep * m, dk = kRelativeStep * m * m;
    const auto derivative = [](double f2m, double f1m, double f1p, double f2p, double step) {
      return (f2m - 8.0 * f1m + 8.0 * f1p - f2p) / (12.0 * step);
    };
    EnergyValue v;
    v.f_H = derivative(at(h - 2 * dh, k), at(h - dh, k), at(h + dh, k), at(h + 2 * dh, k), dh);
    v.f_K = derivative(at(h, k - 2 * dk), at(h, k - dk), at(h, k + dk), at(h, k + 2 * dk), dk);
    v.f = at(h, k);
    return v;
  }
};

std::string describe(const EnergyValue& v) {
  std::ostringstream out;
  out << "f = " << v.f << ", f_H = " << v.f_H << ", f_K = " << v.f_K;
  return out.str();
}

bool is_finite(const EnergyValue& v) {
  return std::isfinite(v.f) && std::isfinite(v.f_H) && std::isfinite(v.f_K);
}

void check_scale(const EnergyScale& scale, const char* function) {
  if (!(scale.curvature > 0) || !std::isfinite(scale.curvature) || !(scale.relative_epsilon >= 0))
    throw InvalidArgument(std::string(function) +
                          ": the curvature scale must be positive and the relative epsilon non-negative");
}

}  // namespace

struct EnergyFunction::Impl {
  std::string spec;
  bool formula = false;
  Builtin builtin = Builtin::H;
  double exponent = 0;                              // absHpH only
  std::vector<std::unique_ptr<FormulaSlot>> slots;  // formulas only: one per OpenMP thread

  EnergyValue at(double H, double K, const EnergyScale& scale, int thread) const {
    return formula ? slots[thread]->evaluate(H, K, scale)
                   : evaluate_builtin(builtin, exponent, H, K, scale.epsilon());
  }
};

EnergyFunction::EnergyFunction(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
EnergyFunction::EnergyFunction(const EnergyFunction& other)
    : EnergyFunction(parse_energy_function(other.spec())) {}
EnergyFunction::EnergyFunction(EnergyFunction&& other) noexcept = default;
EnergyFunction& EnergyFunction::operator=(const EnergyFunction& other) {
  if (this != &other) *this = parse_energy_function(other.spec());
  return *this;
}
EnergyFunction& EnergyFunction::operator=(EnergyFunction&& other) noexcept = default;
EnergyFunction::~EnergyFunction() = default;

const std::string& EnergyFunction::spec() const { return impl_->spec; }
bool EnergyFunction::is_formula() const { return impl_->formula; }

EnergyValue EnergyFunction::evaluate(double H, double K, const EnergyScale& scale) const {
  check_scale(scale, "EnergyFunction::evaluate");
  return impl_->at(H, K, scale, 0);
}

void EnergyFunction::evaluate(const Eigen::VectorXd& H, const Eigen::VectorXd& K, const EnergyScale& scale,
                              EnergyValues& out) const {
  check_scale(scale, "EnergyFunction::evaluate");
  if (H.size() != K.size())
    throw InvalidArgument("EnergyFunction::evaluate: H has " + std::to_string(H.size()) +
                          " values but K has " + std::to_string(K.size()));
  const Eigen::Index n = H.size();
  for (Eigen::VectorXd* v : {&out.f, &out.f_H, &out.f_K})
    if (v->size() != n) v->resize(n);
  const int threads = impl_->formula ? static_cast<int>(impl_->slots.size()) : omp_get_max_threads();
#pragma omp parallel for if (detail::worth_parallel(n)) num_threads(threads) schedule(static)
  for (Eigen::Index i = 0; i < n; ++i) {
    const EnergyValue v = impl_->at(H[i], K[i], scale, omp_get_thread_num());
    out.f[i] = v.f;
    out.f_H[i] = v.f_H;
    out.f_K[i] = v.f_K;
  }
  if (out.f.allFinite() && out.f_H.allFinite() && out.f_K.allFinite()) return;
  for (Eigen::Index i = 0; i < n; ++i) {
    const EnergyValue v{out.f[i], out.f_H[i], out.f_K[i]};
    if (!is_finite(v))
      throw NumericalError("EnergyFunction::evaluate: '" + spec() + "' is not finite at vertex " +
                           std::to_string(i) + " (H = " + std::to_string(H[i]) +
                           ", K = " + std::to_string(K[i]) + "): " + describe(v));
  }
}

namespace {

/// The built-in named `spec`, if it is one; throws for a malformed absHpH exponent.
bool parse_builtin(const std::string& spec, EnergyFunction::Impl& impl) {
  static const std::array<std::pair<const char*, Builtin>, 6> kPlain{{{"H", Builtin::H},
                                                                      {"K", Builtin::K},
                                                                      {"H2", Builtin::H2},
                                                                      {"4absHH+2K", Builtin::absHH4_2K},
                                                                      {"k1", Builtin::k1},
                                                                      {"k2", Builtin::k2}}};
  for (const auto& [name, kind] : kPlain)
    if (spec == name) {
      impl.builtin = kind;
      return true;
    }
  if (!spec.starts_with(kAbsHpHPrefix)) return false;
  const std::string exponent = spec.substr(std::char_traits<char>::length(kAbsHpHPrefix));
  char* end = nullptr;
  impl.exponent = std::strtod(exponent.c_str(), &end);
  if (exponent.empty() || *end != '\0' || !std::isfinite(impl.exponent))
    throw InvalidArgument("parse_energy_function: '" + spec +
                          "': the exponent p of absHpH:p must be a real number");
  impl.builtin = Builtin::absHpH;
  return true;
}

void parse_formula(const std::string& spec, EnergyFunction::Impl& impl) {
  impl.formula = true;
  try {
    const int threads = std::max(1, omp_get_max_threads());
    for (int t = 0; t < threads; ++t) impl.slots.push_back(std::make_unique<FormulaSlot>(spec));
    impl.slots.front()->at(1.0, 1.0);  // muparser parses lazily: force the syntax check now
  } catch (const mu::ParserError& e) {
    throw InvalidArgument("parse_energy_function: '" + spec + "' is neither a built-in function (" +
                          kBuiltinNames + ") nor a valid formula in H and K: " + e.GetMsg());
  }
}

}  // namespace

EnergyFunction parse_energy_function(const std::string& spec) {
  auto impl = std::make_unique<EnergyFunction::Impl>();
  impl->spec = spec;
  if (!parse_builtin(spec, *impl)) parse_formula(spec, *impl);
  return EnergyFunction(std::move(impl));
}

EnergyFunctions parse_energy_functions(const std::vector<std::string>& specs) {
  if (specs.empty()) throw InvalidArgument("parse_energy_functions: no function given");
  EnergyFunctions functions;
  functions.reserve(specs.size());
  for (const auto& spec : specs) functions.push_back(parse_energy_function(spec));
  return functions;
}

const char* builtin_energy_function_names() { return kBuiltinNames; }

double curvature_scale(const Eigen::VectorXd& H, const Eigen::VectorXd& K) {
  if (H.size() != K.size())
    throw InvalidArgument("curvature_scale: H has " + std::to_string(H.size()) + " values but K has " +
                          std::to_string(K.size()));
  if (H.size() == 0) return 1.0;
  const double mean = (2.0 * H.array().square() - K.array()).max(0.0).sqrt().mean();
  return mean > 0 && std::isfinite(mean) ? mean : 1.0;
}

namespace {

/// Coefficients of σ below this fraction of the larger one count as zero: a flow that is parabolic
/// only with an ellipticity ratio under 1e-4 is reported as violating. f = k1 alone, whose symbol
/// vanishes along one principal direction but for the regularization (ratio ≈ ε²/(H² − K)), is.
constexpr double kEllipticityFloor = 1e-4;

/// The symbol (a, b) of σ(ξ) = a ξ1² + b ξ2², scaled to max(|a|, |b|) = 1 with tiny parts zeroed.
std::array<double, 2> normalized_symbol(double a, double b) {
  const double largest = std::max(std::abs(a), std::abs(b));
  if (!(largest > 0)) return {0.0, 0.0};
  a /= largest;
  b /= largest;
  return {std::abs(a) < kEllipticityFloor ? 0.0 : a, std::abs(b) < kEllipticityFloor ? 0.0 : b};
}

/// Every σ_l vanishes on one direction ξ ≠ 0: a direction (u, v) = (ξ1², ξ2²) ≥ 0, not 0, on which
/// all the linear forms a_l u + b_l v vanish. Symbols are normalized.
bool degenerate(const std::vector<std::array<double, 2>>& symbols) {
  const auto first =
      std::find_if(symbols.begin(), symbols.end(), [](const auto& s) { return s[0] != 0 || s[1] != 0; });
  if (first == symbols.end()) return true;
  const double a = (*first)[0], b = (*first)[1];
  if (a * b > 0) return false;                    // this σ alone is definite
  const double u = std::abs(b), v = std::abs(a);  // the one direction where it vanishes
  return std::all_of(symbols.begin(), symbols.end(), [&](const auto& s) {
    return std::abs(s[0] * u + s[1] * v) <= kEllipticityFloor * (u + v);
  });
}

}  // namespace

WellPosedness check_well_posedness(const EnergyFunctions& functions, const Eigen::VectorXd& H,
                                   const Eigen::VectorXd& K, const EnergyScale& scale,
                                   std::vector<char>* violating) {
  if (H.size() != K.size())
    throw InvalidArgument("check_well_posedness: H has " + std::to_string(H.size()) + " values but K has " +
                          std::to_string(K.size()));
  const Eigen::Index n = H.size();
  std::vector<EnergyValues> values(functions.size());
  for (std::size_t l = 0; l < functions.size(); ++l) functions[l].evaluate(H, K, scale, values[l]);
  std::vector<char> flags(n, 0);
  int count = 0;
#pragma omp parallel if (detail::worth_parallel(n)) reduction(+ : count)
  {
    std::vector<std::array<double, 2>> symbols(functions.size());
#pragma omp for schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double root = std::sqrt(std::max(H[i] * H[i] - K[i], 0.0));
      const double k1 = H[i] + root, k2 = H[i] - root;
      for (std::size_t l = 0; l < functions.size(); ++l) {
        const double half_fH = 0.5 * values[l].f_H[i], fK = values[l].f_K[i];
        symbols[l] = normalized_symbol(half_fH + fK * k2, half_fH + fK * k1);
      }
      flags[i] = degenerate(symbols);
      count += flags[i];
    }
  }
  if (violating) *violating = std::move(flags);
  return {static_cast<int>(n), count};
}

}  // namespace fairsurf
