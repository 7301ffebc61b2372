#include "loop_subdivision.h"

#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include <vector>

namespace fairsurf::bench {
namespace {

using Point = Eigen::RowVector3d;

// The corner of face f that is not on the edge (a, b).
int opposite_corner(const Faces& F, int f, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (F(f, k) != a && F(f, k) != b) return F(f, k);
  return a;
}

// Repositioned old vertices: the interior mask on closed fans, the curve mask on manifold borders.
void even_vertices(const Mesh& mesh, const Topology& topo, Vertices& out) {
  const int n = mesh.num_vertices();
  std::vector<int> border_count(n, 0);
  Vertices border_sum = Vertices::Zero(n, 3);
  for (int e = 0; e < topo.edges.rows(); ++e) {
    if (!topo.is_boundary_edge(e)) continue;
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    border_sum.row(a) += mesh.V.row(b);
    border_sum.row(b) += mesh.V.row(a);
    ++border_count[a];
    ++border_count[b];
  }
  for (int v = 0; v < n; ++v) {
    const auto ring = topo.vertex_vertices.row(v);
    if (border_count[v] == 2) {
      out.row(v) = 0.75 * mesh.V.row(v) + 0.125 * border_sum.row(v);
    } else if (border_count[v] > 0 || ring.empty()) {
      out.row(v) = mesh.V.row(v);
    } else {
      const double k = static_cast<double>(ring.size());
      const double beta = ring.size() == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * k);
      Point sum = Point::Zero();
      for (const int w : ring) sum += mesh.V.row(w);
      out.row(v) = (1.0 - k * beta) * mesh.V.row(v) + beta * sum;
    }
  }
}

// New edge vertices: 3/8, 3/8, 1/8, 1/8 inside, the midpoint on a border (or non-manifold) edge.
void odd_vertices(const Mesh& mesh, const Topology& topo, Vertices& out) {
  const int n = mesh.num_vertices();
  for (int e = 0; e < topo.edges.rows(); ++e) {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    const auto faces = topo.edge_faces.row(e);
    if (faces.size() == 2) {
      const int c = opposite_corner(mesh.F, faces[0], a, b), d = opposite_corner(mesh.F, faces[1], a, b);
      out.row(n + e) = 0.375 * (mesh.V.row(a) + mesh.V.row(b)) + 0.125 * (mesh.V.row(c) + mesh.V.row(d));
    } else {
      out.row(n + e) = 0.5 * (mesh.V.row(a) + mesh.V.row(b));
    }
  }
}

Mesh subdivide_once(const Mesh& mesh) {
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  const int n = mesh.num_vertices();
  Mesh fine;
  fine.V.resize(n + topo.edges.rows(), 3);
  even_vertices(mesh, topo, fine.V);
  odd_vertices(mesh, topo, fine.V);
  fine.F.resize(4 * mesh.F.rows(), 3);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    // m[k] is the new vertex on the edge from corner k to corner k+1.
    const int m0 = n + topo.face_edges[3 * f], m1 = n + topo.face_edges[3 * f + 1], m2 = n + topo.face_edges[3 * f + 2];
    fine.F.row(4 * f) << mesh.F(f, 0), m0, m2;
    fine.F.row(4 * f + 1) << mesh.F(f, 1), m1, m0;
    fine.F.row(4 * f + 2) << mesh.F(f, 2), m2, m1;
    fine.F.row(4 * f + 3) << m0, m1, m2;
  }
  return fine;
}

}  // namespace

Mesh loop_subdivide(const Mesh& mesh, int levels) {
  if (levels < 0) throw InvalidArgument("loop_subdivide: negative number of levels");
  Mesh result;
  result.V = mesh.V;
  result.F = mesh.F;
  for (int level = 0; level < levels; ++level) result = subdivide_once(result);
  return result;
}

}  // namespace fairsurf::bench
