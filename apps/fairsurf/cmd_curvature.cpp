// `fairsurf curvature MESH -o OUT.ply [--json] [--flip-sign] [--force]`: per-vertex mean, Gaussian
// and principal curvatures from the local quadratic fits (method.md §1–§3), written as PLY vertex
// properties H, K, k1, k2 (and fit_status), with their statistics printed as text or JSON.
#include "command.h"
#include "repair_report.h"

#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

namespace fairsurf::cli {
namespace {

struct CurvatureArgs {
  std::string input;
  std::string output;
  bool json = false;
  bool flip_sign = false;
  bool force = false;
  bool repair = false;
};

constexpr const char* kQuantities[] = {"H", "K", "k1", "k2"};

struct Summary {
  double min = 0, max = 0, mean = 0, p5 = 0, p50 = 0, p95 = 0;
};

// Percentile by linear interpolation between the closest ranks of the sorted values.
double percentile(const std::vector<double>& sorted, double p) {
  const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(rank));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (rank - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

// Statistics over the well-posed vertices; none when there are none.
std::optional<Summary> summarize(const Eigen::VectorXd& values, const std::vector<FitStatus>& status) {
  std::vector<double> v;
  for (int i = 0; i < values.size(); ++i)
    if (status[i] == FitStatus::kOk) v.push_back(values[i]);
  if (v.empty()) return std::nullopt;
  std::sort(v.begin(), v.end());
  Summary s;
  s.min = v.front(), s.max = v.back();
  for (double x : v) s.mean += x / static_cast<double>(v.size());
  s.p5 = percentile(v, 5), s.p50 = percentile(v, 50), s.p95 = percentile(v, 95);
  return s;
}

std::string status_key(FitStatus s) {
  std::string key = to_string(s);
  std::replace(key.begin(), key.end(), ' ', '_');
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

// Flipping the normal negates H and the principal curvatures; k1 stays the larger one.
void flip_sign(Mesh& mesh) {
  auto& s = mesh.vertex_scalars;
  s["H"] = -s["H"];
  Eigen::VectorXd k1 = -s["k2"];
  s["k2"] = -s["k1"];
  s["k1"] = std::move(k1);
}

void print_text(const CurvatureArgs& args, const Mesh& mesh, const QuadraticFits& fits) {
  const std::vector<int> counts = fits.status_counts();
  const int ok = counts[static_cast<int>(FitStatus::kOk)];
  std::cout << "curvature of " << args.input << ": " << mesh.num_vertices() << " vertices, " << ok
            << " with a well-posed fit, " << mesh.num_vertices() - ok << " ill-posed";
  std::string sep = " (";
  for (std::size_t s = 1; s < counts.size(); ++s)
    if (counts[s] > 0) {
      std::cout << sep << counts[s] << " " << to_string(static_cast<FitStatus>(s));
      sep = ", ";
    }
  std::cout << (sep == ", " ? ")" : "") << "\n";
  std::cout << (args.flip_sign ? "sign: flipped (--flip-sign): H > 0 on a sphere with outward normals\n"
                               : "sign: H < 0 on a sphere with outward normals (H = -1/R)\n");
  if (ok == 0) {
    std::cout << "no vertex has a well-posed fit: no statistics\n";
  } else {
    std::cout << "statistics over the well-posed vertices:\n";
    std::printf("%-3s %13s %13s %13s %13s %13s %13s\n", "", "min", "p5", "p50", "p95", "max", "mean");
  }
  for (const char* q : kQuantities) {
    const auto summary = summarize(mesh.vertex_scalars.at(q), fits.status);
    if (!summary) continue;
    const Summary& s = *summary;
    std::printf("%-3s %13.6g %13.6g %13.6g %13.6g %13.6g %13.6g\n", q, s.min, s.p5, s.p50, s.p95,
                s.max, s.mean);
  }
  std::cout << "wrote " << args.output << " (vertex properties H, K, k1, k2, fit_status)\n";
}

void print_json(const CurvatureArgs& args, const Mesh& mesh, const QuadraticFits& fits,
                const std::optional<RepairReport>& repaired, const std::vector<std::string>& write_notes) {
  const std::vector<int> counts = fits.status_counts();
  const int ok = counts[static_cast<int>(FitStatus::kOk)];
  nlohmann::ordered_json j;
  j["input"] = args.input;
  j["output"] = args.output;
  j["vertices"] = mesh.num_vertices();
  j["repair"] = repair_json(repaired);
  j["write_notes"] = write_notes;  // what the PLY output could not hold (the text mode prints them)
  j["flip_sign"] = args.flip_sign;
  j["sign_convention"] = args.flip_sign ? "H > 0 on a sphere with outward normals (flipped)"
                                        : "H < 0 on a sphere with outward normals (H = -1/R)";
  j["well_posed"] = ok;
  j["ill_posed"] = mesh.num_vertices() - ok;
  for (std::size_t s = 0; s < counts.size(); ++s)
    j["fit_status"][status_key(static_cast<FitStatus>(s))] = counts[s];
  j["statistics"] = nlohmann::ordered_json::object();
  for (const char* q : kQuantities) {
    const auto summary = summarize(mesh.vertex_scalars.at(q), fits.status);
    if (!summary) continue;
    const Summary& s = *summary;
    j["statistics"][q] = {{"min", s.min}, {"p5", s.p5}, {"p50", s.p50}, {"p95", s.p95},
                          {"max", s.max}, {"mean", s.mean}};
  }
  std::cout << j.dump(2) << "\n";
}

void run_curvature(const CurvatureArgs& args) {
  if (lower_extension(args.output) != ".ply")
    throw CliError(kUsage, "curvature: the output must be a .ply file, the only format that carries "
                           "per-vertex H, K, k1, k2 (got '" + args.output + "')");
  check_outputs("curvature", {{"-o", args.output, OutputKind::mesh}}, {args.input}, args.force);
  Mesh mesh = read_mesh(args.input);
  const auto repaired = repair_input(mesh, args.repair, args.input, args.json);
  if (mesh.num_faces() == 0) throw InvalidMeshError("curvature: '" + args.input + "' has no triangles");
  Topology topo;
  try {
    topo = build_topology(mesh.F, mesh.num_vertices());
  } catch (const InvalidArgument& e) {
    throw InvalidMeshError(e.what());
  }
  const QuadraticFits fits = fit_quadratics(mesh.V, mesh.F, topo);
  SurfaceGeometry geometry = compute_geometry(fits, mesh.V);
  mesh.vertex_scalars["H"] = std::move(geometry.H);
  mesh.vertex_scalars["K"] = std::move(geometry.K);
  mesh.vertex_scalars["k1"] = std::move(geometry.k1);
  mesh.vertex_scalars["k2"] = std::move(geometry.k2);
  Eigen::VectorXd status(mesh.num_vertices());
  for (int i = 0; i < mesh.num_vertices(); ++i) status[i] = static_cast<double>(fits.status[i]);
  mesh.vertex_scalars["fit_status"] = std::move(status);
  if (args.flip_sign) flip_sign(mesh);
  std::vector<std::string> write_notes;
  write_mesh_output(args.output, mesh, {}, args.json ? &write_notes : nullptr);

  if (args.json)
    print_json(args, mesh, fits, repaired, write_notes);
  else
    print_text(args, mesh, fits);
}

void setup_curvature(CLI::App& app) {
  auto args = std::make_shared<CurvatureArgs>();
  CLI::App* cmd = app.add_subcommand(
      "curvature", "Per-vertex mean, Gaussian and principal curvatures (H, K, k1, k2) as PLY properties");
  cmd->add_option("mesh", args->input, "Input mesh (.obj, .off, .ply, .stl)")->required();
  cmd->add_option("-o,--output", args->output, "Output PLY with vertex properties H, K, k1, k2")->required();
  cmd->add_flag("--json", args->json, "Print the statistics as JSON");
  cmd->add_flag("--flip-sign", args->flip_sign,
                "Flip the sign of H, k1, k2 so that H > 0 on spheres (default: H = -1/R)");
  cmd->add_flag("--force", args->force, "Allow the output to overwrite the input");
  add_repair_flag(cmd, args->repair);
  cmd->callback([args] { run_curvature(*args); });
}

const CommandRegistration registration(20, setup_curvature);

}  // namespace
}  // namespace fairsurf::cli
