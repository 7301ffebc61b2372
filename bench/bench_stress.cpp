// Fill, fair and blend under stress (issue #11, "patches that are always valid"): cases drawn at
// random on closed meshes, none of them tidy, each run with the library's defaults and its output
// checked. The protocol and figures are in docs/fill.md, "Stress benchmark".
//
// fill:  1–3 balls of 4–17 h cut out (they may overlap, sever a thin part or bite into its side);
//        with --cut irregular, a blob or a slit of faces instead (bench::cut_irregular); with
//        --cut small-balls, 1–200 balls of 1–2.5 h (a scan's missing vertices, crowding into
//        holes that touch and groups filled jointly).
// fair:  the same balls' vertices freed on the uncut mesh, clean and with 0.1 h of normal noise
//        (with --cut irregular, the vertices inside the blob or slit).
// blend: a slab 4 h wide at a random orientation through a random vertex, where it leaves exactly
//        two loops of at most 200 edges.
//
// Usage: bench_stress [--section fill|fair|blend|all] [--mesh NAME | --mesh-file PATH...]
//                     [--trials N] [--seed S] [--cut balls|irregular|small-balls] [--write DIR]
#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/repair.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/mesh/region_selection.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "bench_options.h"
#include "real_holes.h"
#include "real_holes_cases.h"

namespace {

using namespace fairsurf;
using bench::ClosedMesh;

constexpr double kNoise = 0.1;     // σ of the fair section's normal noise, in h
constexpr int kMaxBlendLoop = 200;  // border edges, as bench_real_holes' slabs

struct Args {
  std::string section = "all";
  std::string mesh;                     // bundled meshes whose name contains this
  std::vector<std::string> mesh_files;  // closed meshes to use instead of the bundled ones
  int trials = 40;                      // per mesh and section
  std::uint64_t seed = 1;               // of the first trial; trial t draws from seed + t
  std::string cut = "balls";            // fill and fair: balls, irregular blobs and slits, or small balls
  std::string write_dir;                // where each trial's input and output meshes go
};

void add_options(CLI::App& app, Args& args) {
  bench::add_case_options(app, args.section, args.mesh, args.mesh_files);
  // Not CLI::PositiveNumber: its refusal prints DBL_MAX's 309 digits.
  app.add_option("--trials", args.trials, "Trials per mesh and section")
      ->type_name("N")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()).description(">= 1"))
      ->capture_default_str();
  app.add_option("--seed", args.seed, "Fill and fair trial t draw from S + t, a mesh's blend slabs from S")
      ->type_name("S")
      ->capture_default_str();
  app.add_option("--cut", args.cut,
                 "Fill and fair: balls, irregular blobs and slits of faces, or 1-200 small balls of 1-2.5 h (their "
                 "inner vertices freed for fair)")
      ->check(CLI::IsMember({"balls", "irregular", "small-balls"}))
      ->capture_default_str();
  app.add_option("--write", args.write_dir,
                 "Write each trial's input and output into DIR, to look at with fairsurf render or run again with "
                 "the CLI: fill MESH_seedS_cut.ply and _filled.ply; fair MESH_seedS[_noise]_region.ply (vertex "
                 "property region, for fairsurf fair --region-property region) and _faired.ply; blend "
                 "MESH_slabK_cut.ply (the mesh's K-th slab) and _blended.ply")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory);
}

// How many balls a trial cuts and how large: 1 to `most` balls, of radius smallest_h + k · step_h
// (k < steps) mean edges.
struct BallSizes {
  int most;
  double smallest_h, step_h;
  int steps;
};
constexpr BallSizes kBalls{3, 4.0, 1.0, 14};        // 1–3 balls of 4–17 h
constexpr BallSizes kSmallBalls{200, 1.0, 0.5, 4};  // 1–200 balls of 1–2.5 h

// Balls as `sizes` says, each centred at a vertex of `mesh` as cut so far (`cut`: cut each ball
// out, else keep the mesh whole), all drawn from std::mt19937_64(seed) (whose output the standard
// fixes). Returns the mesh as cut with each of its vertices' index in the uncut mesh, and the
// vertices inside the balls (of the uncut mesh) or, when cut, those the cut dropped.
struct Balls {
  Mesh cut;
  std::vector<int> kept;  ///< cut: for each vertex of `cut`, its index in the uncut mesh
  std::vector<int> inside;
};

