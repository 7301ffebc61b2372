#include "flow_meshes.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <random>
#include <utility>

namespace fairsurf::test {

Mesh noisy_sphere(int level, double radius, double amplitude, unsigned seed) {
  Mesh m = icosphere(level, radius);
  const double step = amplitude * mean_edge_length(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int v = 0; v < m.V.rows(); ++v) m.V.row(v) += step * unit(rng) * m.V.row(v).normalized();
  return m;
}

Mesh noisy_torus(int n, int m, double R, double r, double amplitude, unsigned seed) {
  ParametricMesh torus = torus_grid(n, m, R, r);
  Mesh& mesh = torus.mesh;
  const double step = amplitude * mean_edge_length(mesh);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < mesh.V.rows(); ++k) {
    const double u = torus.uv(k, 0), v = torus.uv(k, 1);
    const Eigen::RowVector3d normal(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
    mesh.V.row(k) += step * unit(rng) * normal;
  }
  return mesh;
}

Mesh jittered_cylinder(int around, int along, double radius, double height, double jitter,
                       unsigned seed) {
  Mesh m = open_cylinder(around, along, radius, height);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-jitter, jitter);
  const double d_theta = 2.0 * std::numbers::pi / around, dz = height / along;
  for (int k = 0; k < m.V.rows(); ++k) {
    const double theta = std::atan2(m.V(k, 1), m.V(k, 0)) + unit(rng) * d_theta;
    const bool end = k < around || k >= along * around;
    const double z = m.V(k, 2) + (end ? 0.0 : unit(rng) * dz);
    m.V.row(k) << radius * std::cos(theta), radius * std::sin(theta), z;
  }
  return m;
}

Eigen::VectorXd sphere_distances(const Vertices& V, double radius) {
  return V.rowwise().norm().array() - radius;
}

Eigen::VectorXd torus_distances(const Vertices& V, double R, double r) {
  Eigen::VectorXd d(V.rows());
  for (int k = 0; k < V.rows(); ++k) {
    const double rho = std::hypot(V(k, 0), V(k, 1)) - R;
    d[k] = std::hypot(rho, V(k, 2)) - r;
  }
  return d;
}

Eigen::VectorXd axis_distances(const Vertices& V) { return V.leftCols<2>().rowwise().norm(); }

double enclosed_volume(const Vertices& V, const Faces& F) {
  double six_volume = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

FlowReport unsettled_flow_report(FlowStepKind kind) {
  FlowReport report;
  report.step_kind = kind;
  report.stop_reason = FlowStopReason::max_steps;
  report.accepted_steps = 2;
  report.initial_energy = 10;
  report.final_energy = 6;
  report.initial_max_velocity = 1;
  report.final_max_velocity = 5;
  for (const auto& [energy, accepted] : {std::pair(8.0, true), std::pair(9.0, false), std::pair(6.0, true)}) {
    StepRecord step;
    step.energy = energy;
    step.accepted = accepted;
    report.records.push_back(step);
  }
  return report;
}

}  // namespace fairsurf::test
