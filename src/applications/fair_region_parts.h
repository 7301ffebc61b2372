// A free region in parts whose fixed rings do not meet, faired part by part (fair_region.h,
// FairRegionReport::parts), without what of it has no fixed vertex to be faired against.
#pragma once

#include <fairsurf/applications/fair_region.h>
#include <fairsurf/mesh/topology.h>

#include <functional>
#include <span>

namespace fairsurf::fair_detail {

/// Fairs one part of a region on the mesh (fair_region's whole fairing, with its checks).
using PartFairing = std::function<FairRegionReport(std::span<const int> part)>;

/// `fair_part` on the region itself where it is one part (or holds an index out of range, which
/// fair_part reports), else on each of its region_parts in turn, their reports combined
/// (FairRegionReport::parts). A part whose fair_part throws NumericalError is put back where it was
/// given, the others are faired, and then NumericalError names the parts that failed.
/// `mesh`, `topo`: the mesh being faired and its connectivity. Free
/// vertices with no fixed vertex in their connected component of the mesh (a vertex no face uses, a
/// component marked whole) are left out and named at the start of the note; InvalidArgument where
/// that leaves nothing (fair_region.h).
FairRegionReport fair_in_parts(Mesh& mesh, const Topology& topo, std::span<const int> free_vertices,
                               const FairRegionOptions& options, const PartFairing& fair_part);

}  // namespace fairsurf::fair_detail
