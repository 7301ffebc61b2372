#include "subdivision.h"

#include <fairsurf/mesh/errors.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>

#include <string>
#include <vector>

namespace fairsurf::bench {
namespace {

struct Traits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

TriMesh to_openmesh(const Mesh& mesh, const char* caller) {
  TriMesh out;
  std::vector<TriMesh::VertexHandle> handle(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    handle[v] = out.add_vertex(TriMesh::Point(mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2)));
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (!out.add_face(handle[mesh.F(f, 0)], handle[mesh.F(f, 1)], handle[mesh.F(f, 2)]).is_valid())
      throw InvalidArgument(std::string(caller) + ": face " + std::to_string(f) + " is not manifold");
  return out;
}

Mesh from_openmesh(const TriMesh& in) {
  Mesh out;
  out.V.resize(static_cast<Eigen::Index>(in.n_vertices()), 3);
  for (const auto v : in.vertices()) {
    const TriMesh::Point& p = in.point(v);
    out.V.row(v.idx()) << p[0], p[1], p[2];
  }
  out.F.resize(static_cast<Eigen::Index>(in.n_faces()), 3);
  for (const auto f : in.faces()) {
    int k = 0;
    for (const auto v : in.fv_range(f)) out.F(f.idx(), k++) = v.idx();
  }
  return out;
}

// `levels` rounds of OpenMesh's uniform subdivider `Scheme` on `mesh`; `caller` names the errors.
template <template <class, class> class Scheme>
Mesh subdivided(const Mesh& mesh, int levels, const char* caller) {
  if (levels < 0) throw InvalidArgument(std::string(caller) + ": levels must be >= 0, got " + std::to_string(levels));
  TriMesh om = to_openmesh(mesh, caller);
  if (levels > 0) {
    Scheme<TriMesh, double> scheme;
    scheme.attach(om);
    scheme(static_cast<size_t>(levels));
    scheme.detach();
  }
  return from_openmesh(om);
}

}  // namespace

Mesh butterfly_refined(const Mesh& mesh, int levels) {
  return subdivided<OpenMesh::Subdivider::Uniform::ModifiedButterflyT>(mesh, levels, "butterfly_refined");
}

Mesh loop_subdivide(const Mesh& mesh, int levels) {
  return subdivided<OpenMesh::Subdivider::Uniform::LoopT>(mesh, levels, "loop_subdivide");
}

}  // namespace fairsurf::bench
