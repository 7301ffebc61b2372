// Private to the repair module: the working state the operations edit in turn, the light
// adjacency they rebuild between edits, and the operations themselves (one file each).
#pragma once

#include <fairsurf/applications/repair.h>
#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <array>
#include <span>
#include <vector>

namespace fairsurf::repair_detail {

using Tri = std::array<int, 3>;

/// The mesh under repair. Working vertices are original vertices or copies of them (a split adds
/// copies); positions are always read from the input, so no operation can move a vertex.
struct Work {
  const Vertices& V;
  std::vector<int> origin;  ///< working vertex -> original vertex
  std::vector<Tri> faces;
  std::vector<int> merged_into;  ///< working vertex -> the working vertex it was merged into, or -1

  int num_vertices() const { return static_cast<int>(origin.size()); }
  Eigen::Vector3d position(int v) const { return V.row(origin[v]).transpose(); }
  int add_copy(int v) {
    origin.push_back(origin[v]);
    merged_into.push_back(-1);
    return num_vertices() - 1;
  }
};

/// Edges and vertex stars of a face list whose faces are all well formed. Corner c = 3f + k stands
/// for face f's edge from faces[f][k] to faces[f][(k+1)%3].
struct Adjacency {
  std::vector<int> corner_edge;                 ///< #corners: edge of each corner
  std::vector<int> edge_offsets{0};             ///< CSR edge -> corners, ascending
  std::vector<int> edge_corners;
  std::vector<int> vertex_offsets;              ///< CSR vertex -> faces, ascending
  std::vector<int> vertex_faces;

  int num_edges() const { return static_cast<int>(edge_offsets.size()) - 1; }
  std::span<const int> corners(int e) const {
    return {edge_corners.data() + edge_offsets[e], static_cast<std::size_t>(edge_offsets[e + 1] - edge_offsets[e])};
  }
  std::span<const int> faces_of(int v) const {
    return {vertex_faces.data() + vertex_offsets[v],
            static_cast<std::size_t>(vertex_offsets[v + 1] - vertex_offsets[v])};
  }
};
Adjacency build_adjacency(const std::vector<Tri>& faces, int num_vertices);

/// Per working vertex, whether it is on a border edge (an edge `adj` gives one face).
std::vector<char> border_vertices(const Work& work, const Adjacency& adj);

/// Mean length of the faces' edges (each face counts its three edges); 0 without faces.
double mean_edge_length(const Work& work);

/// The fans around every vertex: two faces around v belong to one fan when they are joined through
/// an edge incident to v, faces being joined at an edge when both their corners on it are flagged
/// in `corner_joined`. Returns for each corner 3f+k the fan number of faces[f][k] within that
/// vertex's star, fan 0 holding the vertex's lowest-index face.
std::vector<int> fan_numbers(const std::vector<Tri>& faces, const Adjacency& adj,
                             const std::vector<char>& corner_joined);

// The operations, in the order repair runs them. Each edits `work` and counts into `report`.
void remove_invalid_faces(Work& work, RepairReport& report);
void merge_vertices(Work& work, const RepairOptions& options, RepairReport& report);
void stitch_borders(Work& work, const RepairOptions& options, RepairReport& report);
void remove_collapsed_faces(Work& work, RepairReport& report);
void remove_duplicate_faces(Work& work, RepairReport& report);
void fix_degenerate_faces(Work& work, const RepairOptions& options, RepairReport& report);
/// `unchanged`, if given, receives the adjacency of the faces when the split changed nothing.
void split_non_manifold(Work& work, const RepairOptions& options, RepairReport& report,
                        Adjacency* unchanged = nullptr);
/// `adjacency`, if given, must describe work.faces (saves rebuilding it).
void orient_faces(Work& work, RepairReport& report, const Adjacency* adjacency = nullptr);
void remove_small_components(Work& work, int min_faces, RepairReport& report);
void remove_loose_fins(Work& work, RepairReport& report);

/// Whether face f of `work` is degenerate in validate's sense (zero or near-zero area).
bool is_degenerate(const Work& work, const Tri& f, double tolerance);

}  // namespace fairsurf::repair_detail
