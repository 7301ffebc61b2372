// One sixth-order step (f = H) of run_flow on regular torus grids (R = 1, r = 0.4, valence 6) of about
// 10k, 41k, 100k and 164k vertices, with the phases of the step timed separately from its StepRecord:
// fits + operators + energy at the trial state, assembly of J and I − τJ (Eigen sparse products),
// factorization, solve. Each case flows two steps at a fixed τ = 1e-7 (unit-diagonal units; r = 0.1 there, so τ = 0.1 r⁶ and τ/h⁶ ≈ 1e7 at 100k) and
// reports the second, so the one-off analysis and first fits are excluded; the first step's
// factorize time (analysis included) is printed beside. Each case runs in a forked child, so that
// VmHWM is the case's own peak memory. Then MUMPS against GMRES + ILUT on the 10k step.
// ~1M vertices is not run: MUMPS needs about 6 GB at 655k unknowns (METHOD §5) and the machine is
// shared; the measured exponent extrapolates it.
#include <fairsurf/errors.h>
#include <fairsurf/flow.h>

#include "process_memory.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
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

// Runs two steps and prints one line; writes the step's seconds to `out_fd`; the exit code says
// whether the second step was accepted.
int run_case(int n, int m, LinearSolverKind solver, int out_fd) {
  Mesh mesh = torus(n, m);
  FlowOptions o;
  o.tau = o.tau_max = 1e-7;
  o.max_steps = 2;
  o.solver.kind = solver;
  o.step_control.enabled = false;  // time the step, whatever its size
  std::vector<StepRecord> records;
  try {
    run_flow(mesh.V, mesh.F, o, [&](const StepRecord& s) { records.push_back(s); });
  } catch (const Error& e) {
    std::printf("%7d vertices, %-7s: failed: %s\n", n * m, to_string(solver), e.what());
    std::fflush(stdout);
    return 1;
  }
  const StepRecord& s = records.back();
  const double total = s.fit_seconds + s.assembly_seconds + s.factorize_seconds + s.solve_seconds;
  std::printf("%7d vertices, %-7s: fit+operators %.3f s, assembly %.3f s, factorize %.3f s (first "
              "step with analysis %.3f s), solve %.3f s, step %.3f s; iterations %d, backward error "
              "%.1e; peak %.0f MB\n",
              n * m, to_string(solver), s.fit_seconds, s.assembly_seconds, s.factorize_seconds,
              records.front().factorize_seconds, s.solve_seconds, total, s.solver_iterations, s.backward_error,
              static_cast<double>(bench::peak_bytes()) / 1e6);
  std::fflush(stdout);
  return ::write(out_fd, &total, sizeof total) == sizeof total ? 0 : 1;
}

// The step's seconds measured in a forked child, or NaN if it failed.
double in_child(int n, int m, LinearSolverKind solver) {
  std::fflush(stdout);
  int fds[2];
  if (::pipe(fds) != 0) return NAN;
  const pid_t child = ::fork();
  if (child == 0) ::_exit(run_case(n, m, solver, fds[1]));
  ::close(fds[1]);
  double seconds = NAN;
  if (::read(fds[0], &seconds, sizeof seconds) != sizeof seconds) seconds = NAN;
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  return seconds;
}

}  // namespace

int main() {
  const std::vector<std::pair<int, int>> grids = {{160, 64}, {320, 128}, {500, 200}, {640, 256}};
  std::vector<double> sizes, seconds;
  for (const auto& [n, m] : grids) {
    const double t = in_child(n, m, LinearSolverKind::mumps);
    if (std::isfinite(t)) sizes.push_back(n * m), seconds.push_back(t);
  }
  for (std::size_t k = 1; k < sizes.size(); ++k)
    std::printf("scaling exponent %d -> %d vertices: %.2f\n", static_cast<int>(sizes[k - 1]),
                static_cast<int>(sizes[k]), std::log(seconds[k] / seconds[k - 1]) / std::log(sizes[k] / sizes[k - 1]));
  in_child(160, 64, LinearSolverKind::gmres);
  in_child(160, 64, LinearSolverKind::umfpack);
  return 0;
}
