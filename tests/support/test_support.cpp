#include "test_support.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

#include <fstream>
#include <sstream>

namespace fairsurf::test {

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

Mesh tetrahedron() {
  Mesh m;
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.F.resize(4, 3);
  m.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  return m;
}

std::string data_path(const std::string& name) { return std::string(FAIRSURF_DATA_DIR) + "/" + name; }

std::string cli_path() { return FAIRSURF_CLI; }

CliRun run_cli(const std::string& arguments) {
  CliRun run;
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "'" + string + ... at -O2.
  const std::string command = std::string("'").append(cli_path()).append("' ") + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

Mesh regular_grid(int nx, int ny, double h) {
  Mesh m;
  m.V.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.V.row(j * (nx + 1) + i) << i * h, j * h, 0.0;
  m.F.resize(2 * nx * ny, 3);
  int f = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      m.F.row(f++) << a, b, d;  // counter-clockwise seen from +z
      m.F.row(f++) << a, d, c;
    }
  return m;
}

std::vector<int> ball_vertices(const Mesh& mesh, const Eigen::Vector3d& centre, double radius) {
  std::vector<int> inside;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if ((mesh.V.row(v).transpose() - centre).norm() <= radius) inside.push_back(v);
  return inside;
}

}  // namespace fairsurf::test