Balls draw_balls(const ClosedMesh& m, std::uint64_t seed, bool cut, const BallSizes& sizes) {
  std::mt19937_64 draw(seed);
  Balls b{m.mesh, bench::rows_from(0, m.mesh.num_vertices()), {}};
  std::set<int> inside;
  const int balls = 1 + static_cast<int>(draw() % static_cast<std::uint64_t>(sizes.most));
  for (int k = 0; k < balls && b.cut.num_faces() > 0; ++k) {
    const int centre = static_cast<int>(draw() % static_cast<std::uint64_t>(b.cut.num_vertices()));
    const double radius =
        (sizes.smallest_h + sizes.step_h * static_cast<double>(draw() % static_cast<std::uint64_t>(sizes.steps))) *
        m.h;
    const Eigen::Vector3d c = b.cut.V.row(centre).transpose();
    if (cut) {
      bench::CutMesh next = bench::cut_ball(b.cut, c, radius);
      for (int v : next.dropped) inside.insert(b.kept[v]);
      for (int& v : next.kept) v = b.kept[v];
      b.cut = std::move(next.mesh);
      b.kept = std::move(next.kept);
    } else {
      for (int v : vertices_in_ball(b.cut.V, c, radius)) inside.insert(v);
    }
  }
  b.inside.assign(inside.begin(), inside.end());
  return b;
}

// The uncut surface's own reading across the border of hole `loop` of the cut mesh: the largest
// angle between the one-sided normals at its vertices, the dropped vertices as the free side
// (bench_real_holes' `uncut` column), in degrees.
double uncut_angle(const ClosedMesh& m, const Balls& balls, const std::vector<int>& loop) {
  std::vector<int> at;
  for (int v : loop) at.push_back(balls.kept[v]);
  return measure_continuity(m.mesh.V, m.mesh.F, balls.inside, at).max_normal_angle * 180 / std::numbers::pi;
}

bool crosses(const Mesh& mesh, const std::vector<int>& faces) {
  return !find_face_intersections(mesh.V, mesh.F, faces, 1).empty();
}

bool noted(const std::string& note, const char* what) { return note.find(what) != std::string::npos; }

// ---------------------------------------------------------------------------------------------
// Fill: the balls cut out and filled

struct FillTally {
  int trials = 0, refused = 0, holes = 0, open = 0, refined = 0, unfaired = 0, crossing = 0;
  /// Outputs that are not manifold; of those, the ones whose cut was (the others keep a pinch the
  /// cut made where a hole through it stayed open).
  int non_manifold = 0, made_non_manifold = 0;
  int folded = 0;  ///< filled holes whose patch folds back (fill.h's folds_back)
  /// Of those, the ones in a cut that removed disks only (bench::removed_disks: each loop bounds a
  /// disk of the uncut surface, which a fill should follow) across whose border the uncut surface
  /// turns the normal by less than a right angle: folds the cut does not explain. A cap on a
  /// severed tube turns by a right angle whatever the tube does, so other cuts are not counted.
  int folded_against_uncut = 0;
  /// Holes left open because a lone triangle hangs at their border (the reason names repair), and
  /// of those, the holes still open once the cut is repaired (as `fairsurf fill --repair` does).
  int open_at_lone_triangle = 0, open_after_repair = 0;
  double slowest = 0;
};

// An irregular cut (bench::cut_irregular) as draw_balls returns a cut: the vertices it dropped are
// the "inside". From a random face, half the draws grow a blob of 20–399 faces, the others walk
// 10–99 steps into a slit.
Balls draw_irregular(const ClosedMesh& m, std::uint64_t seed, bool& slit) {
  std::mt19937_64 draw(seed);
  const int start = static_cast<int>(draw() % static_cast<std::uint64_t>(m.mesh.num_faces()));
  slit = draw() % 2 == 1;
  const int size = slit ? 10 + static_cast<int>(draw() % 90) : 20 + static_cast<int>(draw() % 380);
  bench::CutMesh cut = bench::cut_irregular(m.mesh, start, slit ? bench::CutShape::slit : bench::CutShape::blob,
                                            size, draw, false);
  return {std::move(cut.mesh), std::move(cut.kept), std::move(cut.dropped)};
}

