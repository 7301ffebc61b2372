// Builds the topology of a tetrahedron through the installed library; exit status 0 only if it has
// the 6 edges a tetrahedron has. The umbrella header proves every public header is installed, in
// its stage's folder, and compiles on its own dependencies.
#include <fairsurf/fairsurf.h>

#include <iostream>

int main() {
  fairsurf::Mesh tet;
  tet.V.resize(4, 3);
  tet.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  tet.F.resize(4, 3);
  tet.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  const fairsurf::Topology topo = fairsurf::build_topology(tet.F, tet.num_vertices());
  std::cout << "tetrahedron edges: " << topo.edges.rows() << "\n";
  return topo.edges.rows() == 6 ? 0 : 1;
}
