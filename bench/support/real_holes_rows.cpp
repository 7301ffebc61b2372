#include "real_holes_rows.h"

namespace fairsurf::bench {
namespace {

std::string csv_escape(std::string s) {
  std::replace(s.begin(), s.end(), '"', '\'');
  return "\"" + s + "\"";
}

}  // namespace

std::string csv_header() {
  return "section,mesh,centre,radius_h,noise_h,size,status,continuity,steps,seconds,mean_h,max_h,"
         "baseline_mean_h,baseline_max_h,cgal_mean_h,cgal_max_h,ratio,angle_deg,uncut_angle_deg,fold,"
         "cgal_angle_deg,cgal_fold,smooth_mean_h,baseline_smooth_mean_h,cgal_smooth_mean_h,smooth_ratio,disks,new_vertices,cgal_new_vertices,choice,held_out,"
         "truth_energy,energy,baseline_energy,cgal_energy,flow_mean_h,flow_energy,baseline_angle_deg,"
         "removed_mean_h,baseline_removed_mean_h,cgal_removed_mean_h,removed_ratio,note\n";
}

std::string number(double x, const char* format) {
  if (std::isnan(x)) return "";
  char text[64];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

bool folds(double angle, double uncut_angle) {
  return !std::isnan(angle) && !std::isnan(uncut_angle) && angle > std::max(1.5 * uncut_angle, 5.0 / kDegrees);
}

void flag_fold(Row& row) {
  row.fold = folds(row.angle, row.uncut_angle);
  row.cgal_fold = folds(row.cgal_angle, row.uncut_angle);
}

void set_ratios(Row& row) {
  if (row.ours.count > 0 && row.cgal.count > 0 && row.cgal.mean > 0) {
    row.ratio = row.ours.mean / row.cgal.mean;
    row.smooth_ratio = row.ours.smooth_mean / row.cgal.smooth_mean;
  }
  if (row.cgal.removed_mean > 0) row.removed_ratio = row.ours.removed_mean / row.cgal.removed_mean;
}

void add_note(Row& row, const std::string& note) { row.note += (row.note.empty() ? "" : "; ") + note; }

std::string csv_line(const Row& r) {
  const auto stat = [](bool has, double x) { return has ? number(x) : std::string(); };
  return r.section + "," + r.mesh + "," + std::to_string(r.centre) + "," + std::to_string(r.radius_h) + "," +
              number(r.noise) + "," + csv_escape(r.size) + "," + csv_escape(r.status) + "," +
              csv_escape(r.continuity) + "," + std::to_string(r.steps) + "," + number(r.seconds) + "," +
              stat(r.ours.count > 0, r.ours.mean) + "," + stat(r.ours.count > 0, r.ours.max) + "," +
              stat(r.has_baseline, r.baseline.mean) + "," + stat(r.has_baseline, r.baseline.max) + "," +
              stat(r.has_cgal, r.cgal.mean) + "," + stat(r.has_cgal, r.cgal.max) + "," + number(r.ratio) + "," +
              number(r.angle * kDegrees) + "," + number(r.uncut_angle * kDegrees) + "," + (r.fold ? "1" : "0") +
              "," + number(r.cgal_angle * kDegrees) + "," + (r.cgal_fold ? "1" : "0") + "," +
              stat(r.ours.count > 0, r.ours.smooth_mean) + "," + stat(r.has_baseline, r.baseline.smooth_mean) + "," +
              stat(r.has_cgal, r.cgal.smooth_mean) + "," + number(r.smooth_ratio) + "," + (r.disks ? "1" : "0") +
              "," + std::to_string(r.ours.count) + "," + (r.has_cgal ? std::to_string(r.cgal.count) : std::string()) +
              "," + csv_escape(r.choice) + "," + csv_escape(r.held_out) + "," + number(r.truth_energy) + "," +
              number(r.energy) + "," + number(r.baseline_energy) + "," + number(r.cgal_energy) + "," +
              stat(r.has_flow, r.flow.mean) + "," + number(r.flow_energy) + "," + number(r.baseline_angle * kDegrees) + "," +
              number(r.ours.removed_mean) + "," + stat(r.has_baseline, r.baseline.removed_mean) + "," +
              number(r.cgal.removed_mean) + "," + number(r.removed_ratio) + "," + csv_escape(r.note) + "\n";
}

std::string cgal_angle_text(const Row& r) {
  return number(r.cgal_angle * kDegrees, "%.1f") + (r.cgal_fold ? "*" : "");
}

std::string smooth_text(const Row& r) {
  const auto mean = [](bool has, const DistanceStats& s) { return has ? number(s.smooth_mean, "%.3f") : "-"; };
  char text[80];
  std::snprintf(text, sizeof text, "%6s %6s %6s %5s", mean(r.ours.count > 0, r.ours).c_str(),
                mean(r.has_baseline, r.baseline).c_str(), mean(r.has_cgal, r.cgal).c_str(),
                number(r.smooth_ratio, "%.2f").c_str());
  return text;
}

std::string pair_text(bool has, const DistanceStats& s) {
  if (!has) return "     -     -";
  char text[32];
  std::snprintf(text, sizeof text, "%6.3f %5.2f", s.mean, s.max);
  return text;
}

std::string percent(int part, int whole) {
  return whole > 0 ? number(100.0 * part / whole, "%.0f") + "%" : "-";
}

}  // namespace fairsurf::bench