// The holes still open after repairing `cut` and filling it again (the trial's holes that a lone
// triangle kept open: does repair let them be filled?).
int open_after_repair(Mesh cut) {
  RepairOptions options;  // as `fairsurf fill --repair`
  options.keep_border_pinches = true;
  repair(cut, options);
  Mesh filled = cut;
  return fill_holes(filled, FillOptions{}).failed;
}

// --write: `DIR/` + `trial` + `_` + `what` + `.ply`, where `trial` names the mesh and its draw.
void write_trial(const std::string& dir, const std::string& trial, const char* what, const Mesh& mesh) {
  write_mesh(std::filesystem::path(dir) / (trial + "_" + what + ".ply"), mesh);
}

std::string seed_name(const ClosedMesh& m, std::uint64_t seed) { return m.name + "_seed" + std::to_string(seed); }

// The trial's cut as --cut names it (`shape`), cut out (`cut`) or only marked; `label` says which.
Balls draw_cut(const ClosedMesh& m, std::uint64_t seed, const std::string& shape, bool cut, std::string& label) {
  if (shape == "irregular") {
    bool slit = false;
    Balls b = draw_irregular(m, seed, slit);
    label = slit ? "slit, " : "blob, ";
    return b;
  }
  label = shape == "small-balls" ? "small balls, " : "";
  return draw_balls(m, seed, cut, shape == "small-balls" ? kSmallBalls : kBalls);
}

void fill_trial(const ClosedMesh& m, std::uint64_t seed, const std::string& shape, const std::string& write_dir,
                FillTally& tally) {
  std::string label;
  const Balls balls = draw_cut(m, seed, shape, true, label);
  const Mesh& cut = balls.cut;
  std::printf("fill  %-26s seed %3llu: ", m.name.c_str(), static_cast<unsigned long long>(seed));
  if (cut.num_faces() == 0) {  // the balls took the whole mesh: nothing to fill (fill_holes refuses it)
    std::printf("the cut left no face, not run\n");
    return;
  }
  std::printf("%sloops %s", label.c_str(), bench::border_sizes(cut).c_str());
  ++tally.trials;
  if (!write_dir.empty()) write_trial(write_dir, seed_name(m, seed), "cut", cut);
  Mesh filled = cut;
  FillReport report;
  try {
    report = fill_holes(filled, FillOptions{});
  } catch (const Error& e) {
    ++tally.refused;
    std::printf(", refused: %s\n", e.what());
    return;
  }
  if (!write_dir.empty()) write_trial(write_dir, seed_name(m, seed), "filled", filled);
  const bool crossing = crosses(filled, bench::rows_from(cut.num_faces(), filled.num_faces()));
  const bool manifold = validate(filled).manifold();
  const bool cut_manifold = validate(cut).manifold();
  tally.holes += static_cast<int>(report.holes.size());
  tally.open += report.failed;
  tally.crossing += crossing;
  tally.non_manifold += !manifold;
  tally.made_non_manifold += !manifold && cut_manifold;
  tally.slowest = std::max(tally.slowest, report.seconds);
  std::printf(", %.2f s%s%s", report.seconds, crossing ? ", OUTPUT CROSSES" : "",
              manifold ? "" : (cut_manifold ? ", NOT MANIFOLD" : ", not manifold, as the cut"));
  const std::vector<std::vector<int>> loops = bench::loops_of(cut);
  const bool disks = bench::removed_disks(m.mesh, cut);
  for (const HoleReport& r : report.holes) {
    const bool unfaired = r.unfaired;
    const bool refined = !unfaired && noted(r.note, "faired from the refined triangulation instead");
    tally.unfaired += unfaired;
    tally.refined += refined;
    if (folds_back(r) && r.patch_shared_with < 0) {  // a patch two loops share counts once
      const double uncut = uncut_angle(m, balls, loops[static_cast<std::size_t>(r.index)]);
      ++tally.folded;
      tally.folded_against_uncut += disks && uncut < 90;
      std::printf("\n    hole %d (%d edges): %s, folds back (%.0f° across its border; the uncut surface %.0f°%s)",
                  r.index, r.border_edges, delivered_label(r.supported, r.linear).c_str(),
                  r.continuity.max_normal_angle * 180 / std::numbers::pi, uncut, disks ? "" : ", not disk holes");
    }
    tally.open_at_lone_triangle += open_at_lone_triangle(report, r);
    if (r.status == HoleStatus::failed)
      std::printf("\n    hole %d (%d edges) left open: %s", r.index, r.border_edges, r.reason.c_str());
    else if (unfaired || refined)
      std::printf("\n    hole %d (%d edges): %s, %s", r.index, r.border_edges,
                  delivered_label(r.supported, r.linear).c_str(),
                  unfaired ? "the refined triangulation unfaired" : "faired from the refined triangulation");
  }
  if (std::any_of(report.holes.begin(), report.holes.end(),
                  [&](const HoleReport& r) { return open_at_lone_triangle(report, r); })) {
    const int still_open = open_after_repair(cut);
    tally.open_after_repair += still_open;
    std::printf("\n    repaired and filled again: %d left open", still_open);
  }
  std::printf("\n");
}

