// A free region in parts whose fixed rings do not meet, faired part by part (fair_region.h,
// FairRegionReport::parts), and what of it has no fixed vertex to be faired against (AnchoredRegion).
#pragma once

#include <fairsurf/applications/fair_region.h>
#include <fairsurf/mesh/topology.h>

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace fairsurf::fair_detail {

/// Fairs one part of a region on the mesh (fair_region's whole fairing, with its checks).
using PartFairing = std::function<FairRegionReport(std::span<const int> part)>;

/// `fair_part` on the region itself where it is one part (or holds an index out of range, which
/// fair_part reports), else on each of its region_parts in turn, their reports combined
/// (FairRegionReport::parts). `mesh`, `topo`: the mesh being faired and its connectivity.
FairRegionReport fair_in_parts(const Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                               const FairRegionOptions& options, const PartFairing& fair_part);

/// What of a marked region can be faired: the free vertices whose connected component of the mesh
/// also has a fixed vertex. A vertex no face uses (scans list some: the Stanford bunny's OBJ has
/// 1113) is not on the surface, and a component marked whole has no ring to be faired against: both
/// stay where they are, counted for fair_region's note.
struct AnchoredRegion {
  std::vector<int> free;  ///< ascending
  int loose_vertices = 0;       ///< free vertices no face uses
  int whole_components = 0;     ///< components of the mesh whose every vertex is free
  int in_whole_components = 0;  ///< their vertices
  bool complete() const { return loose_vertices == 0 && whole_components == 0; }
  /// "1 vertex on no face, 2 components of the mesh marked whole (84 vertices)".
  std::string left_out() const;
};

/// The AnchoredRegion of `free_vertices` (indices of topo's vertices, in range).
AnchoredRegion anchored_region(const Topology& topo, std::span<const int> free_vertices);

}  // namespace fairsurf::fair_detail
