#include "cgal_reference.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <exception>
#include <iterator>
#include <stdexcept>

namespace fairsurf::bench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

SurfaceMesh to_surface_mesh(const Mesh& mesh) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  vertices.reserve(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    vertices.push_back(sm.add_vertex(Kernel::Point_3(mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2))));
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (sm.add_face(vertices[mesh.F(f, 0)], vertices[mesh.F(f, 1)], vertices[mesh.F(f, 2)]) ==
        SurfaceMesh::null_face())
      throw std::runtime_error("Surface_mesh refused face " + std::to_string(f) + " (non-manifold)");
  return sm;
}

Vertices positions(const SurfaceMesh& sm) {
  Vertices V(static_cast<int>(sm.number_of_vertices()), 3);
  for (SurfaceMesh::Vertex_index v : sm.vertices()) {
    const auto& p = sm.point(v);
    V.row(static_cast<int>(v)) << p.x(), p.y(), p.z();
  }
  return V;
}

// Surface_mesh keeps no removed elements here (nothing is deleted), so face and vertex indices are
// dense and the input's come first.
Faces triangles(const SurfaceMesh& sm) {
  Faces F(static_cast<int>(sm.number_of_faces()), 3);
  for (SurfaceMesh::Face_index f : sm.faces()) {
    int corner = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm))
      F(static_cast<int>(f), corner++) = static_cast<int>(v);
  }
  return F;
}

// One border halfedge per hole.
std::vector<SurfaceMesh::Halfedge_index> border_loops(const SurfaceMesh& sm) {
  std::vector<SurfaceMesh::Halfedge_index> loops;
  std::vector<char> seen(sm.number_of_halfedges(), 0);
  for (SurfaceMesh::Halfedge_index h : sm.halfedges()) {
    if (!sm.is_border(h) || seen[h]) continue;
    loops.push_back(h);
    for (auto g = h; !seen[g]; g = sm.next(g)) seen[g] = 1;
  }
  return loops;
}

template <class Run>
CgalResult timed(Run run) {
  const auto start = std::chrono::steady_clock::now();
  CgalResult result;
  try {
    run(result);
  } catch (const std::exception& e) {
    result.ok = false;
    result.error = e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

CgalResult cgal_fill_holes(const Mesh& mesh) {
  return timed([&](CgalResult& result) {
    SurfaceMesh sm = to_surface_mesh(mesh);
    result.ok = true;
    for (SurfaceMesh::Halfedge_index h : border_loops(sm)) {
      std::vector<SurfaceMesh::Face_index> faces;
      std::vector<SurfaceMesh::Vertex_index> added;
      const auto outcome = PMP::triangulate_refine_and_fair_hole(
          sm, h, std::back_inserter(faces), std::back_inserter(added), CGAL::parameters::fairing_continuity(2));
      if (!std::get<0>(outcome)) {
        result.ok = false;
        result.error = "fairing failed";
      }
      for (SurfaceMesh::Vertex_index v : added) result.moved.push_back(static_cast<int>(v));
    }
    result.V = positions(sm);
    result.F = triangles(sm);
  });
}

CgalResult cgal_fair(const Mesh& mesh, const std::vector<int>& free_vertices) {
  return timed([&](CgalResult& result) {
    SurfaceMesh sm = to_surface_mesh(mesh);
    std::vector<SurfaceMesh::Vertex_index> vertices;
    for (int v : free_vertices) vertices.emplace_back(static_cast<SurfaceMesh::size_type>(v));
    result.ok = PMP::fair(sm, vertices, CGAL::parameters::fairing_continuity(2));
    if (!result.ok) result.error = "fairing failed";
    result.moved = free_vertices;
    result.V = positions(sm);
  });
}

}  // namespace fairsurf::bench
