// Real holes (issue #11): fairsurf's fill, fair and blend on holes cut out of clean closed meshes,
// measured against the uncut surface and, when CMake finds CGAL, against CGAL 5.5's
// triangulate_refine_and_fair_hole and fair at fairing_continuity(2). The protocol and every column
// are described in docs/fill.md, "Real holes benchmark".
//
// Usage: bench_real_holes [--section fill|fair|blend|all] [--mesh NAME | --mesh-file PATH...] [--no-cgal]
//                         [--quick] [--random N [--seed S]] [--cut ball|blob|slit] [--all-slabs] [--keep-flow]
//                         [--functions F ...] [--other-functions F ...]
//                         [--csv FILE]
#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/region_selection.h>
#include <fairsurf/mesh/topology.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "bench_options.h"
#include "real_holes.h"
#include "real_holes_cases.h"
#include "real_holes_rows.h"
#include "region_energy.h"
#ifdef FAIRSURF_BENCH_CGAL
#include "cgal_reference.h"
#endif

namespace {

using namespace fairsurf;
using bench::DistanceStats;

using bench::kDegrees;
constexpr double kNoise = 0.1;  // σ of the normal noise, in h

struct Args {
  std::string section = "all", mesh, csv;
  std::vector<std::string> mesh_files;  // closed meshes to cut instead of the bundled ones
  bool cgal = true, quick = false;
  bool all_slabs = false;  // blend: every_blend_slab instead of the fixed cases
  int random = 0;          // ball centres drawn at random instead of the fixed ones (0: fixed)
  std::uint64_t seed = 1;  // of those draws
  bool keep_flow = false;  // fairsurf's rows as with --keep-flow
  std::vector<std::string> functions;  // fairsurf's rows with these f instead of H (--functions)
  std::vector<std::string> other_functions;  // and weighing these on the held-out rings (--other-functions)
  std::string cut = "ball";  // fill: the holes' shape round each centre (ball, blob or slit)
  std::vector<int> radii{4, 8};  // fill and fair: the balls' radii, in h
};

// What fairsurf's own rows run: the commands' defaults, or with `--keep-flow` their settled flows
// kept over the linear floors the held-out rings and the fold and angle checks prefer.
struct Ours {
  // FillOptions{} is exactly what `fairsurf fill` runs without options (apps/fairsurf/cmd_fill.cpp
  // starts from it and sets continuity G2, method flow, f = H: the defaults).
  FillOptions fill;
  // `fairsurf fair` without options: harmonic_started() with the flags' defaults (G2, f = H, flow,
  // 200 steps), which are its own (apps/fairsurf/cmd_fair.cpp, region_fairing_args.cpp).
  FairRegionOptions fair = FairRegionOptions::harmonic_started();
  // BlendOptions{} is what `fairsurf blend` runs without options (apps/fairsurf/cmd_blend.cpp).
  BlendOptions blend;
};

Ours ours_options(bool keep_flow, const std::vector<std::string>& functions,
                  const std::vector<std::string>& other_functions) {
  Ours ours;
  if (keep_flow) {
    keep_settled_flow(ours.fill);
    keep_settled_flow(ours.fair);
    keep_settled_flow(ours.blend);
  }
  if (!functions.empty()) ours.fill.flow.functions = ours.fair.flow.functions = ours.blend.flow.functions = functions;
  ours.fill.held_out_other_functions = ours.fair.held_out_other_functions = other_functions;
  return ours;
}

// N distinct vertices of `mesh` drawn by std::mt19937_64 (whose output the standard fixes), the same
// on every platform for a seed: holes that are not the fixed cases, for the robustness of a choice
// tuned on those.
std::vector<int> random_centres(const Mesh& mesh, int count, std::uint64_t seed) {
  std::mt19937_64 draw(seed);
  std::vector<int> centres;
  const int wanted = std::min(count, mesh.num_vertices());
  while (static_cast<int>(centres.size()) < wanted) {
    const int v = static_cast<int>(draw() % static_cast<std::uint64_t>(mesh.num_vertices()));
    if (std::find(centres.begin(), centres.end(), v) == centres.end()) centres.push_back(v);
  }
  return centres;
}

// ---------------------------------------------------------------------------------------------
// Loaded meshes, their ball centres and the truth (bench/support/real_holes_cases.h)

using bench::blend_slabs;
using bench::border_sizes;
using bench::Loaded;
using bench::measure;
using bench::removed_disks;
using bench::rows_from;
using bench::Slab;
using bench::Truth;

// Deterministic per case, independent of which other cases run.
std::uint64_t noise_seed(int centre, int radius_h) {
  return 0x9e3779b97f4a7c15ULL ^ (static_cast<std::uint64_t>(centre) * 1000003ULL + static_cast<std::uint64_t>(radius_h));
}

// ---------------------------------------------------------------------------------------------
// Rows (bench/support/real_holes_rows.h) and the CSV of every row

using bench::add_note;
using bench::cgal_angle_text;
using bench::flag_fold;
using bench::number;
using bench::pair_text;
using bench::percent;
using bench::Row;
using bench::set_ratios;
using bench::smooth_text;
using bench::Tally;

std::string csv_text = bench::csv_header();

void add_csv(const Row& row) { csv_text += bench::csv_line(row); }

using Clock = std::chrono::steady_clock;

// Wall time of a call that threw (a report carries its own otherwise).
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The row of a ball case: which section, mesh, centre, radius and noise.
Row ball_row(const char* section, const Loaded& m, int centre, int radius_h, bool noisy) {
  Row row;
  row.section = section;
  row.mesh = m.name;
  row.centre = centre;
  row.radius_h = radius_h;
  row.noise = noisy ? kNoise : 0.0;
  return row;
}

// ---------------------------------------------------------------------------------------------
// Fill

// "G2", "fb:G1", "fail" per hole, comma separated.
std::string continuity_text(const FillReport& report) {
  std::string text;
  for (const HoleReport& h : report.holes) {
    if (!text.empty()) text += ",";
    if (h.status != HoleStatus::filled) text += "fail";
    else text += (h.supported != h.requested ? "fb:" : "") + delivered_label(h.supported, h.linear);
  }
  return text;
}

// fill_holes on a copy of `cut`; the new vertices' distances. Throws what fill_holes throws.
FillReport run_fill(const Mesh& cut, const FillOptions& options, const Truth& truth, double h,
                    DistanceStats& stats) {
  Mesh mesh = cut;
  FillReport report = fill_holes(mesh, options);
  stats = measure(truth, mesh.V, rows_from(cut.num_vertices(), mesh.num_vertices()), h);
  stats.removed_mean = bench::removed_mean(truth, mesh, h);
  return report;
}

// The largest max normal angle across a filled hole's border; NaN where no patch has an interior
// vertex (border_vertices 0: no measure, not 0°).
double max_border_angle(const FillReport& report) {
  double angle = NAN;
  for (const HoleReport& r : report.holes)
    if (r.continuity.border_vertices > 0)
      angle = std::isnan(angle) ? r.continuity.max_normal_angle : std::max(angle, r.continuity.max_normal_angle);
  return angle;
}

void fill_ours(const Mesh& cut, const FillOptions& options, const Truth& truth, double h, Row& row) {
  const auto start = Clock::now();
  try {
    const FillReport report = run_fill(cut, options, truth, h, row.ours);
    row.continuity = continuity_text(report);
    row.seconds = report.seconds;
    row.status = report.failed > 0 ? "failed" : "ok";
    row.angle = max_border_angle(report);
    for (const HoleReport& r : report.holes) {
      if (r.patch_shared_with < 0) row.steps += r.steps;  // a patch two loops share counts once
      if (r.status == HoleStatus::filled)
        add_choice(row, r), add_note(row, r.note);
      if (r.status == HoleStatus::failed) add_note(row, r.reason);
    }
  } catch (const std::exception& e) {
    row.seconds = seconds_since(start);
    row.status = "failed";
    row.continuity = "error";
    add_note(row, e.what());
  }
}

void fill_baseline(const Mesh& cut, const Truth& truth, double h, Row& row) {
  FillOptions options;
  options.method = FairMethod::harmonic;  // cotangent ∆³ at G2
  try {
    const FillReport report = run_fill(cut, options, truth, h, row.baseline);
    row.has_baseline = report.failed == 0;
    row.baseline_angle = max_border_angle(report);
    if (report.failed > 0) add_note(row, "∆³ failed");
  } catch (const std::exception& e) {
    add_note(row, "∆³: " + std::string(e.what()));
  }
}

void fill_cgal([[maybe_unused]] const Mesh& cut, [[maybe_unused]] const Truth& truth,
               [[maybe_unused]] double h, [[maybe_unused]] Row& row) {
#ifdef FAIRSURF_BENCH_CGAL
  const bench::CgalResult result = bench::cgal_fill_holes(cut);
  row.has_cgal = !result.moved.empty();
  row.cgal_ok = result.ok && row.has_cgal;
  if (row.has_cgal) {
    row.cgal = measure(truth, result.V, result.moved, h);
    const ContinuityMeasure border = measure_continuity(result.V, result.F, result.moved);
    if (border.border_vertices > 0) row.cgal_angle = border.max_normal_angle;
  }
  if (result.ok) {
    Mesh filled;
    filled.V = result.V;
    filled.F = result.F;
    row.cgal.removed_mean = bench::removed_mean(truth, filled, h);
  }
  if (!result.ok) add_note(row, "CGAL: " + std::string(result.error));
  else if (!row.has_cgal) add_note(row, "CGAL: no new vertex");
#endif
}

void print_fill_header() {
  std::printf("%-9s %6s %2s %5s %-8s %-12s %5s %6s | %-12s | %-12s | %-12s | %5s | %-26s | %6s %6s %-4s %6s\n", "mesh", "centre",
              "r", "noise", "edges", "continuity", "steps", "sec", "fairsurf h", "D3 h", "CGAL C2 h", "ratio",
              "smooth: fs, D3, CGAL, ratio", "angle", "uncut", "fold", "cgal");
}

void print_fill_row(const Row& r) {
  std::printf("%-9s %6d %2d %5.2f %-8s %-12s %5d %6.2f | %s | %s | %s | %5s | %s | %6s %6s %-4s %6s%s%s\n", r.mesh.c_str(),
              r.centre, r.radius_h, r.noise, r.size.c_str(), r.continuity.c_str(), r.steps, r.seconds,
              pair_text(r.ours.count > 0, r.ours).c_str(), pair_text(r.has_baseline, r.baseline).c_str(),
              pair_text(r.has_cgal, r.cgal).c_str(), number(r.ratio, "%.2f").c_str(), smooth_text(r).c_str(),
              number(r.angle * kDegrees, "%.1f").c_str(), number(r.uncut_angle * kDegrees, "%.1f").c_str(),
              r.fold ? "FOLD" : "-", cgal_angle_text(r).c_str(), r.note.empty() ? "" : "  ", r.note.c_str());
  std::fflush(stdout);
}

// The cut of a fill row: the ball of radius r·h round `centre`, or (--cut blob, slit) an irregular
// hole from a face at `centre` of about the ball's size, without lone triangles at its border:
// a blob of as many faces as a disk of radius r·h holds (4π r²/√3), or a random walk of 4r steps
// thickened to the faces at its vertices (a slit about 2 h wide), drawn from the row's noise seed.
bench::CutMesh fill_cut(const Loaded& m, int centre, int radius_h, const std::string& shape) {
  const Eigen::Vector3d c = m.mesh.V.row(centre).transpose();
  if (shape == "ball") return bench::cut_ball(m.mesh, c, radius_h * m.h);
  int start = 0;
  while (m.mesh.F(start, 0) != centre && m.mesh.F(start, 1) != centre && m.mesh.F(start, 2) != centre) ++start;
  std::mt19937_64 draw(noise_seed(centre, radius_h));
  const bool blob = shape == "blob";
  const int size = blob ? static_cast<int>(std::lround(4 * std::numbers::pi * radius_h * radius_h / std::sqrt(3.0)))
                        : 4 * radius_h;
  return bench::cut_irregular(m.mesh, start, blob ? bench::CutShape::blob : bench::CutShape::slit, size, draw, true);
}

Row fill_case(const Loaded& m, int centre, int radius_h, bool noisy, const std::string& shape, const Ours& ours,
              bool cgal) {
  Row row = ball_row("fill", m, centre, radius_h, noisy);
  const Eigen::Vector3d c = m.mesh.V.row(centre).transpose();
  bench::CutMesh cut = fill_cut(m, centre, radius_h, shape);
  if (noisy) bench::add_normal_noise(cut.mesh, kNoise * m.h, noise_seed(centre, radius_h));
  row.size = border_sizes(cut.mesh);
  row.disks = removed_disks(m.mesh, cut.mesh);
  if (!row.disks) add_note(row, "not disk holes (excluded from the summary)");
  Truth truth(m, c);
  truth.removed.resize(static_cast<Eigen::Index>(cut.dropped.size()), 3);
  for (std::size_t i = 0; i < cut.dropped.size(); ++i)
    truth.removed.row(static_cast<Eigen::Index>(i)) = m.mesh.V.row(cut.dropped[i]);
  fill_ours(cut.mesh, ours.fill, truth, m.h, row);
  fill_baseline(cut.mesh, truth, m.h, row);
  if (cgal) fill_cgal(cut.mesh, truth, m.h, row);
  if (!cut.dropped.empty())
    row.uncut_angle = measure_continuity(m.mesh.V, m.mesh.F, cut.dropped).max_normal_angle;
  // Each ratio where CGAL's fill succeeded and has that measure (a fill with no new vertex has only
  // the removed vertices' distance).
  if (row.status == "ok" && (row.cgal_ok || !std::isnan(row.cgal.removed_mean))) set_ratios(row);
  flag_fold(row);
  return row;
}

std::string fill_summary(const char* label, const Tally& t) {
  char text[1024];
  std::snprintf(text, sizeof text, "%s holes: %d (+%d not disks), failed %d, G2 %d (%s), folds %d (CGAL %d), %s",
                label, t.rows, t.excluded, t.failed, t.g2, percent(t.g2, t.rows).c_str(), t.folds, t.cgal_folds,
                t.comparison_text().c_str());
  return text;
}

bool all_g2(const std::string& continuity) {
  std::size_t start = 0;
  while (start <= continuity.size()) {
    const std::size_t end = std::min(continuity.find(',', start), continuity.size());
    if (continuity.substr(start, end - start) != "G2") return false;
    start = end + 1;
  }
  return true;
}

std::string fill_section(const std::vector<Loaded>& meshes, const Ours& ours, bool cgal, const std::string& shape,
                         const std::vector<int>& radii) {
  if (shape == "ball")
    std::printf("== fill: holes cut by a ball of radius r·h around vertex `centre`; distances in h ==\n");
  else
    std::printf("== fill: a %s of faces cut from vertex `centre`, about as large as a ball of radius r·h; distances "
                "in h ==\n",
                shape.c_str());
  print_fill_header();
  Tally tally[2];
  for (int noisy = 0; noisy < 2; ++noisy)
    for (const Loaded& m : meshes)
      for (int centre : m.centres)
        for (int radius_h : radii) {
          const Row row = fill_case(m, centre, radius_h, noisy, shape, ours, cgal);
          print_fill_row(row);
          add_csv(row);
          Tally& t = tally[noisy];
          if (!row.disks) {
            ++t.excluded;
            continue;
          }
          ++t.rows;
          t.failed += row.status != "ok";
          t.g2 += row.status == "ok" && all_g2(row.continuity);
          t.folds += row.fold;
          t.cgal_folds += row.cgal_fold;
          if (row.status == "ok") t.compare(row);  // a failed fill has no ratio either
        }
  const std::string summary = fill_summary("clean", tally[0]) + " | " + fill_summary("noise 0.1h", tally[1]);
  std::printf("fill summary: %s\n\n", summary.c_str());
  return summary;
}

// ---------------------------------------------------------------------------------------------
// Fair: the ball's vertices freed on the uncut mesh

void fair_ours(const Mesh& mesh, const Topology& topo, const std::vector<int>& region,
               const FairRegionOptions& options, const Truth& truth, double h, Row& row) {
  Mesh faired = mesh;
  const auto start = Clock::now();
  try {
    const FairRegionReport report = fair_region(faired, region, options);
    row.status = report.linear || report.flow.stop_reason == FlowStopReason::steady ? "steady" : "not steady";
    row.continuity = delivered_label(report.supported, report.linear);
    row.steps = report.flow.accepted_steps;
    row.seconds = report.seconds;
    row.angle = report.continuity.max_normal_angle;
    row.ours = measure(truth, faired.V, region, h);
    row.energy = bench::region_energy(faired.V, faired.F, topo, region);
    add_choice(row, report);
    add_note(row, report.note);
  } catch (const std::exception& e) {
    row.seconds = seconds_since(start);
    row.status = "error";
    row.continuity = "error";
    add_note(row, e.what());
  }
}

void fair_baseline(const Mesh& mesh, const Topology& topo, const std::vector<int>& region, const Truth& truth,
                   double h, Row& row) {
  Mesh faired = mesh;
  FairRegionOptions options = FairRegionOptions::harmonic_started();
  options.method = FairMethod::harmonic;
  try {
    const FairRegionReport report = fair_region(faired, region, options);
    row.has_baseline = true;
    row.baseline_angle = report.continuity.max_normal_angle;
    row.baseline = measure(truth, faired.V, region, h);
    row.baseline_energy = bench::region_energy(faired.V, faired.F, topo, region);
  } catch (const std::exception& e) {
    add_note(row, "∆³: " + std::string(e.what()));
  }
}

// The flow's own steady state, as if the held-out rings and the fold check always let it through:
// what the energy prefers, beside what is delivered.
void fair_flow_alone(const Mesh& mesh, const Topology& topo, const std::vector<int>& region, const Truth& truth,
                     double h, Row& row) {
  Mesh faired = mesh;
  FairRegionOptions options = FairRegionOptions::harmonic_started();
  options.held_out_rings = 0;
  options.max_border_angle_ratio = std::numeric_limits<double>::infinity();
  try {
    const FairRegionReport report = fair_region(faired, region, options);
    // The floor (the flow did not settle, or its state crossed the mesh): no flow state to weigh.
    if (report.linear) return;
    row.has_flow = true;
    row.flow = measure(truth, faired.V, region, h);
    row.flow_energy = bench::region_energy(faired.V, faired.F, topo, region);
  } catch (const std::exception&) {
    // Nor where it threw; the delivered fairing's own run reports the error.
  }
}

void fair_cgal([[maybe_unused]] const Mesh& mesh, [[maybe_unused]] const Topology& topo,
               [[maybe_unused]] const std::vector<int>& region,
               [[maybe_unused]] const Truth& truth, [[maybe_unused]] double h,
               [[maybe_unused]] Row& row) {
#ifdef FAIRSURF_BENCH_CGAL
  const bench::CgalResult result = bench::cgal_fair(mesh, region);
  row.has_cgal = result.V.rows() > 0;
  row.cgal_ok = result.ok;
  if (row.has_cgal) {
    row.cgal = measure(truth, result.V, result.moved, h);
    row.cgal_energy = bench::region_energy(result.V, mesh.F, topo, region);
    const ContinuityMeasure border = measure_continuity(result.V, mesh.F, region);
    if (border.border_vertices > 0) row.cgal_angle = border.max_normal_angle;
  }
  if (!result.ok) add_note(row, "CGAL: " + std::string(result.error));
#endif
}

Row fair_case(const Loaded& m, int centre, int radius_h, bool noisy, const Ours& ours, bool cgal) {
  Row row = ball_row("fair", m, centre, radius_h, noisy);
  const Eigen::Vector3d c = m.mesh.V.row(centre).transpose();
  Mesh mesh = m.mesh;
  if (noisy) bench::add_normal_noise(mesh, kNoise * m.h, noise_seed(centre, radius_h));
  // As `fairsurf fair --region-sphere`: the vertices strictly inside the ball (of the clean mesh).
  const std::vector<int> region = vertices_in_ball(m.mesh.V, c, radius_h * m.h);
  row.size = std::to_string(region.size());
  const Truth truth(m, c);
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  row.truth_energy = bench::region_energy(m.mesh.V, m.mesh.F, topo, region);
  fair_ours(mesh, topo, region, ours.fair, truth, m.h, row);
  fair_baseline(mesh, topo, region, truth, m.h, row);
  fair_flow_alone(mesh, topo, region, truth, m.h, row);
  if (cgal) fair_cgal(mesh, topo, region, truth, m.h, row);
  row.uncut_angle = measure_continuity(m.mesh.V, m.mesh.F, region).max_normal_angle;
  if (row.has_cgal && row.cgal_ok && row.ours.count > 0 && row.cgal.mean > 0) set_ratios(row);
  flag_fold(row);
  return row;
}

// The flow's steady state (fair_flow_alone): its mean distance in h, then the region's energy on the
// uncut surface and on the ∆³ baseline's result over the flow's.
std::string flow_text(const Row& r) {
  const auto over_flow = [&](double e) { return number(e / r.flow_energy, "%.2f"); };
  char text[64];
  std::snprintf(text, sizeof text, "%6s %5s %5s", r.has_flow ? number(r.flow.mean, "%.3f").c_str() : "-",
                over_flow(r.truth_energy).c_str(), over_flow(r.baseline_energy).c_str());
  return text;
}

// Over the clean rows where the flow settled (fair_flow_alone): how the energy ranks the surface
// the region was cut from, the flow's steady state and the ∆³ baseline's result (geometric means of
// their energies over the flow's), and how the distances to that surface rank the last two.
struct EnergyTally {
  int rows = 0, truth_higher = 0, flow_closer = 0;
  double log_truth = 0, log_baseline = 0, log_distance = 0;
  void add(const Row& r) {
    if (r.noise > 0 || !r.has_flow || !r.has_baseline || !(r.flow_energy > 0) || !(r.truth_energy > 0) ||
        !(r.baseline_energy > 0) || !(r.baseline.mean > 0))
      return;
    ++rows;
    truth_higher += r.truth_energy > r.flow_energy;
    flow_closer += r.flow.mean < r.baseline.mean;
    log_truth += std::log(r.truth_energy / r.flow_energy);
    log_baseline += std::log(r.baseline_energy / r.flow_energy);
    log_distance += std::log(r.flow.mean / r.baseline.mean);
  }
  std::string text() const {
    const auto mean = [&](double log_sum) { return number(rows > 0 ? std::exp(log_sum / rows) : NAN, "%.2f"); };
    char text[320];
    std::snprintf(text, sizeof text,
                  "flow's steady state (clean, %d settled): energy of the uncut surface %s times its own "
                  "(higher on %d), of D3 %s; distance %s times D3's (closer on %d)",
                  rows, mean(log_truth).c_str(), truth_higher, mean(log_baseline).c_str(),
                  mean(log_distance).c_str(), flow_closer);
    return text;
  }
};

void print_fair_header() {
  std::printf("%-9s %6s %2s %5s %5s %-10s %-4s %5s %6s | %-12s | %-12s | %-12s | %5s | %-26s | %6s %6s %-4s %6s | %-18s\n",
              "mesh", "centre", "r", "noise", "free", "exit", "cont", "steps", "sec", "fairsurf h", "D3 h", "CGAL C2 h",
              "ratio", "smooth: fs, D3, CGAL, ratio", "angle", "uncut", "fold", "cgal", "flow h E/flow: uncut D3");
}

void print_fair_row(const Row& r) {
  std::printf("%-9s %6d %2d %5.2f %5s %-10s %-4s %5d %6.2f | %s | %s | %s | %5s | %s | %6s %6s %-4s %6s | %-18s%s%s\n",
              r.mesh.c_str(), r.centre, r.radius_h, r.noise, r.size.c_str(), r.status.c_str(), r.continuity.c_str(),
              r.steps, r.seconds, pair_text(r.ours.count > 0, r.ours).c_str(),
              pair_text(r.has_baseline, r.baseline).c_str(), pair_text(r.has_cgal, r.cgal).c_str(),
              number(r.ratio, "%.2f").c_str(), smooth_text(r).c_str(), number(r.angle * kDegrees, "%.1f").c_str(),
              number(r.uncut_angle * kDegrees, "%.1f").c_str(), r.fold ? "FOLD" : "-", cgal_angle_text(r).c_str(),
              flow_text(r).c_str(), r.note.empty() ? "" : "  ", r.note.c_str());
  std::fflush(stdout);
}

std::string fair_section(const std::vector<Loaded>& meshes, const Ours& ours, bool cgal, const std::vector<int>& radii) {
  std::printf("== fair: the vertices strictly inside the ball freed on the uncut mesh; distances in h ==\n");
  print_fair_header();
  Tally tally;
  EnergyTally energies;
  int errors = 0;
  for (int noisy = 0; noisy < 2; ++noisy)
    for (const Loaded& m : meshes)
      for (int centre : m.centres)
        for (int radius_h : radii) {
          const Row row = fair_case(m, centre, radius_h, noisy, ours, cgal);
          print_fair_row(row);
          energies.add(row);
          add_csv(row);
          ++tally.rows;
          errors += row.status == "error";
          tally.steady += row.status == "steady" && row.continuity == "G2";
          tally.folds += row.fold;
          tally.cgal_folds += row.cgal_fold;
          tally.compare(row);
        }
  char text[1024];
  std::snprintf(text, sizeof text, "fair: %d steady G2 of %d, errors %d, folds %d (CGAL %d), %s; %s", tally.steady,
                tally.rows, errors, tally.folds, tally.cgal_folds, tally.comparison_text().c_str(),
                energies.text().c_str());
  std::printf("fair summary: %s\n\n", text);
  return text;
}

// ---------------------------------------------------------------------------------------------
// Blend: a slab of width 4h removed, the two loops joined again

// The linear ∆³ tube between the same loops (`fairsurf blend --method harmonic`): the baseline a
// blend's G2 tube must not lose to.
void blend_baseline(const Mesh& cut, const Truth& truth, double h, Row& row) {
  Mesh mesh = cut;
  BlendOptions options;
  options.method = FairMethod::harmonic;
  try {
    blend_loops(mesh, options);
    row.baseline = measure(truth, mesh.V, rows_from(cut.num_vertices(), mesh.num_vertices()), h);
    row.has_baseline = true;
  } catch (const std::exception& e) {
    add_note(row, "∆³: " + std::string(e.what()));
  }
}

Row blend_case(const Loaded& m, const Slab& slab, const BlendOptions& options) {
  Row row;
  row.section = "blend";
  row.mesh = m.name;
  row.centre = slab.vertex;
  row.radius_h = slab.axis;  // the CSV's radius_h column holds the axis (0 x, 1 y, 2 z)
  const Eigen::Vector3d c = m.mesh.V.row(slab.vertex).transpose();
  const bench::CutMesh cut = bench::cut_slab(m.mesh, slab.vertex, Eigen::Vector3d::Unit(slab.axis), 2 * m.h);
  row.size = border_sizes(cut.mesh);
  const Truth truth(m, c);
  Mesh mesh = cut.mesh;
  const auto start = Clock::now();
  try {
    const BlendReport report = blend_loops(mesh, options);
    row.status = report.fair.linear || report.fair.flow.stop_reason == FlowStopReason::steady ? "steady" : "not steady";
    row.continuity = delivered_label(report.fair.supported, report.fair.linear);
    add_note(row, report.fair.note);
    row.steps = report.fair.flow.accepted_steps;
    row.seconds = report.seconds;
    row.angle = std::max(report.a.border.max_normal_angle, report.b.border.max_normal_angle);
    row.uncut_angle = std::max(report.a.reference.max_normal_angle, report.b.reference.max_normal_angle);
    row.ours = measure(truth, mesh.V, rows_from(cut.mesh.num_vertices(), mesh.num_vertices()), m.h);
    flag_fold(row);
  } catch (const std::exception& e) {
    row.seconds = seconds_since(start);
    row.status = "error";
    add_note(row, e.what());
  }
  blend_baseline(cut.mesh, truth, m.h, row);
  return row;
}

// The delivered tubes' mean distances over the linear ∆³ tubes' on the same slabs, by one measure.
struct BaselineRatios {
  // Its ratio(): how many, below 1, geometric mean, worst; its baseline(): how many the same (the
  // linear tube delivered).
  bench::Comparison ratios;
  int worse_by_a_tenth = 0;
  void add(double ours, double baseline) {
    if (!(baseline > 0)) return;
    const double ratio = ours / baseline;
    const int compared = ratios.compared;
    ratios.ratio(ratio);
    if (ratios.compared == compared) return;  // NaN: ours was not measured
    ratios.baseline(ours, baseline);
    worse_by_a_tenth += ratio > 1.1;
  }
  std::string text() const {
    char text[200];
    std::snprintf(text, sizeof text,
                  "below D3 on %d of %d (the same on %d), geo-mean ratio to D3 %.2f, above 1.1x D3 on %d, worst %.2fx",
                  ratios.below, ratios.compared, ratios.same_as_baseline, ratios.geo_mean(), worse_by_a_tenth,
                  ratios.worst);
    return text;
  }
};

// BaselineRatios to the uncut mesh and to its smooth stand-in (the torus's own surface).
struct BlendRatios {
  BaselineRatios faceted, smooth;
  void add(const Row& row) {
    if (row.ours.count == 0 || !row.has_baseline) return;
    faceted.add(row.ours.mean, row.baseline.mean);
    smooth.add(row.ours.smooth_mean, row.baseline.smooth_mean);
  }
  std::string text() const { return "mean distance " + faceted.text() + "; to the smooth surface: " + smooth.text(); }
};

std::string blend_section(const std::vector<Loaded>& meshes, const BlendOptions& options, bool quick, bool all_slabs) {
  std::printf("== blend: the band of the slab |(x - centre)·axis| < 2h through `centre` removed, the two loops "
              "blended; distances in h ==\n");
  std::printf("%-9s %6s %4s %-8s %-10s %-11s %5s %6s | %-12s | %-12s %5s | %6s %6s %s\n", "mesh", "centre", "axis",
              "loops", "exit", "cont", "steps", "sec", "fairsurf h", "D3 h", "/D3", "angle", "ref", "fold");
  int rows = 0, steady = 0, folds = 0;
  BlendRatios ratios;
  for (const Loaded& m : meshes)
    for (const Slab& slab : all_slabs ? bench::every_blend_slab(m) : blend_slabs(m, quick ? 1 : 2)) {
      const Row r = blend_case(m, slab, options);
      const double ratio = r.ours.count > 0 && r.has_baseline ? r.ours.mean / r.baseline.mean : NAN;
      std::printf("%-9s %6d %4c %-8s %-10s %-11s %5d %6.2f | %s | %s %5s | %6s %6s %s%s%s\n", r.mesh.c_str(),
                  r.centre, "xyz"[slab.axis], r.size.c_str(), r.status.c_str(), r.continuity.c_str(), r.steps,
                  r.seconds, pair_text(r.ours.count > 0, r.ours).c_str(), pair_text(r.has_baseline, r.baseline).c_str(),
                  number(ratio, "%.2f").c_str(), number(r.angle * kDegrees, "%.1f").c_str(),
                  number(r.uncut_angle * kDegrees, "%.1f").c_str(), r.fold ? "FOLD" : "-",
                  r.note.empty() ? "" : "  ", r.note.c_str());
      std::fflush(stdout);
      add_csv(r);
      ++rows;
      steady += r.status == "steady" && r.continuity == "G2";
      folds += r.fold;
      ratios.add(r);
    }
  const std::string text = "blend: " + std::to_string(steady) + " steady G2 of " + std::to_string(rows) + ", folds " +
                           std::to_string(folds) + ", " + ratios.text();
  std::printf("blend summary: %s\n\n", text.c_str());
  return text;
}

// ---------------------------------------------------------------------------------------------
// Main

void add_options(CLI::App& app, Args& args) {
  bench::add_case_options(app, args.section, args.mesh, args.mesh_files);
  app.add_flag_callback("--no-cgal", [&args] { args.cgal = false; }, "Leave out the CGAL columns");
  app.add_flag("--quick", args.quick, "One ball centre and one blend plane a mesh");
  // Not CLI::NonNegativeNumber: its refusal prints DBL_MAX's 309 digits.
  app.add_option("--random", args.random, "Draw N ball centres a mesh at random instead of the fixed ones (0: fixed)")
      ->type_name("N")
      ->check(CLI::Range(0, std::numeric_limits<int>::max()).description(">= 0"));
  app.add_option("--seed", args.seed, "Seed of the --random draws")->type_name("S")->capture_default_str();
  app.add_option("--cut", args.cut,
                 "Fill: cut a ball round each centre, or an irregular blob or slit of faces of about its size")
      ->check(CLI::IsMember({"ball", "blob", "slit"}))
      ->capture_default_str();
  app.add_option("--radii", args.radii, "Fill and fair: the balls' radii in h, one or more (small holes: 1 2)")
      ->type_name("R")
      ->delimiter(',')
      ->check(CLI::Range(1, 1000).description(">= 1"))
      ->capture_default_str();
  app.add_flag("--all-slabs", args.all_slabs, "Blend every plane that qualifies instead of the fixed cases");
  app.add_option("--csv", args.csv, "Write every row of every section to FILE")->type_name("FILE");
  app.add_flag("--keep-flow", args.keep_flow,
               "fairsurf's rows as `fairsurf fill|fair|blend --keep-flow`: the settled flow kept over the linear "
               "floor that the held-out rings and the fold and angle checks prefer");
  app.add_option("--functions,--f", args.functions,
                 "fairsurf's rows with these energy functions f(H,K) instead of H, one per --functions "
                 "(as `fairsurf fill|fair|blend --functions`)")
      ->type_name("F")
      ->allow_extra_args(false);
  app.add_option("--other-functions", args.other_functions,
                 "fill and fair: also weigh the flow with these energy functions on the held-out rings, one per "
                 "--other-functions (as `fairsurf fill|fair --other-functions`)")
      ->type_name("F")
      ->allow_extra_args(false);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fairsurf's fill, fair and blend on holes cut out of clean closed meshes (docs/fill.md)",
               "bench_real_holes"};
  bench::take_last_values(app);
  Args args;
  add_options(app, args);
  CLI11_PARSE(app, argc, argv);
  try {
#ifndef FAIRSURF_BENCH_CGAL
    if (args.cgal) std::printf("CGAL was not found at configure time: no CGAL columns\n");
    args.cgal = false;
#endif
    std::vector<Loaded> meshes;
    if (args.mesh_files.empty()) meshes = bench::load_meshes(args.mesh, args.quick);
    for (const std::string& file : args.mesh_files) meshes.push_back(bench::load_mesh_file(file, args.quick));
    if (args.random > 0)
      for (Loaded& m : meshes) m.centres = random_centres(m.mesh, args.random, args.seed);
    for (const Loaded& m : meshes) {
      std::printf("%s: %d vertices, %d faces, h = %.6g; centres", m.name.c_str(), m.mesh.num_vertices(),
                  m.mesh.num_faces(), m.h);
      for (int c : m.centres) std::printf(" %d", c);
      std::printf("\n");
    }
    const Ours ours = ours_options(args.keep_flow, args.functions, args.other_functions);
    if (args.keep_flow) std::printf("fairsurf's rows with --keep-flow\n");
    for (const std::string& f : args.functions) std::printf("fairsurf's rows with --functions %s\n", f.c_str());
    for (const std::string& f : args.other_functions)
      std::printf("fairsurf's rows with --other-functions %s\n", f.c_str());
    std::vector<std::string> summaries;
    const auto wanted = [&](const char* section) { return args.section == section || args.section == "all"; };
    if (wanted("fill")) summaries.push_back(fill_section(meshes, ours, args.cgal, args.cut, args.radii));
    if (wanted("fair")) summaries.push_back(fair_section(meshes, ours, args.cgal, args.radii));
    if (wanted("blend")) summaries.push_back(blend_section(meshes, ours.blend, args.quick, args.all_slabs));
    std::string overall;
    for (const auto& s : summaries) overall += (overall.empty() ? "" : " | ") + s;
    std::printf("overall%s: %s\n", args.keep_flow ? " (--keep-flow)" : "", overall.c_str());
    if (!args.csv.empty()) write_file_atomically(args.csv, csv_text, "bench_real_holes");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
