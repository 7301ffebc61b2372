// fairsurf — measuring the continuity reached across the border of a faired region (method.md §6, §8).
//
// At every border vertex (a fixed vertex with a free neighbour) two one-sided fits are compared: one
// on the faces that touch the free region, one on the faces that do not. Each side sees the vertex
// as a mesh-border vertex and fits its 2-ring (method.md §3.1), so the two normals and mean curvatures
// are the surface's one-sided limits. G1 shows as a small normal angle, G2 as a small jump in H too.
#pragma once

#include <fairsurf/mesh/continuity.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <span>

namespace fairsurf {

struct ContinuityMeasure {
  int border_vertices = 0;         ///< fixed vertices adjacent to the free region that were measured
  double max_normal_angle = 0;     ///< radians, between the one-sided normals
  double mean_normal_angle = 0;    ///< radians
  double max_mean_curvature_jump = 0;   ///< |H_inside − H_outside|, 1/length
  double mean_mean_curvature_jump = 0;  ///< 1/length
};

/// Measures the one-sided normals and mean curvatures at the border of `free_vertices` on (V, F):
/// at every border vertex, or only at those listed in `at` when it is not empty (one border of a
/// region that has several, e.g. one loop of a blend). Border vertices where either side's fit is
/// ill-posed are skipped (not counted). Throws InvalidArgument for a vertex of `at` out of range.
ContinuityMeasure measure_continuity(const Vertices& V, const Faces& F, std::span<const int> free_vertices,
                                     std::span<const int> at = {});
/// The same on `topo`, the connectivity of F (build_topology), instead of building it again: the two
/// sides' connectivities derive from it (derive_topology). Throws InvalidArgument if `topo` is not
/// over #V vertices and #F faces.
ContinuityMeasure measure_continuity(const Vertices& V, const Faces& F, const Topology& topo,
                                     std::span<const int> free_vertices, std::span<const int> at = {});

}  // namespace fairsurf
