// One sixth-order step (f = H) of run_flow on regular torus grids (R = 1, r = 0.4, valence 6) of about
// 10k, 41k, 100k and 164k vertices, with the phases of the step timed separately from its StepRecord:
// fits + operators + energy at the trial state, assembly of J (pattern built once, values in place)
// and I − τJ, factorization, solve. Each case flows two steps at a fixed τ = 1e-7 (unit-diagonal
// units; r = 0.1 there, so τ = 0.1 r⁶ and τ/h⁶ ≈ 1e7 at 100k) and reports the second, so the one-off
// analysis, symbolic assembly and first fits are excluded; the first step's factorize time
// (analysis included) is printed beside. Each case runs in a forked child, so that VmHWM is the
// case's own peak memory; the child's CPU seconds (both steps, all threads) and the load average
// before the case are printed too: on the shared 2-core machine wall times follow the load.
// Then the scaling exponents of the step time and peak memory (pairwise and a least-squares fit)
// and their extrapolation to 1M vertices. `bench_flow --million` also runs a 1,024,000-vertex grid
// (about 13 GB peak, as MUMPS needs about 6 GB at 655k unknowns, method.md §5): by default it is not
// run, since the machine is shared. Then the 100k case with a frozen Jacobian
// (FlowOptions::refactor_interval = 2: the second step reuses the first one's factorization). Last,
// the same 10k step with GMRES + ILUT at the default options and at the smaller fill of the first version, and with UMFPACK.
#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/errors.h>

#include "process_memory.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace fairsurf;

Mesh torus(int n, int m) {
  const double R = 1.0, r = 0.4;
  Mesh mesh;
  mesh.V.resize(n * m, 3);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2.0 * std::numbers::pi * i / n, v = 2.0 * std::numbers::pi * j / m;
      mesh.V.row(j * n + i) << (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
          r * std::sin(v);
    }
  mesh.F.resize(2 * n * m, 3);
  int f = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * n + i, b = j * n + (i + 1) % n, c = ((j + 1) % m) * n + i,
                d = ((j + 1) % m) * n + (i + 1) % n;
      mesh.F.row(f++) << a, b, d;
      mesh.F.row(f++) << a, d, c;
    }
  return mesh;
}

// GMRES + ILUT with the smaller fill of the first version's defaults (20, drop 1e-5, GMRES target
// 1e-12), which stalls near a relative residual of 1e-4 on this step: method.md §5 says ILU needs
// near-complete fill on this matrix; the defaults now are fill 40, drop 1e-6, target 1e-8.
constexpr int kSmallFill = 20;
constexpr double kSmallFillDrop = 1e-5;
constexpr double kSmallFillGmresTolerance = 1e-12;

// What a case's child reports to the parent.
struct CaseFigures {
  double step_seconds = NAN;
  double peak_megabytes = NAN;
};

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five;
  in >> one >> five;
  return one + " " + five;
}

