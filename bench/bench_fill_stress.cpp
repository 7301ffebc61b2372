// Fill under stress (issue #11, "patches that are always valid"): 1–3 balls of 4–17 h drawn at
// random are cut out of a closed mesh, so they may overlap, sever a thin part or bite into its side,
// and the cut is filled with fill's defaults. Per trial: the loops, what was left open and why, the
// holes filled only by fallback_on_failure's later starts (the refined triangulation, faired or
// not), and two checks of the output: no new face crosses the mesh, and it is manifold. The protocol
// and figures are in docs/fill.md, "A loop that bites into a thin part".
//
// Usage: bench_fill_stress [--mesh NAME | --mesh-file PATH...] [--trials N] [--seed S]
#include <fairsurf/applications/fill.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/validate.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "real_holes.h"
#include "real_holes_cases.h"

namespace {

using namespace fairsurf;

struct Args {
  std::string mesh;                     // bundled meshes whose name contains this
  std::vector<std::string> mesh_files;  // closed meshes to cut instead of the bundled ones
  int trials = 40;                      // per mesh
  std::uint64_t seed = 1;               // of the first trial; trial t draws from seed + t
};

Args parse_args(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw InvalidArgument("bench_fill_stress: " + a + " needs a value");
      return argv[++i];
    };
    if (a == "--mesh") args.mesh = value();
    else if (a == "--mesh-file") args.mesh_files.push_back(value());
    else if (a == "--trials") args.trials = std::stoi(value());
    else if (a == "--seed") args.seed = std::stoull(value());
    else
      throw InvalidArgument("bench_fill_stress: unknown argument " + a +
                            " (--mesh NAME, --mesh-file PATH, --trials N, --seed S)");
  }
  if (args.trials < 1) throw InvalidArgument("bench_fill_stress: --trials must be >= 1");
  if (!args.mesh.empty() && !args.mesh_files.empty())
    throw InvalidArgument("bench_fill_stress: --mesh and --mesh-file exclude each other");
  return args;
}

struct Tally {
  int trials = 0, refused = 0, holes = 0, open = 0, refined = 0, unfaired = 0, crossing = 0, non_manifold = 0;
  double slowest = 0;
};

// The cut of one trial: k = 1–3 balls, each centred at a vertex of the mesh cut so far, of radius
// 4–17 h, all drawn from std::mt19937_64(seed) (whose output the standard fixes).
Mesh cut_balls(const bench::ClosedMesh& m, std::uint64_t seed) {
  std::mt19937_64 draw(seed);
  Mesh cut = m.mesh;
  const int balls = 1 + static_cast<int>(draw() % 3);
  for (int b = 0; b < balls && cut.num_faces() > 0; ++b) {
    const int centre = static_cast<int>(draw() % static_cast<std::uint64_t>(cut.num_vertices()));
    const double radius = static_cast<double>(4 + draw() % 14) * m.h;
    cut = bench::cut_ball(cut, cut.V.row(centre).transpose(), radius).mesh;
  }
  return cut;
}

bool noted(const HoleReport& r, const char* what) { return r.note.find(what) != std::string::npos; }

void run_trial(const bench::ClosedMesh& m, std::uint64_t seed, Tally& tally) {
  const Mesh cut = cut_balls(m, seed);
  std::printf("%-28s seed %3llu: loops %s", m.name.c_str(), static_cast<unsigned long long>(seed),
              bench::border_sizes(cut).c_str());
  ++tally.trials;
  Mesh filled = cut;
  FillReport report;
  try {
    report = fill_holes(filled, FillOptions{});
  } catch (const Error& e) {
    ++tally.refused;
    std::printf(", refused: %s\n", e.what());
    return;
  }
  std::vector<int> new_faces(filled.num_faces() - cut.num_faces());
  std::iota(new_faces.begin(), new_faces.end(), cut.num_faces());
  const bool crosses = !find_face_intersections(filled.V, filled.F, new_faces, 1).empty();
  const bool manifold = validate(filled).manifold();
  tally.holes += static_cast<int>(report.holes.size());
  tally.open += report.failed;
  tally.crossing += crosses;
  tally.non_manifold += !manifold;
  tally.slowest = std::max(tally.slowest, report.seconds);
  std::printf(", %.2f s%s%s", report.seconds, crosses ? ", OUTPUT CROSSES" : "", manifold ? "" : ", NOT MANIFOLD");
  for (const HoleReport& r : report.holes) {
    const bool unfaired = noted(r, "delivered unfaired");
    const bool refined = !unfaired && noted(r, "faired from the refined triangulation instead");
    tally.unfaired += unfaired;
    tally.refined += refined;
    if (r.status == HoleStatus::failed)
      std::printf("\n    hole %d (%d edges) left open: %s", r.index, r.border_edges, r.reason.c_str());
    else if (unfaired || refined)
      std::printf("\n    hole %d (%d edges): %s, %s", r.index, r.border_edges,
                  delivered_label(r.supported, r.linear).c_str(),
                  unfaired ? "the refined triangulation unfaired" : "faired from the refined triangulation");
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Args args = parse_args(argc, argv);
    std::vector<bench::ClosedMesh> meshes;
    if (args.mesh_files.empty()) meshes = bench::read_bundled_meshes(args.mesh);
    for (const std::string& file : args.mesh_files) meshes.push_back(bench::read_closed_mesh(file));
    Tally tally;
    for (const bench::ClosedMesh& m : meshes)
      for (int t = 0; t < args.trials; ++t) run_trial(m, args.seed + static_cast<std::uint64_t>(t), tally);
    std::printf("summary: %d trials on %zu meshes (%d refused), %d holes: %d left open, %d faired from the refined "
                "triangulation, %d filled by it unfaired; outputs crossing the mesh %d, not manifold %d; slowest "
                "trial %.2f s\n",
                tally.trials, meshes.size(), tally.refused, tally.holes, tally.open, tally.refined, tally.unfaired,
                tally.crossing, tally.non_manifold, tally.slowest);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
