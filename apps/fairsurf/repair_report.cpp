#include "repair_report.h"

#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/region_selection.h>

#include <cstdio>
#include <vector>

namespace fairsurf::cli {
namespace {

struct Count {
  int value;
  const char* singular;
  const char* plural;
};

std::vector<Count> changes(const RepairReport& r) {
  return {{r.invalid_faces_removed, "invalid face removed", "invalid faces removed"},
          {r.vertices_merged, "duplicate vertex merged", "duplicate vertices merged"},
          {r.border_vertices_stitched, "border vertex stitched", "border vertices stitched"},
          {r.faces_collapsed, "face collapsed by a merge", "faces collapsed by merges"},
          {r.duplicate_faces_removed, "duplicate face removed", "duplicate faces removed"},
          {r.needles_collapsed, "needle collapsed", "needles collapsed"},
          {r.caps_flipped, "cap flipped", "caps flipped"},
          {r.caps_removed, "cap removed", "caps removed"},
          {r.non_manifold_edges, "non-manifold edge resolved", "non-manifold edges resolved"},
          {r.vertices_split, "vertex split", "vertices split"},
          {r.vertices_added, "vertex copy added", "vertex copies added"},
          {r.faces_flipped, "face flipped", "faces flipped"},
          {r.small_components_removed, "small component removed", "small components removed"},
          {r.fins_removed, "loose fin removed", "loose fins removed"},
          {r.unreferenced_vertices_removed, "unreferenced vertex removed", "unreferenced vertices removed"},
          {r.degenerate_faces_left, "degenerate face left", "degenerate faces left"},
          {r.non_orientable_components, "non-orientable component (reported, not fixed)",
           "non-orientable components (reported, not fixed)"}};
}

}  // namespace

std::string describe(const RepairReport& report) {
  std::string out;
  for (const Count& c : changes(report)) {
    if (c.value == 0) continue;
    out += (out.empty() ? "" : ", ") + std::to_string(c.value) + " " + (c.value == 1 ? c.singular : c.plural);
  }
  return out.empty() ? "nothing to repair" : out;
}

nlohmann::json to_json(const RepairReport& r) {
  nlohmann::json j = nlohmann::json::object();
  for (const NamedCount& count : named_counts(r)) j[count.key] = count.value;
  j["changed"] = r.changed();
  return j;
}

void add_repair_flag(CLI::App* command, bool& repair_flag, const std::string& how) {
  command->add_flag("--repair", repair_flag, "Repair the input first (" + how + "; docs/repair.md) and report it");
}

std::optional<RepairReport> repair_input(Mesh& mesh, bool enabled, const std::string& path, bool quiet,
                                         const RepairOptions& options) {
  if (!enabled) return std::nullopt;
  const RepairReport report = repair(mesh, options);
  if (!quiet) std::printf("repaired %s: %s\n", path.c_str(), describe(report).c_str());
  return report;
}

std::vector<int> input_vertex_indices(const std::string& path, const Mesh& mesh,
                                      const std::optional<RepairReport>& repaired) {
  if (!repaired) return read_vertex_indices(path, mesh.num_vertices());
  const std::vector<int> listed = read_vertex_indices(path, repaired->input_vertices);
  for (int v : listed)
    if (repaired->vertex_destination[static_cast<std::size_t>(v)] < 0)
      throw ParseError("read_vertex_indices: " + path + ": vertex " + std::to_string(v) +
                       " was removed by --repair (no face it kept uses it)");
  return repaired_vertices(*repaired, listed);
}

nlohmann::json repair_json(const std::optional<RepairReport>& report) {
  return report ? to_json(*report) : nlohmann::json(nullptr);
}

}  // namespace fairsurf::cli
