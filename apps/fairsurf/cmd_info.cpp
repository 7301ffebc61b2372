// `fairsurf info MESH [--json] [--strict]`: counts, topology, extent and every validation finding.
// Findings are reported, not errors: the exit status is 0 whenever the file could be read, unless
// --strict asks for 3 on any finding (docs/validation.md).
#include "command.h"

#include <fairsurf/io/io.h>
#include <fairsurf/mesh/mesh_summary.h>
#include <fairsurf/mesh/validate.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace fairsurf::cli {
namespace {

struct InfoArgs {
  std::string mesh;
  bool json = false;
  bool strict = false;
};

std::string join(const std::vector<int>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) out += (i > 0 ? ", " : "") + std::to_string(values[i]);
  return out;
}

int finding_count(const ValidationReport& report) {
  int kinds = report.no_faces ? 1 : 0;
  for (const auto& named : named_findings(report)) kinds += named.finding->count > 0;
  return kinds;
}

std::string genus_text(const MeshSummary& s, const ValidationReport& report) {
  if (s.genus) return std::to_string(*s.genus);
  return report.manifold() ? "undefined (non-orientable)" : "undefined (non-manifold)";
}

// What the file holds beyond positions and triangles: what the commands keep (docs/cli.md).
struct Held {
  int texture_coordinates = 0, textured_triangles = 0, normals = 0, normal_triangles = 0, polygons = 0;
};

Held held(const Mesh& mesh) {
  Held h;
  const auto with_all = [](const Faces& FX) {
    int n = 0;
    for (Eigen::Index f = 0; f < FX.rows(); ++f) n += FX.row(f).minCoeff() >= 0;
    return n;
  };
  h.texture_coordinates = static_cast<int>(mesh.TC.rows());
  h.textured_triangles = with_all(mesh.FTC);
  h.normals = static_cast<int>(mesh.N.rows());
  h.normal_triangles = with_all(mesh.FN);
  const Eigen::VectorXi& p = mesh.face_polygon;  // polygons of 4 or more corners: runs of 2+ triangles
  for (Eigen::Index f = 1; f < p.size(); ++f) h.polygons += p[f] >= 0 && p[f] == p[f - 1] && (f == 1 || p[f - 2] != p[f]);
  return h;
}

void print_held(const Held& h, int faces) {
  if (h.texture_coordinates > 0)
    std::cout << "texture coordinates: " << h.texture_coordinates << " (on " << h.textured_triangles << " of "
              << faces << " triangles)\n";
  if (h.normals > 0)
    std::cout << "normals: " << h.normals << " (on " << h.normal_triangles << " of " << faces << " triangles)\n";
  if (h.polygons > 0) std::cout << "polygons of 4 or more corners: " << h.polygons << "\n";
}

void print_text(const std::string& path, const ReadReport& read, const MeshSummary& s,
                const ValidationReport& report, const Held& h) {
  std::cout << "mesh: " << path << "\n"
            << "vertices: " << s.vertices << " (" << s.referenced_vertices << " referenced)\n"
            << "faces: " << s.faces << "\n"
            << "edges: " << s.edges << " (" << s.boundary_edges << " on the boundary)\n"
            << "boundary loops: " << s.boundary_loop_lengths.size();
  if (!s.boundary_loop_lengths.empty())
    std::cout << " (edges: " << join(s.boundary_loop_lengths) << ")";
  if (s.lone_triangles > 0)
    std::cout << "\nlone triangles: " << s.lone_triangles
              << " (every edge on the border: fill takes one hanging at a hole's border into that hole's "
                 "patch where it can, and never fills one's loop alone)";
  std::cout << "\ncomponents: " << s.components << "\n"
            << "euler characteristic: " << s.euler_characteristic << "\n"
            << "genus: " << genus_text(s, report) << "\n";
  if (s.bounding_box.isEmpty())
    std::cout << "bounding box: empty\n";
  else
    std::cout << "bounding box: [" << s.bounding_box.min().transpose() << "] to ["
              << s.bounding_box.max().transpose() << "]\n";
  std::cout << "mean edge length: " << s.mean_edge_length << "\n"
            << "manifold: " << (report.manifold() ? "yes" : "no") << "\n"
            << "orientable: " << (report.orientable() ? "yes" : "no") << "\n";
  print_held(h, s.faces);
  if (read.polygons_triangulated > 0)
    std::cout << "read: " << read.polygons_triangulated << " polygons triangulated ("
              << read.triangles_added << " triangles added)\n";
  for (const auto& note : read.notes) std::cout << "read: " << note << "\n";

  const int kinds = finding_count(report);
  std::cout << "findings: " << (kinds == 0 ? "none" : std::to_string(kinds)) << "\n";
  if (report.no_faces) std::cout << "  no faces\n";
  for (const auto& named : named_findings(report)) {
    const Finding& f = *named.finding;
    if (f.count == 0) continue;
    std::cout << "  " << f.count << " " << (f.count == 1 ? named.singular : named.plural)
              << " (first: " << format_examples(f, static_cast<int>(f.examples.size())) << ")\n";
  }
}

