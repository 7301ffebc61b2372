// The rows of bench_real_holes: one case's figures, its CSV line and printed columns, and the
// counts and ratios that a section's summary line gives (docs/fill.md, "Real holes benchmark").
#pragma once

#include "real_holes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace fairsurf::bench {

inline constexpr double kDegrees = 180.0 / std::numbers::pi;

struct Row {
  std::string section, mesh, status, continuity, note, size;
  // Per hole (comma-separated): which held-out candidate was delivered, and the held-out errors
  // "flow/2-ring flow/linear/refined" in mean edges (empty where not weighed).
  std::string choice, held_out;
  int centre = 0, radius_h = 0, steps = 0;
  double noise = 0, seconds = 0;
  DistanceStats ours, baseline, cgal;
  bool has_baseline = false, has_cgal = false, cgal_ok = false, fold = false, cgal_fold = false;
  bool disks = true;  // fill: the cut removed disks only (a ball across a thin tube removes an annulus)
  double ratio = NAN, smooth_ratio = NAN, removed_ratio = NAN, angle = NAN, uncut_angle = NAN, cgal_angle = NAN;
  double baseline_angle = NAN;  // the ∆³ fill's or fairing's border angle, as `angle`
  // fair: region_energy of the uncut (clean) mesh, of fairsurf's result, the ∆³ baseline's and CGAL's,
  // and the sixth-order flow's steady state delivered whatever the held-out rings and fold check
  // say (flow: its distances; has_flow where it settled).
  double truth_energy = NAN, energy = NAN, baseline_energy = NAN, cgal_energy = NAN, flow_energy = NAN;
  DistanceStats flow;
  bool has_flow = false;
};

// Ratios of fairsurf's mean distance to CGAL's, and comparisons with the ∆³ baseline's, by one
// measure (to the uncut mesh, or to its smooth stand-in).
struct Comparison {
  int compared = 0, below = 0, baseline_compared = 0, below_baseline = 0, same_as_baseline = 0;
  double log_ratio = 0, worst = 0;
  void ratio(double r) {
    if (std::isnan(r) || r <= 0) return;
    ++compared;
    below += r < 1;
    log_ratio += std::log(r);
    worst = std::max(worst, r);
  }
  void baseline(double ours, double baseline) {
    ++baseline_compared;
    below_baseline += ours < baseline;
    same_as_baseline += ours == baseline;  // the linear solution delivered: the baseline's own fill
  }
  /// Geometric mean of the ratios; NaN before the first.
  double geo_mean() const { return compared > 0 ? std::exp(log_ratio / compared) : NAN; }
  std::string text() const {
    std::string t = "no CGAL comparison";
    if (compared > 0) {
      char text[160];
      std::snprintf(text, sizeof text, "mean distance below CGAL on %d of %d (%.0f%%), geo-mean ratio %.2f, worst %.2fx",
                    below, compared, 100.0 * below / compared, geo_mean(), worst);
      t = text;
    }
    return t + ", below D3 on " + std::to_string(below_baseline) + " of " + std::to_string(baseline_compared) +
           " (the same as D3 on " + std::to_string(same_as_baseline) + ")";
  }
};

// Counts over the rows of one section and noise level.
struct Tally {
  int rows = 0, failed = 0, g2 = 0, folds = 0, cgal_folds = 0, steady = 0, excluded = 0;
  Comparison faceted, smooth, removed;
  // The ratios to CGAL and the comparison with the ∆³ baseline on the same input, by each measure.
  void compare(const Row& row) {
    faceted.ratio(row.ratio);
    smooth.ratio(row.smooth_ratio);
    removed.ratio(row.removed_ratio);
    if (row.has_baseline && !std::isnan(row.ours.removed_mean) && !std::isnan(row.baseline.removed_mean))
      removed.baseline(row.ours.removed_mean, row.baseline.removed_mean);
    if (row.ours.count == 0 || !row.has_baseline) return;
    faceted.baseline(row.ours.mean, row.baseline.mean);
    smooth.baseline(row.ours.smooth_mean, row.baseline.smooth_mean);
  }
  std::string comparison_text() const {
    return faceted.text() + "; to the smooth surface: " + smooth.text() +
           (removed.baseline_compared > 0 ? "; the removed vertices to the fill: " + removed.text() : "");
  }
};

/// The CSV's header line and one row's line (all sections share the columns).
std::string csv_header();
std::string csv_line(const Row& row);

/// `x` printed with `format`; empty for NaN.
std::string number(double x, const char* format = "%.4g");

/// FOLD: a border angle above 1.5 times the uncut mesh's reading at the same place, or 5°. CGAL's
/// result is judged by the same rule, so that a fold count can be told from the measure's own floor
/// (one-sided fits on a coarse or noisy ring read tens of degrees on any smooth fill).
bool folds(double angle, double uncut_angle);
/// Sets row.fold and row.cgal_fold by that rule.
void flag_fold(Row& row);
/// fairsurf's mean distance over CGAL's, by each measure both have.
void set_ratios(Row& row);
void add_note(Row& row, const std::string& note);
/// Appends one hole's (or region's) held-out decision to row.choice and row.held_out (its four
/// held-out errors, the roughness around it, and the other functions' two errors): `report` is a
/// HoleReport or a FairRegionReport, which name these fields alike.
template <class Report>
void add_choice(Row& row, const Report& report) {
  const char* choice = report.refined_start ? "refined"
                       : report.linear      ? "linear"
                       : report.two_ring_boundary_fits ? (report.other_functions ? "other 2-ring flow" : "2-ring flow")
                                                       : (report.other_functions ? "other flow" : "flow");
  if (!row.choice.empty()) {
    row.choice.push_back(',');
    row.held_out.push_back(',');
  }
  row.choice.append(choice);
  for (const double error : {report.held_out_flow_error, report.held_out_two_ring_flow_error,
                             report.held_out_linear_error})
    row.held_out.append(number(error)).push_back('/');
  row.held_out.append(number(report.held_out_refined_linear_error)).push_back('/');
  row.held_out.append(number(report.held_out_roughness));
  for (const double error : {report.held_out_other_flow_error, report.held_out_other_two_ring_flow_error})
    row.held_out.append("/").append(number(error));
}

/// CGAL's border angle in degrees, starred when it folds by the same rule.
std::string cgal_angle_text(const Row& r);
/// The smooth-surface means of fairsurf, the ∆³ baseline and CGAL, and fairsurf's ratio to CGAL's.
std::string smooth_text(const Row& r);
/// "mean max" of a distance, or dashes.
std::string pair_text(bool has, const DistanceStats& s);
std::string percent(int part, int whole);

}  // namespace fairsurf::bench
