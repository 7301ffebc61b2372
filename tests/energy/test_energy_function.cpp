#include <fairsurf/energy/energy_function.h>
#include <fairsurf/mesh/errors.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace fairsurf;

namespace {

struct Point {
  double H, K;
};

/// Random (H, K) with |H| ≥ 0.05 and H² − K ≥ 0.01 (away from the points the regularization smooths).
std::vector<Point> sample_points(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> h(0.05, 2.0), gap(0.01, 3.0), sign(-1.0, 1.0);
  std::vector<Point> points;
  for (int i = 0; i < count; ++i) {
    const double H = (sign(rng) < 0 ? -1 : 1) * h(rng);
    points.push_back({H, H * H - gap(rng)});
  }
  return points;
}

/// Central difference of f along H or K with a small fixed step.
double central_difference(const EnergyFunction& fn, Point p, bool along_H, const EnergyScale& scale) {
  const double step = 1e-6;
  const auto f = [&](double dh, double dk) { return fn.evaluate(p.H + dh, p.K + dk, scale).f; };
  return along_H ? (f(step, 0) - f(-step, 0)) / (2 * step) : (f(0, step) - f(0, -step)) / (2 * step);
}

std::string parse_error(const std::string& spec) {
  try {
    parse_energy_function(spec);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no exception";
}

}  // namespace

TEST(EnergyFunction, BuiltinDerivativesMatchFiniteDifferences) {
  const EnergyScale scale{1.0, 1e-3};
  const std::vector<std::string> names = {"H",          "K",          "H2",       "absHpH:-0.5",
                                          "absHpH:0.2", "absHpH:0.5", "absHpH:1", "absHpH:2.7",
                                          "4absHH+2K",  "k1",         "k2"};
  for (const auto& name : names) {
    const EnergyFunction fn = parse_energy_function(name);
    EXPECT_FALSE(fn.is_formula()) << name;
    for (const Point& p : sample_points(200, 1)) {
      const EnergyValue v = fn.evaluate(p.H, p.K, scale);
      EXPECT_NEAR(v.f_H, central_difference(fn, p, true, scale), 1e-6 * (1 + std::abs(v.f_H)))
          << name << " at H = " << p.H << ", K = " << p.K;
      EXPECT_NEAR(v.f_K, central_difference(fn, p, false, scale), 1e-6 * (1 + std::abs(v.f_K)))
          << name << " at H = " << p.H << ", K = " << p.K;
    }
  }
}

TEST(EnergyFunction, BuiltinValuesAreTheCatalogueAndRegularizeAsDocumented) {
  const EnergyScale exact{1.0, 0.0};
  for (const Point& p : sample_points(50, 2)) {
    const double root = std::sqrt(p.H * p.H - p.K);
    EXPECT_DOUBLE_EQ(parse_energy_function("H").evaluate(p.H, p.K, exact).f, p.H);
    EXPECT_DOUBLE_EQ(parse_energy_function("K").evaluate(p.H, p.K, exact).f, p.K);
    EXPECT_DOUBLE_EQ(parse_energy_function("H2").evaluate(p.H, p.K, exact).f, p.H * p.H);
    EXPECT_DOUBLE_EQ(parse_energy_function("absHpH:0.5").evaluate(p.H, p.K, exact).f,
                     std::pow(std::abs(p.H), 0.5) * p.H);
    EXPECT_DOUBLE_EQ(parse_energy_function("4absHH+2K").evaluate(p.H, p.K, exact).f,
                     4 * std::abs(p.H) * p.H + 2 * p.K);
    EXPECT_DOUBLE_EQ(parse_energy_function("k1").evaluate(p.H, p.K, exact).f, p.H + root);
    EXPECT_DOUBLE_EQ(parse_energy_function("k2").evaluate(p.H, p.K, exact).f, p.H - root);
  }
  // Unit sphere (H = −1, K = 1, umbilic): k1 = k2 = −1 exactly without ε, ±ε with it.
  const EnergyScale regularized{1.0, 1e-3};
  EXPECT_DOUBLE_EQ(parse_energy_function("k1").evaluate(-1, 1, exact).f, -1.0);
  EXPECT_NEAR(parse_energy_function("k1").evaluate(-1, 1, regularized).f, -1.0 + 1e-3, 1e-15);
  EXPECT_NEAR(parse_energy_function("k2").evaluate(-1, 1, regularized).f, -1.0 - 1e-3, 1e-15);
  // At H = 0, |H|^{-1/2} H is regularized to (ε²)^{-1/4}·0 = 0 with slope ε^{-1/2}, ε = 1e-3 κ.
  const EnergyScale curved{4.0, 1e-3};
  EXPECT_DOUBLE_EQ(curved.epsilon(), 4e-3);
  const EnergyValue at_zero = parse_energy_function("absHpH:-0.5").evaluate(0, 0, curved);
  EXPECT_EQ(at_zero.f, 0.0);
  EXPECT_NEAR(at_zero.f_H, 1 / std::sqrt(4e-3), 1e-12);
}

TEST(EnergyFunction, FormulaDerivativesMatchAnalyticOnes) {
  struct Case {
    std::string formula;
    std::function<double(double, double)> f_H, f_K;
  };
  const std::vector<Case> cases = {
      {"H^3+0.5*K", [](double H, double) { return 3 * H * H; }, [](double, double) { return 0.5; }},
      {"exp(H)*sin(K)", [](double H, double K) { return std::exp(H) * std::sin(K); },
       [](double H, double K) { return std::exp(H) * std::cos(K); }},
      {"sqrt(H^2+K^2+1)", [](double H, double K) { return H / std::sqrt(H * H + K * K + 1); },
       [](double H, double K) { return K / std::sqrt(H * H + K * K + 1); }},
      {"H^2*K - K^3/3 + H^7", [](double H, double K) { return 2 * H * K + 7 * std::pow(H, 6); },
       [](double H, double K) { return H * H - K * K; }},
      {"abs(H)^0.5*H", [](double H, double) { return 1.5 * std::sqrt(std::abs(H)); },
       [](double, double) { return 0.0; }},
  };
  const EnergyScale scale{1.0, 1e-3};
  double worst = 0;
  for (const auto& c : cases) {
    const EnergyFunction fn = parse_energy_function(c.formula);
    EXPECT_TRUE(fn.is_formula());
    for (const Point& p : sample_points(200, 3)) {
      const EnergyValue v = fn.evaluate(p.H, p.K, scale);
      const double eH = std::abs(v.f_H - c.f_H(p.H, p.K)) / std::max(1.0, std::abs(c.f_H(p.H, p.K)));
      const double eK = std::abs(v.f_K - c.f_K(p.H, p.K)) / std::max(1.0, std::abs(c.f_K(p.H, p.K)));
      worst = std::max({worst, eH, eK});
      EXPECT_LT(eH, 1e-6) << c.formula << " at H = " << p.H << ", K = " << p.K;
      EXPECT_LT(eK, 1e-6) << c.formula << " at H = " << p.H << ", K = " << p.K;
    }
  }
  std::ostringstream figure;
  figure << std::scientific << worst;
  RecordProperty("worst_relative_derivative_error", figure.str());
  EXPECT_LT(worst, 1e-8);  // the documented accuracy of the five-point differences, with margin
  // The formula of a built-in agrees with it (no regularization in either).
  const EnergyScale exact{1.0, 0.0};
  const EnergyFunction formula = parse_energy_function("4*abs(H)*H + 2*K");
  const EnergyFunction builtin = parse_energy_function("4absHH+2K");
  for (const Point& p : sample_points(50, 4)) {
    EXPECT_NEAR(formula.evaluate(p.H, p.K, exact).f, builtin.evaluate(p.H, p.K, exact).f, 1e-13);
    EXPECT_NEAR(formula.evaluate(p.H, p.K, exact).f_H, builtin.evaluate(p.H, p.K, exact).f_H, 1e-8);
  }
}

TEST(EnergyFunction, FormulaCanUseTheRegularizationEpsilon) {
  const EnergyFunction fn = parse_energy_function("sqrt(H^2+eps^2)");
  const EnergyScale scale{2.0, 0.01};
  EXPECT_DOUBLE_EQ(fn.evaluate(0.0, 0.5, scale).f, 0.02);
  EXPECT_NEAR(fn.evaluate(0.3, 0.0, scale).f_H, 0.3 / std::sqrt(0.09 + 0.0004), 1e-10);
}

// K/kappa has the units of H whatever the mesh's size, so {H, K/kappa} weighs its two terms alike
// on every surface (docs/energies.md).
TEST(EnergyFunction, FormulaCanUseTheCurvatureScale) {
  const EnergyFunction fn = parse_energy_function("K/kappa");
  const EnergyScale scale{4.0, 1e-3};
  EXPECT_DOUBLE_EQ(fn.evaluate(0.3, 2.0, scale).f, 0.5);
  EXPECT_NEAR(fn.evaluate(0.3, 2.0, scale).f_K, 0.25, 1e-10);
  EXPECT_NEAR(fn.evaluate(0.3, 2.0, scale).f_H, 0.0, 1e-10);
  // Scaling a surface by s scales H by 1/s, K by 1/s² and κ by 1/s: f scales as H does.
  const double s = 10;
  EXPECT_DOUBLE_EQ(fn.evaluate(0.3 / s, 2.0 / (s * s), EnergyScale{4.0 / s, 1e-3}).f, 0.5 / s);
}

TEST(EnergyFunction, ParseErrorsArePrecise) {
  const std::string valid = "H, K, H2, absHpH:p, 4absHH+2K, k1, k2";
  EXPECT_EQ(builtin_energy_function_names(), valid);
  EXPECT_EQ(parse_error("Hx"),
            "parse_energy_function: 'Hx' is neither a built-in function (" + valid +
                ") nor a valid formula in H and K: Unexpected token \"Hx\" found at position 0.");
  EXPECT_EQ(parse_error("H+*K"),
            "parse_energy_function: 'H+*K' is neither a built-in function (" + valid +
                ") nor a valid formula in H and K: Unexpected operator \"*\" found at position 2");
  EXPECT_EQ(parse_error("(H+K"), "parse_energy_function: '(H+K' is neither a built-in function (" + valid +
                                     ") nor a valid formula in H and K: Missing parenthesis");
  EXPECT_EQ(parse_error("absHpH:x"),
            "parse_energy_function: 'absHpH:x': the exponent p of absHpH:p must be a real number");
  EXPECT_EQ(parse_error("absHpH:"),
            "parse_energy_function: 'absHpH:': the exponent p of absHpH:p must be a real number");
  try {
    parse_energy_functions({});
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "parse_energy_functions: no function given");
  }
}

