#include <fairsurf/geometry/curvatures.h>

#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

namespace fairsurf {

Curvatures curvatures(const Mesh& mesh) {
  Topology topo;
  try {
    topo = build_topology(mesh.F, mesh.num_vertices());
  } catch (const InvalidArgument& e) {
    // A face index out of range is a defect of the mesh, not of an option.
    throw InvalidMeshError(e.what());
  }
  QuadraticFits fits = fit_quadratics(mesh.V, mesh.F, topo);
  Curvatures result{compute_geometry(fits, mesh.V), std::move(fits.status)};
  return result;
}

}  // namespace fairsurf
