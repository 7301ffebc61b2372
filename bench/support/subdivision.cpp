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

}  // namespace

Mesh butterfly_refined(const Mesh& mesh, int levels) {
  if (levels < 0) throw InvalidArgument("butterfly_refined: levels must be >= 0, got " + std::to_string(levels));
  TriMesh om = to_openmesh(mesh, "butterfly_refined");
  if (levels > 0) {
    OpenMesh::Subdivider::Uniform::ModifiedButterflyT<TriMesh> butterfly;
    butterfly.attach(om);
    butterfly(static_cast<size_t>(levels));
    butterfly.detach();
  }
  return from_openmesh(om);
}

Mesh loop_subdivide(const Mesh& mesh, int levels) {
  if (levels < 0) throw InvalidArgument("loop_subdivide: levels must be >= 0, got " + std::to_string(levels));
  TriMesh om = to_openmesh(mesh, "loop_subdivide");
  if (levels > 0) {
    OpenMesh::Subdivider::Uniform::LoopT<TriMesh> loop;
    loop.attach(om);
    loop(static_cast<size_t>(levels));
    loop.detach();
  }
  return from_openmesh(om);
}

}  // namespace fairsurf::bench
