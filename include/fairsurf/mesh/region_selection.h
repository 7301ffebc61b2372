// fairsurf — ways a user marks the free region of `fairsurf fair`: a vertex-index file, a ball, or
// a per-vertex property of the input.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace fairsurf {

/// Reads 0-based vertex indices (in the input's vertex order), separated by any white space; '#'
/// starts a comment that runs to the end of the line. Returns them ascending and deduplicated.
/// Throws IoError if the file cannot be read and ParseError naming the line and the token for
/// anything that is not an integer in [0, num_vertices).
std::vector<int> read_vertex_indices(const std::filesystem::path& path, int num_vertices);

/// Vertices strictly inside the ball of `radius` around `center`, ascending.
/// Throws InvalidArgument if the radius is not positive and finite.
std::vector<int> vertices_in_ball(const Vertices& V, const Eigen::Vector3d& center, double radius);

/// Vertices whose per-vertex scalar `name` is non-zero, ascending. Throws InvalidArgument naming
/// the properties the mesh has if it has no property `name`.
std::vector<int> vertices_with_property(const Mesh& mesh, const std::string& name);

}  // namespace fairsurf