std::string fill_summary(const FillTally& t) {
  char text[640];
  std::snprintf(text, sizeof text,
                "fill: %d trials (%d refused), %d holes: %d left open (%d at a lone triangle; after repair, %d), "
                "%d faired from the refined triangulation, %d filled by it unfaired, %d folding back (%d in disk "
                "holes where the uncut surface turns less than a right angle); outputs crossing the mesh %d, not "
                "manifold %d (%d of them where the cut was manifold); slowest trial %.2f s",
                t.trials, t.refused, t.holes, t.open, t.open_at_lone_triangle, t.open_after_repair, t.refined,
                t.unfaired, t.folded, t.folded_against_uncut, t.crossing, t.non_manifold, t.made_non_manifold, t.slowest);
  return text;
}

// ---------------------------------------------------------------------------------------------
// Fair: the balls' vertices freed, as `fairsurf fair` runs without options

struct FairTally {
  int regions = 0, errors = 0, not_steady = 0, g2 = 0, crossing = 0;
  int parts = 0, g2_parts = 0;  ///< FairRegionReport::parts (a region of one part counts as one)
};

// The floor, or a flow that settled.
bool settled(const FairRegionReport& r) { return r.linear || r.flow.stop_reason == FlowStopReason::steady; }

bool steady_g2(const FairRegionReport& r) { return settled(r) && !r.linear && r.supported == Continuity::G2; }

// " [parts: G2, C2 (linear)]" for a region faired part by part; counts its parts into `tally`.
std::string parts_text(const FairRegionReport& r, FairTally& tally) {
  if (r.parts.empty()) {
    ++tally.parts;
    tally.g2_parts += steady_g2(r);
    return "";
  }
  std::string text;
  for (const FairRegionReport& part : r.parts) {
    ++tally.parts;
    tally.g2_parts += steady_g2(part);
    text += (text.empty() ? " [parts: " : ", ") + delivered_label(part.supported, part.linear);
  }
  return text + "]";
}

// The mesh given to fair_region with its region as the vertex property `region` (1 inside, 0
// elsewhere), which `fairsurf fair --region-property region` reads.
Mesh with_region_property(Mesh mesh, const std::vector<int>& region) {
  Eigen::VectorXd mark = Eigen::VectorXd::Zero(mesh.num_vertices());
  for (int v : region) mark[v] = 1;
  mesh.vertex_scalars["region"] = mark;
  return mesh;
}

