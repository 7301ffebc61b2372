// libFuzzer harness for repair: the bytes are read as an OFF file (the simplest text format, so
// mutations reach the connectivity quickly), then repaired. Beyond the sanitizers it checks what
// repair.h promises: a manifold result with every index in range and no zero-area face left
// unreported, no vertex at a position the input did not have, and a second run changing nothing.
#include <fairsurf/applications/repair.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/validate.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <array>
#include <set>
#include <string_view>

#include "io/io_formats.h"

namespace {

void check(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fairsurf;
  const io_detail::Source source{"fuzz", std::string_view(reinterpret_cast<const char*>(data), size)};
  Mesh mesh;
  try {
    ReadReport report;
    mesh = triangulate(io_detail::read_off(source, report), &report);
  } catch (const Error&) {
    return 0;
  }
  const Mesh input = mesh;
  const RepairReport first = repair(mesh);
  const ValidationReport after = validate(mesh);
  check(after.out_of_range_indices.count == 0 && after.repeated_vertex_faces.count == 0);
  check(after.nan_vertices.count == 0 && after.unreferenced_vertices.count == 0);
  check(after.non_manifold_edges.count == 0 && after.non_manifold_vertices.count == 0);
  check(after.degenerate_faces.count + after.near_degenerate_faces.count == first.degenerate_faces_left);
  std::set<std::array<double, 3>> positions;
  for (int v = 0; v < input.num_vertices(); ++v) positions.insert({input.V(v, 0), input.V(v, 1), input.V(v, 2)});
  for (int v = 0; v < mesh.num_vertices(); ++v) check(positions.count({mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2)}) == 1);
  Mesh again = mesh;
  check(!repair(again).changed());
  check(again.V.rows() == mesh.V.rows() && again.F.rows() == mesh.F.rows());
  check(again.V == mesh.V && again.F == mesh.F);
  return 0;
}