TEST(EnergyFunction, ArrayEvaluationMatchesPointwiseAndReusesBuffers) {
  const auto points = sample_points(5000, 5);
  Eigen::VectorXd H(points.size()), K(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    H[i] = points[i].H;
    K[i] = points[i].K;
  }
  const EnergyScale scale{curvature_scale(H, K), 1e-3};
  for (const std::string spec : {"absHpH:0.5", "k2", "exp(H)*K+H^4"}) {
    const EnergyFunction fn = parse_energy_function(spec);
    EnergyValues values;
    fn.evaluate(H, K, scale, values);
    const double* buffer = values.f_H.data();
    fn.evaluate(H, K, scale, values);
    EXPECT_EQ(values.f_H.data(), buffer) << spec;
    for (Eigen::Index i = 0; i < H.size(); i += 7) {
      const EnergyValue v = fn.evaluate(H[i], K[i], scale);
      EXPECT_EQ(values.f[i], v.f);
      EXPECT_EQ(values.f_H[i], v.f_H);
      EXPECT_EQ(values.f_K[i], v.f_K);
    }
    const EnergyFunction copy = fn;  // a copy re-parses and evaluates alike
    EXPECT_EQ(copy.evaluate(H[3], K[3], scale).f_K, values.f_K[3]);
  }
}