void fair_trial(const ClosedMesh& m, std::uint64_t seed, bool noisy, const std::string& shape,
                const std::string& write_dir, FairTally& tally) {
  Mesh mesh = m.mesh;
  if (noisy) bench::add_normal_noise(mesh, kNoise * m.h, seed);
  ClosedMesh drawn{m.name, mesh, m.h};
  std::string label;
  const std::vector<int> region = draw_cut(drawn, seed, shape, false, label).inside;
  std::printf("fair  %-26s seed %3llu%s: %s%zu free: ", m.name.c_str(), static_cast<unsigned long long>(seed),
              noisy ? ", noise" : "", label.c_str(), region.size());
  if (region.empty()) {  // a cut with no vertex inside marks no region
    std::printf("no vertex inside the cut, not run\n");
    return;
  }
  ++tally.regions;
  const std::string trial = seed_name(m, seed) + (noisy ? "_noise" : "");
  if (!write_dir.empty()) write_trial(write_dir, trial, "region", with_region_property(mesh, region));
  Mesh faired = mesh;
  try {
    const FairRegionReport r = fair_region(faired, region, FairRegionOptions::harmonic_started());
    if (!write_dir.empty()) write_trial(write_dir, trial, "faired", with_region_property(faired, region));
    const bool steady = settled(r);
    // More crossings than the given region had (a noisy scan's may cross already).
    const std::vector<int> faces = region_faces(mesh.F, mesh.num_vertices(), region);
    const bool crossing = find_face_intersections(faired.V, faired.F, faces, 0).size() >
                          find_face_intersections(mesh.V, mesh.F, faces, 0).size();
    tally.not_steady += !steady;
    tally.g2 += steady_g2(r);
    tally.crossing += crossing;
    std::printf("%s%s%s, %.2f s%s\n", delivered_label(r.supported, r.linear).c_str(), parts_text(r, tally).c_str(),
                steady ? "" : ", NOT STEADY", r.seconds, crossing ? ", OUTPUT CROSSES" : "");
  } catch (const std::exception& e) {
    ++tally.errors;
    std::printf("error: %s\n", e.what());
  }
}

std::string fair_summary(const FairTally& t) {
  char text[300];
  std::snprintf(text, sizeof text,
                "fair: %d regions, errors %d, not steady %d, steady G2 %d (of their %d parts %d), crossing outputs %d",
                t.regions, t.errors, t.not_steady, t.g2, t.parts, t.g2_parts, t.crossing);
  return text;
}

// ---------------------------------------------------------------------------------------------
// Blend: a slab at a random orientation

struct BlendTally {
  int blends = 0, errors = 0, not_steady = 0, g2 = 0, lower = 0, folds_back = 0, crossing = 0;
  /// Errors that were refusals naming repair (RepairableMeshError: two loops that touch), and of
  /// those, the slabs still not blended once the cut is repaired (as `fairsurf blend --repair` does).
  int repairable = 0, errors_after_repair = 0;
};

// Blends `cut` again after repairing it, as `fairsurf blend --repair` does: the label delivered, or
// the error.
std::string blend_after_repair(Mesh cut, BlendTally& tally) {
  repair(cut, RepairOptions{});
  try {
    const BlendReport r = blend_loops(cut, BlendOptions{});
    return delivered_label(r.fair.supported, r.fair.linear);
  } catch (const std::exception& e) {
    ++tally.errors_after_repair;
    return std::string("error: ") + e.what();
  }
}

// The cut of slab `draw`'s next draws leave, if it has exactly two loops of at most kMaxBlendLoop
// edges; an empty mesh otherwise.
Mesh draw_slab(const ClosedMesh& m, std::mt19937_64& draw, int& vertex, Eigen::Vector3d& axis) {
  vertex = static_cast<int>(draw() % static_cast<std::uint64_t>(m.mesh.num_vertices()));
  std::normal_distribution<double> normal;
  for (int k = 0; k < 3; ++k) axis(k) = normal(draw);
  axis.normalize();
  Mesh cut = bench::cut_slab(m.mesh, vertex, axis, 2 * m.h).mesh;
  const auto loops = boundary_loops(cut.F, build_topology(cut.F, cut.num_vertices()));
  if (loops.size() != 2 || std::max(loops[0].size(), loops[1].size()) > static_cast<std::size_t>(kMaxBlendLoop))
    return {};
  return cut;
}