double cpu_seconds() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Runs two steps and prints one line (the failing step's figures and message if a step fails);
// writes the figures to `out_fd`; the exit code says whether the second step was accepted.
int run_case(int n, int m, FlowOptions o, const char* label, int out_fd) {
  Mesh mesh = torus(n, m);
  o.tau = o.tau_max = 1e-7;
  o.max_steps = 2;
  o.step_control = false;  // time the step, whatever its size
  std::vector<StepRecord> records;
  std::string failure;
  try {
    run_flow(mesh.V, mesh.F, o, [&](const StepRecord& s) { records.push_back(s); });
  } catch (const Error& e) {
    failure = e.what();
  }
  const double peak = static_cast<double>(bench::peak_bytes()) / 1e6;
  if (records.empty()) {
    std::printf("%7d vertices, %-15s: failed: %s\n", n * m, label, failure.c_str());
    return 1;
  }
  const StepRecord& s = records.back();
  const double total = s.fit_seconds + s.assembly_seconds + s.factorize_seconds + s.solve_seconds;
  std::printf("%7d vertices, %-15s: step %d: fit+operators %.3f s, assembly %.3f s, factorize %.3f s "
              "(first step with analysis %.3f s), solve %.3f s, step %.3f s; ",
              n * m, label, s.step, s.fit_seconds, s.assembly_seconds, s.factorize_seconds,
              records.front().factorize_seconds, s.solve_seconds, total);
  if (failure.empty())
    std::printf("iterations %d, backward error %.1e; ", s.solver_iterations, s.backward_error);
  std::printf("peak %.0f MB; CPU %.1f s; load %s\n", peak, cpu_seconds(), load_average().c_str());
  if (!failure.empty()) std::printf("%7s  failed: %s\n", "", failure.c_str());
  std::fflush(stdout);
  const CaseFigures figures{failure.empty() ? total : NAN, peak};
  return ::write(out_fd, &figures, sizeof figures) == sizeof figures && failure.empty() ? 0 : 1;
}

// The case's figures measured in a forked child (NaN where it failed).
CaseFigures in_child(int n, int m, const FlowOptions& options, const char* label) {
  std::fflush(stdout);
  CaseFigures figures;
  int fds[2];
  if (::pipe(fds) != 0) return figures;
  const pid_t child = ::fork();
  if (child == 0) ::_exit(run_case(n, m, options, label, fds[1]));
  ::close(fds[1]);
  if (::read(fds[0], &figures, sizeof figures) != sizeof figures) figures = CaseFigures{};
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  return figures;
}

// Least-squares slope of log y against log x.
double fitted_exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += std::log(x[k]), my += std::log(y[k]);
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxy += (std::log(x[k]) - mx) * (std::log(y[k]) - my);
    sxx += (std::log(x[k]) - mx) * (std::log(x[k]) - mx);
  }
  return sxy / sxx;
}

void print_scaling(const char* what, const char* unit, const std::vector<double>& sizes,
                   const std::vector<double>& values) {
  if (sizes.size() < 2) return;
  std::printf("%s exponent:", what);
  for (std::size_t k = 1; k < sizes.size(); ++k)
    std::printf(" %.2f (%.0fk -> %.0fk)", std::log(values[k] / values[k - 1]) / std::log(sizes[k] / sizes[k - 1]),
                sizes[k - 1] / 1e3, sizes[k] / 1e3);
  const double exponent = fitted_exponent(sizes, values);
  constexpr double kMillion = 1e6;
  std::printf("; fit %.2f, extrapolated to 1M vertices: %.3g %s\n", exponent,
              values.back() * std::pow(kMillion / sizes.back(), exponent), unit);
}

}  // namespace

int main(int argc, char** argv) {
  const bool million = argc > 1 && std::string(argv[1]) == "--million";
  const char* blas_threads = std::getenv("OPENBLAS_NUM_THREADS");
  std::printf("OPENBLAS_NUM_THREADS=%s\n", blas_threads ? blas_threads : "(unset: one thread a core)");
  std::vector<std::pair<int, int>> grids = {{160, 64}, {320, 128}, {500, 200}, {640, 256}};
  if (million) grids.emplace_back(1600, 640);  // 1,024,000 vertices, ~13 GB: a quiet machine only
  std::vector<double> sizes, seconds, megabytes;
  for (const auto& [n, m] : grids) {
    const CaseFigures f = in_child(n, m, FlowOptions{}, "mumps");
    if (std::isfinite(f.step_seconds))
      sizes.push_back(n * m), seconds.push_back(f.step_seconds), megabytes.push_back(f.peak_megabytes);
  }
  print_scaling("step time", "s", sizes, seconds);
  print_scaling("peak memory", "MB", sizes, megabytes);
  // The frozen Jacobian: the second step reuses the first one's factorization (same τ).
  FlowOptions frozen;
  frozen.refactor_interval = 2;
  in_child(500, 200, frozen, "mumps, frozen J");

  FlowOptions gmres;
  gmres.solver.kind = LinearSolverKind::gmres;
  in_child(160, 64, gmres, "gmres");
  gmres.solver.ilut_fill_factor = kSmallFill;
  gmres.solver.ilut_drop_tolerance = kSmallFillDrop;
  gmres.solver.gmres_tolerance = kSmallFillGmresTolerance;
  in_child(160, 64, gmres, "gmres, fill 20");
  FlowOptions umfpack;
  umfpack.solver.kind = LinearSolverKind::umfpack;
  in_child(160, 64, umfpack, "umfpack");
  return 0;
}
