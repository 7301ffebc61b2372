#include <fairsurf/applications/repair.h>
#include <fairsurf/mesh/mesh_attributes.h>

#include "repair_internal.h"

#include <fairsurf/mesh/errors.h>

#include <string>

namespace fairsurf {
namespace {

using repair_detail::Tri;
using repair_detail::Work;

Work load(const Mesh& mesh) {
  Work work{mesh.V, std::vector<int>(mesh.num_vertices()), std::vector<Tri>(mesh.num_faces()),
            std::vector<int>(mesh.num_vertices(), -1)};
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
  carry_face_attributes(mesh, source, out);
  report.vertex_destination.assign(static_cast<std::size_t>(mesh.num_vertices()), -1);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    int w = v;
    while (work.merged_into[w] >= 0) w = work.merged_into[w];  // each merge goes to a surviving vertex
    report.vertex_destination[v] = index[w];
  }
  mesh = std::move(out);
  report.vertex_origin = std::move(source);
}

int change_count(const RepairReport& r) {
  return r.invalid_faces_removed + r.vertices_merged + r.border_vertices_stitched + r.faces_collapsed +
         r.duplicate_faces_removed + r.needles_collapsed + r.caps_flipped + r.caps_removed +
         r.non_manifold_edges + r.vertices_split + r.vertices_added + r.faces_flipped +
         r.small_components_removed + r.fins_removed + r.unreferenced_vertices_removed;
}

// Merging, then removing what merging collapsed or doubled.
void merge_round(Work& work, const RepairOptions& options, RepairReport& report) {
  using namespace repair_detail;
  const int before = report.vertices_merged + report.border_vertices_stitched;
  if (options.merge_duplicate_vertices) merge_vertices(work, options, report);
  // Exact merging has already joined every coincident border vertex it could.
  if (options.stitch_borders && (options.stitch_tolerance > 0 || !options.merge_duplicate_vertices))
    stitch_borders(work, options, report);
  if (report.vertices_merged + report.border_vertices_stitched == before) return;  // faces unchanged
  remove_collapsed_faces(work, report);
  if (options.remove_duplicate_faces) remove_duplicate_faces(work, report);
}

// One round of everything after the first merge. Each operation can enable another (a cap on a
// non-manifold edge flips once the edge is resolved; a merge refused beside a needle is accepted
// once the needle is gone), so rounds repeat until one changes nothing: the result is then a fixed
// point of every operation, and a second repair is idle.
void repair_round(Work& work, const RepairOptions& options, RepairReport& report) {
  using namespace repair_detail;
  const int before = change_count(report);
  if (options.fix_degenerate_faces) {
    fix_degenerate_faces(work, options, report);
    if (options.remove_duplicate_faces && change_count(report) > before) remove_duplicate_faces(work, report);
  }
  Adjacency unsplit;  // the adjacency split_non_manifold built, when it changed nothing
  split_non_manifold(work, options, report, &unsplit);
  if (options.remove_small_components) remove_small_components(work, options.min_component_faces, report);
  if (options.remove_loose_fins) remove_loose_fins(work, report);
  const bool changed = change_count(report) > before;
  if (changed) merge_round(work, options, report);  // else merged already
  if (options.orient) orient_faces(work, report, changed || unsplit.vertex_offsets.empty() ? nullptr : &unsplit);
}

}  // namespace

bool RepairReport::changed() const {
  return change_count(*this) > 0;
}

std::vector<int> repaired_vertices(const RepairReport& report, std::span<const int> input_vertices) {
  const int n = static_cast<int>(report.vertex_destination.size());
  std::vector<char> listed(static_cast<std::size_t>(n), 0);  // by input vertex, after merges
  for (int v : input_vertices) {
    if (v < 0 || v >= n)
      throw InvalidArgument("repaired_vertices: vertex " + std::to_string(v) + " is outside the " +
                            std::to_string(n) + " vertices repair was given");
    const int destination = report.vertex_destination[v];
    if (destination < 0)
      throw InvalidArgument("repaired_vertices: vertex " + std::to_string(v) +
                            " was removed by repair (no face it kept uses it)");
    listed[report.vertex_origin[destination]] = 1;
  }
  std::vector<int> out;
  for (int o = 0; o < static_cast<int>(report.vertex_origin.size()); ++o)
    if (listed[report.vertex_origin[o]]) out.push_back(o);
  return out;
}

std::vector<NamedCount> named_counts(const RepairReport& r) {
  return {{"input_vertices", r.input_vertices},
          {"input_faces", r.input_faces},
          {"output_vertices", r.output_vertices},
          {"output_faces", r.output_faces},
          {"invalid_faces_removed", r.invalid_faces_removed},
          {"vertices_merged", r.vertices_merged},
          {"merges_refused", r.merges_refused},
          {"border_vertices_stitched", r.border_vertices_stitched},
          {"faces_collapsed", r.faces_collapsed},
          {"duplicate_faces_removed", r.duplicate_faces_removed},
          {"needles_collapsed", r.needles_collapsed},
          {"caps_flipped", r.caps_flipped},
          {"caps_removed", r.caps_removed},
          {"degenerate_faces_left", r.degenerate_faces_left},
          {"non_manifold_edges", r.non_manifold_edges},
          {"vertices_split", r.vertices_split},
          {"vertices_added", r.vertices_added},
          {"faces_flipped", r.faces_flipped},
          {"non_orientable_components", r.non_orientable_components},
          {"small_components_removed", r.small_components_removed},
          {"small_component_faces_removed", r.small_component_faces_removed},
          {"fins_removed", r.fins_removed},
          {"fin_faces_removed", r.fin_faces_removed},
          {"unreferenced_vertices_removed", r.unreferenced_vertices_removed}};
}

RepairReport repair(Mesh& mesh, const RepairOptions& options) {
  using namespace repair_detail;
  RepairReport report;
  report.input_vertices = mesh.num_vertices();
  report.input_faces = mesh.num_faces();
  Work work = load(mesh);

  remove_invalid_faces(work, report);
  // Repeated faces first, so that they cannot veto a merge (an edge they double looks non-manifold).
  if (options.remove_duplicate_faces) remove_duplicate_faces(work, report);
  merge_round(work, options, report);
  constexpr int kMaxRounds = 8;
  for (int round = 0; round < kMaxRounds; ++round) {
    const int before = change_count(report);
    repair_round(work, options, report);
    if (change_count(report) == before) break;
  }

  store(work, options.remove_unreferenced_vertices, mesh, report);
  report.output_vertices = mesh.num_vertices();
  report.output_faces = mesh.num_faces();
  return report;
}

}  // namespace fairsurf
