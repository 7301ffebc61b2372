// fairsurf — the functions f(H, K) of the energies E = Σ_l ∫ ‖∇f_l‖² dA (method.md §4).
//
// A function is named by a string (docs/energies.md has the catalogue):
//   built-ins, with exact f, f_H, f_K:  H  K  H2  absHpH:p  4absHH+2K  k1  k2
//   anything else is parsed as a formula in H and K (muparser syntax: H^3+0.5*K, exp(H)*K, ...), whose
//   f_H and f_K are central differences (see below). A formula may also use `eps`, the regularization ε,
//   and `kappa`, the curvature scale κ (so that K/kappa has the units of H).
// Signs follow method.md §1: H = ½ trace of the shape operator with the outward normal, so H = −1/R and
// K = 1/R² on a sphere of radius R; k1,2 = H ± √(H² − K), k1 ≥ k2.
//
// Regularization: singular built-ins replace |H| by √(H² + ε²) and √(H² − K) by √(H² − K + ε²), where
// ε = relative_epsilon · κ and κ is the curvature scale of the surface (EnergyScale; by default the
// mean root-mean-square principal curvature, curvature_scale()). relative_epsilon = 0 gives the exact,
// singular functions. H² − K < 0 (round-off only) is read as 0.
//
// Formula derivatives: five-point central differences with steps h_H = 1e-3 m and h_K = 1e-3 m²,
// m = max(|H|, √|K|, κ); their error is about 1e-12 of f's scale for smooth formulas.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace fairsurf {

/// The curvature scale κ (1/length) of a surface and the relative size of the regularization ε.
struct EnergyScale {
  double curvature = 1.0;          ///< κ, e.g. from curvature_scale(); must be positive
  double relative_epsilon = 1e-3;  ///< ε = relative_epsilon · κ; must be non-negative
  double epsilon() const { return relative_epsilon * curvature; }
};

/// κ = mean over vertices of √max(2H² − K, 0) = √((k1² + k2²)/2): 1 on a unit sphere. #V vectors H,
/// K. Returns 1 when the surface is flat (κ = 0), which in method.md §7's units (unit bounding-box
/// diagonal) is the curvature of a sphere about the size of the mesh.
double curvature_scale(const Eigen::VectorXd& H, const Eigen::VectorXd& K);

/// f and its partial derivatives at one point.
struct EnergyValue {
  double f = 0, f_H = 0, f_K = 0;
};

/// f, f_H and f_K at #V vertices.
struct EnergyValues {
  Eigen::VectorXd f, f_H, f_K;
};

/// One function f(H, K). Copying re-parses, so that copies can be evaluated concurrently.
/// An object itself is not safe to evaluate from several threads at once (formulas keep per-thread
/// parser state); the array evaluate() parallelizes internally.
class EnergyFunction {
 public:
  EnergyFunction(const EnergyFunction& other);
  EnergyFunction(EnergyFunction&& other) noexcept;
  EnergyFunction& operator=(const EnergyFunction& other);
  EnergyFunction& operator=(EnergyFunction&& other) noexcept;
  ~EnergyFunction();

  /// The string it was parsed from.
  const std::string& spec() const;
  /// True for a user formula, false for a built-in.
  bool is_formula() const;

  /// f, f_H, f_K at (H, K).
  EnergyValue evaluate(double H, double K, const EnergyScale& scale) const;
  /// Fills `out` (vectors resized to #V only if their size differs: no allocation in the steady
  /// state) from #V vectors H and K, in parallel. Throws InvalidArgument if H and K differ in size
  /// or the scale is invalid, NumericalError naming the first vertex where a value is not finite.
  void evaluate(const Eigen::VectorXd& H, const Eigen::VectorXd& K, const EnergyScale& scale,
                EnergyValues& out) const;

  struct Impl;  // built-in or formula; defined in src/energy/energy_function.cpp

 private:
  friend EnergyFunction parse_energy_function(const std::string& spec);
  explicit EnergyFunction(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Parses a built-in name or, if `spec` is not one, a formula in H and K. Throws InvalidArgument with
/// the valid built-in names and muparser's message (with the position) if it is neither, or if an
/// absHpH exponent is not a real number.
EnergyFunction parse_energy_function(const std::string& spec);

/// The functions of one energy, summed: E = Σ_l ∫ ‖∇f_l‖².
using EnergyFunctions = std::vector<EnergyFunction>;

/// Parses each spec; throws InvalidArgument for an empty list or an invalid spec.
EnergyFunctions parse_energy_functions(const std::vector<std::string>& specs);

/// The built-in names, for help texts: "H, K, H2, absHpH:p, 4absHH+2K, k1, k2".
const char* builtin_energy_function_names();

/// Where the flow of an energy is parabolic (method.md §4). The principal part of the flow of one f is
/// −2|ξ|²σ(ξ)² with σ(ξ) = (½f_H + f_K k2)ξ1² + (½f_H + f_K k1)ξ2² in the principal frame, so the flow
/// is parabolic where the two coefficients are non-zero with the same sign (|f_K k_i| < f_H/2 is the
/// sufficient form method.md §4 states; f = K is ill-posed exactly where K ≤ 0). For a sum of functions
/// it is parabolic unless one direction ξ makes every σ_l vanish. A coefficient below 1e-4 of the
/// larger one counts as zero, so f = k1 alone (degenerate but for the regularization) is flagged.
struct WellPosedness {
  int vertices = 0;
  int violating_vertices = 0;
  double fraction() const { return vertices > 0 ? double(violating_vertices) / vertices : 0.0; }
};

/// Counts the vertices where the flow of `functions` is not parabolic, for #V vectors H and K. If
/// `violating` is given it receives #V flags (1 = violating).
WellPosedness check_well_posedness(const EnergyFunctions& functions, const Eigen::VectorXd& H,
                                   const Eigen::VectorXd& K, const EnergyScale& scale,
                                   std::vector<char>* violating = nullptr);

}  // namespace fairsurf
