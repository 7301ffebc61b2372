// The sixth-order energy of a region as the G2 fairing watches it, measured on any positions with the
// region's connectivity: the uncut surface itself, fairsurf's result, the ∆³ baseline's or CGAL's
// (docs/real-holes.md, "The surface is not fair at the scale of a hole").
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <span>

namespace fairsurf::bench {

/// E = Σ_i A_i ‖∇H_i‖² (energy.h, f = H, from the quadratic fits of positions V, #V by 3, on faces F)
/// summed over `region` and its `rings` rings: the vertices whose energy a G2 fairing of the region
/// lowers (three fixed rings carry its boundary data). `topo`: the connectivity of F. In 1/length².
double region_energy(const Vertices& V, const Faces& F, const Topology& topo, std::span<const int> region,
                     int rings = 3);

}  // namespace fairsurf::bench
