#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region_selection.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace fairsurf {

std::vector<int> read_vertex_indices(const std::filesystem::path& path, int num_vertices) {
  std::ifstream in(path);
  if (!in)
    throw IoError("read_vertex_indices: " + path.string() + ": cannot open (" +
                  std::strerror(errno) + ")");
  std::vector<int> indices;
  std::string line, token;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    std::istringstream words(line.substr(0, line.find('#')));
    while (words >> token) {
      char* end = nullptr;
      errno = 0;
      const long value = std::strtol(token.c_str(), &end, 10);
      if (*end != '\0' || errno != 0 || value < 0 || value >= num_vertices)
        throw ParseError("read_vertex_indices: " + path.string() + ":" + std::to_string(line_number) +
                         ": '" + token + "' is not a vertex index in [0, " +
                         std::to_string(num_vertices) + ")");
      indices.push_back(static_cast<int>(value));
    }
  }
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  return indices;
}

std::vector<int> vertices_in_ball(const Vertices& V, const Eigen::Vector3d& center, double radius) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw InvalidArgument("vertices_in_ball: radius " + std::to_string(radius) +
                          " is not positive and finite");
  std::vector<int> inside;
  for (int v = 0; v < V.rows(); ++v)
    if ((V.row(v).transpose() - center).squaredNorm() < radius * radius) inside.push_back(v);
  return inside;
}

std::vector<int> vertices_with_property(const Mesh& mesh, const std::string& name) {
  const auto found = mesh.vertex_scalars.find(name);
  if (found == mesh.vertex_scalars.end()) {
    std::string available;
    for (const auto& [key, values] : mesh.vertex_scalars) available += (available.empty() ? "" : ", ") + key;
    throw InvalidArgument("vertices_with_property: the mesh has no vertex property '" + name +
                          "' (it has: " + (available.empty() ? "none" : available) + ")");
  }
  std::vector<int> marked;
  for (int v = 0; v < found->second.size(); ++v)
    if (found->second[v] != 0) marked.push_back(v);
  return marked;
}

}  // namespace fairsurf
