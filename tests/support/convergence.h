// Observed convergence orders for the numerical tests (method.md §8.2).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace fairsurf::test {

/// Least-squares slope of log(error) against log(h): the observed order p in error ≈ C·h^p.
inline double observed_order(const std::vector<double>& h, const std::vector<double>& error) {
  const int n = static_cast<int>(h.size());
  double mx = 0, my = 0;
  for (int k = 0; k < n; ++k) mx += std::log(h[k]) / n, my += std::log(error[k]) / n;
  double sxy = 0, sxx = 0;
  for (int k = 0; k < n; ++k) {
    const double dx = std::log(h[k]) - mx;
    sxy += dx * (std::log(error[k]) - my);
    sxx += dx * dx;
  }
  return sxy / sxx;
}

/// Prints one line per resolution and the observed order, in the form docs/operators.md quotes.
inline double report_convergence(const std::string& what, const std::vector<int>& vertices,
                                 const std::vector<double>& h, const std::vector<double>& error) {
  const double order = observed_order(h, error);
  for (std::size_t k = 0; k < h.size(); ++k)
    std::printf("[convergence] %s: #V %d, h %.4g, error %.3e\n", what.c_str(), vertices[k], h[k],
                error[k]);
  std::printf("[convergence] %s: observed order %.2f\n", what.c_str(), order);
  return order;
}

}  // namespace fairsurf::test