TEST(EnergyFunction, NonFiniteValuesNameTheVertex) {
  const Eigen::VectorXd H = Eigen::Vector3d(0.5, 0.0, -0.5), K = Eigen::Vector3d(0.1, -0.2, 0.3);
  EnergyValues values;
  try {
    parse_energy_function("sqrt(K)").evaluate(H, K, EnergyScale{}, values);
    FAIL() << "no exception";
  } catch (const NumericalError& e) {
    EXPECT_TRUE(
        std::string(e.what()).starts_with("EnergyFunction::evaluate: 'sqrt(K)' is not finite at vertex 1 "))
        << e.what();
  }
  EXPECT_THROW(parse_energy_function("absHpH:-0.5").evaluate(H, K, EnergyScale{1.0, 0.0}, values),
               NumericalError);
  EXPECT_NO_THROW(parse_energy_function("absHpH:-0.5").evaluate(H, K, EnergyScale{1.0, 1e-3}, values));
  EXPECT_THROW(parse_energy_function("H").evaluate(H, Eigen::Vector2d(1, 2), EnergyScale{}, values),
               InvalidArgument);
  EXPECT_THROW(parse_energy_function("H").evaluate(0, 0, EnergyScale{0.0, 1e-3}), InvalidArgument);
}

TEST(EnergyFunction, CurvatureScaleIsTheMeanRmsPrincipalCurvature) {
  EXPECT_DOUBLE_EQ(curvature_scale(Eigen::VectorXd::Constant(10, -1.0), Eigen::VectorXd::Constant(10, 1.0)),
                   1.0);
  // Cylinder of radius 2: k = (0, −1/2), H = −1/4, K = 0: rms = √(1/8).
  EXPECT_DOUBLE_EQ(curvature_scale(Eigen::VectorXd::Constant(4, -0.25), Eigen::VectorXd::Zero(4)),
                   std::sqrt(0.125));
  EXPECT_DOUBLE_EQ(curvature_scale(Eigen::VectorXd::Zero(4), Eigen::VectorXd::Zero(4)), 1.0);  // flat
}

