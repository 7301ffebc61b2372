// Test support shared by every test program: paths to bundled data and the CLI, and small
// generated meshes. Analytic-surface generators for the numerical tests live beside this file.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <filesystem>
#include <string>
#include <vector>

namespace fairsurf::test {

/// Absolute path of a mesh bundled in the repository's data/ folder.
std::string data_path(const std::string& name);

/// Absolute path of the built `fairsurf` CLI.
std::string cli_path();

/// The outcome of one CLI run.
struct CliRun {
  int exit_code = -1;
  std::string out;  ///< standard output and standard error, interleaved as they came
};

/// Runs the CLI with `arguments` (a shell-quoted string), capturing stdout and stderr together.
CliRun run_cli(const std::string& arguments);

/// The whole content of a file as bytes ("" if it cannot be read).
std::string read_bytes(const std::filesystem::path& path);

/// A closed, outward-oriented tetrahedron on the origin and the three unit points.
Mesh tetrahedron();

/// A planar (nx+1) by (ny+1) vertex grid on [0, nx*h] x [0, ny*h], every quad split along the
/// same diagonal, so that interior vertices have valence 6. Vertex (i, j) has index j*(nx+1)+i.
Mesh regular_grid(int nx, int ny, double h = 1.0);

/// The vertices of `mesh` in the closed ball (centre, radius), in index order.
std::vector<int> ball_vertices(const Mesh& mesh, const Eigen::Vector3d& centre, double radius);

}  // namespace fairsurf::test