nlohmann::json examples_json(const Finding& f) {
  if (f.element != Element::edge) return f.examples;
  nlohmann::json pairs = nlohmann::json::array();
  for (std::size_t i = 0; i + 1 < f.examples.size(); i += 2)
    pairs.push_back({f.examples[i], f.examples[i + 1]});
  return pairs;
}

nlohmann::json to_json(const std::string& path, const ReadReport& read, const MeshSummary& s,
                       const ValidationReport& report, const Held& h) {
  nlohmann::json j;
  j["file"] = path;
  j["vertices"] = s.vertices;
  j["referenced_vertices"] = s.referenced_vertices;
  j["faces"] = s.faces;
  j["edges"] = s.edges;
  j["boundary_edges"] = s.boundary_edges;
  j["boundary_loops"] = s.boundary_loop_lengths;
  j["lone_triangles"] = s.lone_triangles;
  j["components"] = s.components;
  j["euler_characteristic"] = s.euler_characteristic;
  j["genus"] = s.genus ? nlohmann::json(*s.genus) : nlohmann::json(nullptr);
  if (s.bounding_box.isEmpty()) {
    j["bounding_box"] = nullptr;
  } else {
    const Eigen::Vector3d lo = s.bounding_box.min(), hi = s.bounding_box.max();
    j["bounding_box"] = {{"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}};
  }
  j["mean_edge_length"] = s.mean_edge_length;
  j["manifold"] = report.manifold();
  j["orientable"] = report.orientable();
  j["no_faces"] = report.no_faces;
  j["valid"] = report.is_valid();
  nlohmann::json examples = nlohmann::json::object();
  for (const auto& named : named_findings(report)) {
    j[named.key] = named.finding->count;
    if (named.finding->count > 0) examples[named.key] = examples_json(*named.finding);
  }
  j["examples"] = examples;
  j["polygons_triangulated"] = read.polygons_triangulated;
  j["triangles_added"] = read.triangles_added;
  j["read_notes"] = read.notes;
  j["texture_coordinates"] = h.texture_coordinates;
  j["textured_triangles"] = h.textured_triangles;
  j["normals"] = h.normals;
  j["normal_triangles"] = h.normal_triangles;
  j["polygons"] = h.polygons;
  return j;
}

void run_info(const InfoArgs& args) {
  ReadReport read;
  const Mesh mesh = read_mesh(args.mesh, &read);
  const ValidationReport report = validate(mesh);
  const MeshSummary summary = summarize(mesh, report);
  const Held h = held(mesh);
  if (args.json)
    std::cout << to_json(args.mesh, read, summary, report, h).dump(2) << "\n";
  else
    print_text(args.mesh, read, summary, report, h);
  std::cout.flush();
  const int kinds = finding_count(report);
  if (args.strict && kinds > 0)
    throw CliError(kInvalidMesh, "info: " + args.mesh + " has " + std::to_string(kinds) +
                                     (kinds == 1 ? " kind" : " kinds") + " of finding (--strict)");
}

void setup(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Print a mesh's counts, topology, extent and validation findings");
  // No CLI::ExistingFile check: a missing file is an input error (exit 2) reported by read_mesh.
  cmd->add_option("MESH", args->mesh, "Mesh file (.obj, .off, .ply, .stl)")->required();
  cmd->add_flag("--json", args->json, "Print one JSON object instead of text");
  cmd->add_flag("--strict", args->strict, "Exit with status 3 if there is any finding");
  cmd->callback([args] { run_info(*args); });
}

const CommandRegistration registration(10, setup);

}  // namespace
}  // namespace fairsurf::cli
