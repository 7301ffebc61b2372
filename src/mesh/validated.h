// Private: validation that hands over the connectivity it built, so that an operation which
// validates its input builds that mesh's topology once (docs/architecture.md).
#pragma once

#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include <vector>

namespace fairsurf::detail {

/// validate(mesh); `topo` receives the topology of mesh.F when every face is well formed (no
/// out-of-range index, no repeated vertex), and is left as it was otherwise.
ValidationReport validate_keeping_topology(const Mesh& mesh, Topology& topo);

/// require_valid(validate(mesh), requirements, caller), returning the topology of mesh.F that
/// validate built.
Topology validated_topology(const Mesh& mesh, const Requirements& requirements, const char* caller);

/// The border edges at each vertex (#V): more than two make the vertex a pinch of the border.
std::vector<int> border_edge_counts(const Topology& topo);

/// Takes the pinches of the border (vertices with more than two border edges) out of
/// report.non_manifold_vertices: fill_holes fills the loops through such a vertex together, and a
/// region faired near one sees it as a border vertex. `topo` is the connectivity of the mesh
/// `report` validated, whose faces are well formed.
void allow_border_pinches(ValidationReport& report, const Topology& topo);

}  // namespace fairsurf::detail
