#include <fairsurf/repair.h>

#include "repair_internal.h"

#include <limits>

namespace fairsurf {
namespace {

using repair_detail::Tri;
using repair_detail::Work;

Work load(const Mesh& mesh) {
  Work work{mesh.V, std::vector<int>(mesh.num_vertices()), std::vector<Tri>(mesh.num_faces())};
  for (int v = 0; v < mesh.num_vertices(); ++v) work.origin[v] = v;
  for (int f = 0; f < mesh.num_faces(); ++f) work.faces[f] = {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
  return work;
}

// Writes the working state back: kept vertices in working order (originals in input order, then
// copies), their attributes following them.
void store(const Work& work, bool remove_unreferenced, Mesh& mesh, RepairReport& report) {
  const int n = work.num_vertices();
  std::vector<char> keep(n, 0);
  for (const Tri& f : work.faces)
    for (int v : f) keep[v] = 1;
  if (!remove_unreferenced)
    for (int v = 0; v < mesh.num_vertices(); ++v) keep[v] = 1;
  std::vector<int> index(n, -1), source;
  for (int v = 0; v < n; ++v)
    if (keep[v]) index[v] = static_cast<int>(source.size()), source.push_back(work.origin[v]);
  const int kept = static_cast<int>(source.size());
  report.unreferenced_vertices_removed = n - kept;

  Mesh out;
  out.V.resize(kept, 3);
  for (int i = 0; i < kept; ++i) out.V.row(i) = mesh.V.row(source[i]);
  out.F.resize(static_cast<Eigen::Index>(work.faces.size()), 3);
  for (std::size_t f = 0; f < work.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) out.F(static_cast<Eigen::Index>(f), k) = index[work.faces[f][k]];
  for (const auto& [name, values] : mesh.vertex_scalars) {
    if (values.size() != mesh.num_vertices()) continue;  // not a per-vertex scalar: cannot follow
    Eigen::VectorXd moved(kept);
    for (int i = 0; i < kept; ++i) moved[i] = values[source[i]];
    out.vertex_scalars[name] = std::move(moved);
  }
  if (mesh.vertex_colors.rows() == mesh.num_vertices() && mesh.num_vertices() > 0) {
    out.vertex_colors.resize(kept, 3);
    for (int i = 0; i < kept; ++i) out.vertex_colors.row(i) = mesh.vertex_colors.row(source[i]);
  }
  mesh = std::move(out);
}

// Splits, small components, stitching of what the splits left coincident, orientation.
void repair_connectivity(Work& work, const RepairOptions& options, RepairReport& report) {
  using namespace repair_detail;
  const int before_split = work.num_vertices();
  split_non_manifold(work, options, report);
  if (options.remove_small_components) remove_small_components(work, options.min_component_faces, report);
  // A split can leave copies that stitching now joins into a manifold vertex (a fin cut loose at
  // both ends whose other edges meet a border, once the debris around it is gone): joining them
  // here keeps a second repair idle.
  if (options.stitch_borders && work.num_vertices() > before_split) {
    stitch_borders(work, options, report);
    remove_collapsed_faces(work, report);
  }
  if (options.orient) orient_faces(work, report);
}

}  // namespace

bool RepairReport::changed() const {
  return invalid_faces_removed + vertices_merged + border_vertices_stitched + faces_collapsed +
             duplicate_faces_removed + needles_collapsed + caps_flipped + caps_removed +
             non_manifold_edges + vertices_split + vertices_added + faces_flipped +
             small_components_removed + unreferenced_vertices_removed >
         0;
}

RepairReport repair(Mesh& mesh, const RepairOptions& options) {
  using namespace repair_detail;
  RepairReport report;
  report.input_vertices = mesh.num_vertices();
  report.input_faces = mesh.num_faces();
  Work work = load(mesh);

  remove_invalid_faces(work, report);
  if (options.merge_duplicate_vertices) merge_vertices(work, options, report);
  if (options.stitch_borders) stitch_borders(work, options, report);
  remove_collapsed_faces(work, report);
  if (options.remove_duplicate_faces) remove_duplicate_faces(work, report);
  // A degenerate face whose edge was non-manifold, or whose neighbour was inconsistently oriented,
  // can be fixed once the splits and the orientation have run: repeat while that helps.
  int degenerate_before = std::numeric_limits<int>::max();
  for (int round = 0; round < 4; ++round) {
    if (options.fix_degenerate_faces) {
      fix_degenerate_faces(work, options, report);
      if (options.remove_duplicate_faces) remove_duplicate_faces(work, report);
    }
    repair_connectivity(work, options, report);
    if (!options.fix_degenerate_faces || report.degenerate_faces_left == 0 ||
        report.degenerate_faces_left >= degenerate_before)
      break;
    degenerate_before = report.degenerate_faces_left;
  }

  store(work, options.remove_unreferenced_vertices, mesh, report);
  report.output_vertices = mesh.num_vertices();
  report.output_faces = mesh.num_faces();
  return report;
}

}  // namespace fairsurf