// `slab`: the slab's place among the mesh's, from 1.
void blend_trial(const ClosedMesh& m, const Mesh& cut, int slab, int vertex, const Eigen::Vector3d& axis,
                 const std::string& write_dir, BlendTally& tally) {
  std::printf("blend %-26s slab %2d: vertex %5d axis (%.3f, %.3f, %.3f), loops %s: ", m.name.c_str(), slab, vertex,
              axis(0), axis(1), axis(2), bench::border_sizes(cut).c_str());
  ++tally.blends;
  const std::string trial = m.name + "_slab" + std::to_string(slab);  // two slabs may share a vertex
  if (!write_dir.empty()) write_trial(write_dir, trial, "cut", cut);
  Mesh blended = cut;
  try {
    const BlendReport r = blend_loops(blended, BlendOptions{});
    if (!write_dir.empty()) write_trial(write_dir, trial, "blended", blended);
    const bool steady = r.fair.linear || r.fair.flow.stop_reason == FlowStopReason::steady;
    const bool crossing = crosses(blended, bench::rows_from(cut.num_faces(), blended.num_faces()));
    const bool back = folds_back(r.a) || folds_back(r.b);  // `fairsurf blend` warns there
    tally.not_steady += !steady;
    tally.g2 += steady && !r.fair.linear && r.fair.supported == Continuity::G2;
    tally.lower += r.fair.supported < r.fair.requested;
    tally.folds_back += back;
    tally.crossing += crossing;
    std::printf("%s%s%s, %.2f s%s\n", delivered_label(r.fair.supported, r.fair.linear).c_str(),
                steady ? "" : ", NOT STEADY", back ? ", folds back" : "", r.seconds, crossing ? ", OUTPUT CROSSES" : "");
  } catch (const RepairableMeshError& e) {
    ++tally.errors;
    ++tally.repairable;
    std::printf("error: %s\n    repaired and blended again: %s\n", e.what(), blend_after_repair(cut, tally).c_str());
  } catch (const std::exception& e) {
    ++tally.errors;
    std::printf("error: %s\n", e.what());
  }
}

std::string blend_summary(const BlendTally& t) {
  char text[400];
  std::snprintf(text, sizeof text,
                "blend: %d slabs, errors %d (%d refused for repair; after repair, %d), not steady %d, steady G2 %d, "
                "below the continuity asked for %d, folding back at a loop %d, crossing outputs %d",
                t.blends, t.errors, t.repairable, t.errors_after_repair, t.not_steady, t.g2, t.lower, t.folds_back,
                t.crossing);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fill, fair and blend on cases drawn at random on closed meshes (docs/fill.md)", "bench_stress"};
  bench::take_last_values(app);
  Args args;
  add_options(app, args);
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<ClosedMesh> meshes;
    if (args.mesh_files.empty()) meshes = bench::read_bundled_meshes(args.mesh);
    for (const std::string& file : args.mesh_files) meshes.push_back(bench::read_closed_mesh(file));
    const auto wanted = [&](const char* section) { return args.section == section || args.section == "all"; };
    std::vector<std::string> summaries;
    if (wanted("fill")) {
      FillTally tally;
      for (const ClosedMesh& m : meshes)
        for (int t = 0; t < args.trials; ++t)
          fill_trial(m, args.seed + static_cast<std::uint64_t>(t), args.cut, args.write_dir, tally);
      summaries.push_back(fill_summary(tally));
    }
    if (wanted("fair")) {
      FairTally tally;
      for (const ClosedMesh& m : meshes)
        for (bool noisy : {false, true})
          for (int t = 0; t < args.trials; ++t)
            fair_trial(m, args.seed + static_cast<std::uint64_t>(t), noisy, args.cut, args.write_dir, tally);
      summaries.push_back(fair_summary(tally));
    }
    if (wanted("blend")) {
      BlendTally tally;
      for (const ClosedMesh& m : meshes) {
        // Slabs are drawn until `trials` of them leave two loops (at most 50 draws each).
        std::mt19937_64 draw(args.seed);
        for (int drawn = 0, found = 0; drawn < 50 * args.trials && found < args.trials; ++drawn) {
          int vertex = 0;
          Eigen::Vector3d axis;
          const Mesh cut = draw_slab(m, draw, vertex, axis);
          if (cut.num_faces() == 0) continue;
          ++found;
          blend_trial(m, cut, found, vertex, axis, args.write_dir, tally);
        }
      }
      summaries.push_back(blend_summary(tally));
    }
    for (const std::string& s : summaries) std::printf("summary: %s\n", s.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