namespace {

/// H and K of the torus with radii R > r at 360 equally spaced angles v around the tube (outward
/// normal, method.md §1 signs): K = cos v / (r (R + r cos v)), H = −(R + 2 r cos v) / (2 r (R + r cos v)).
void torus_curvatures(double R, double r, Eigen::VectorXd& H, Eigen::VectorXd& K) {
  const int n = 360;
  H.resize(n);
  K.resize(n);
  for (int i = 0; i < n; ++i) {
    const double c = std::cos(2 * std::numbers::pi * (i + 0.5) / n);
    K[i] = c / (r * (R + r * c));
    H[i] = -(R + 2 * r * c) / (2 * r * (R + r * c));
  }
}

int violations(const std::vector<std::string>& specs, const Eigen::VectorXd& H, const Eigen::VectorXd& K,
               std::vector<char>* flags = nullptr) {
  return check_well_posedness(parse_energy_functions(specs), H, K, EnergyScale{curvature_scale(H, K), 1e-3},
                              flags)
      .violating_vertices;
}

}  // namespace

TEST(EnergyFunction, WellPosednessOnATorus) {
  Eigen::VectorXd H, K;
  torus_curvatures(2.0, 1.0, H, K);
  const int non_positive = static_cast<int>((K.array() <= 0).count());
  ASSERT_EQ(non_positive, 180);
  EXPECT_EQ(violations({"H"}, H, K), 0);
  EXPECT_EQ(violations({"-H"}, H, K), 0);  // the sign of f does not matter
  EXPECT_EQ(violations({"H", "K"}, H, K), 0);
  EXPECT_EQ(violations({"k1", "k2"}, H, K), 0);
  EXPECT_EQ(violations({"absHpH:0.5"}, H, K), 0);
  std::vector<char> flags;
  EXPECT_EQ(violations({"K"}, H, K, &flags), non_positive);
  for (Eigen::Index i = 0; i < K.size(); ++i) EXPECT_EQ(flags[i], K[i] <= 0 ? 1 : 0) << "K = " << K[i];
  // k1 alone: its symbol vanishes along one principal direction everywhere (up to ε).
  EXPECT_EQ(violations({"k1"}, H, K), static_cast<int>(H.size()));
  const WellPosedness w =
      check_well_posedness(parse_energy_functions({"K"}), H, K, EnergyScale{curvature_scale(H, K), 1e-3});
  EXPECT_EQ(w.vertices, 360);
  EXPECT_DOUBLE_EQ(w.fraction(), 0.5);
}

TEST(EnergyFunction, WellPosednessOnASphereAndWhereTheSufficientConditionFails) {
  // Unit sphere: H = −1, K = 1. f = K is parabolic (K > 0) although |f_K k_i| = 1 > f_H/2 = 0.
  const Eigen::VectorXd H = Eigen::VectorXd::Constant(5, -1.0), K = Eigen::VectorXd::Constant(5, 1.0);
  EXPECT_EQ(violations({"K"}, H, K), 0);
  EXPECT_EQ(violations({"H"}, H, K), 0);
  // f = H + 2K on the unit sphere: ½f_H + f_K k = ½ − 2 < 0 for both k: parabolic.
  EXPECT_EQ(violations({"H+2*K"}, H, K), 0);
  // f = H − K on a saddle with k = ±1 (H = 0, K = −1): ½ ∓ 1 change sign: ill-posed.
  EXPECT_EQ(violations({"H-K"}, Eigen::VectorXd::Zero(3), Eigen::VectorXd::Constant(3, -1.0)), 3);
  // f = H2 vanishes to first order where H = 0 only.
  EXPECT_EQ(violations({"H2"}, Eigen::Vector3d(0.0, 0.5, -0.5), Eigen::Vector3d(-1.0, 0.1, 0.1)), 1);
}
