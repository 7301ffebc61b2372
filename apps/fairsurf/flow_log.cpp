#include "flow_log.h"

#include <fairsurf/io/io.h>

#include <cstdio>

#include <unistd.h>

#include "command.h"

namespace fairsurf::cli {

nlohmann::json to_json(const StepRecord& r) {
  nlohmann::json j{{"step", r.step},
                   {"attempt", r.attempt},
                   {"time", r.time},
                   {"tau", r.tau},
                   {"energy", r.energy},
                   {"predicted_decrease", r.predicted_decrease},
                   {"max_displacement", r.max_displacement},
                   {"held_back_vertices", r.held_back_vertices},
                   {"clipped_vertices", r.clipped_vertices},
                   {"max_velocity", r.max_velocity},
                   {"accepted", r.accepted},
                   {"solver_iterations", r.solver_iterations},
                   {"backward_error", r.backward_error},
                   {"seconds",
                    {{"fit", r.fit_seconds},
                     {"assembly", r.assembly_seconds},
                     {"factorize", r.factorize_seconds},
                     {"solve", r.solve_seconds}}}};
  if (!r.accepted) j["rejection"] = {{"reason", to_string(r.rejection)}, {"detail", r.detail}};
  return j;
}

nlohmann::json to_json(const FlowReport& report) {
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& record : report.records) steps.push_back(to_json(record));
  return {{"stop_reason", to_string(report.stop_reason)},
          {"accepted_steps", report.accepted_steps},
          {"rejected_steps", report.rejected_steps},
          {"time", report.time},
          {"next_tau", report.tau},
          {"initial_energy", report.initial_energy},
          {"final_energy", report.final_energy},
          {"initial_max_velocity", report.initial_max_velocity},
          {"final_max_velocity", report.final_max_velocity},
          {"length_scale", report.length_scale},
          {"curvature_scale", report.curvature_scale},
          {"free_vertices", report.free_vertices},
          {"supported_continuity", to_string(report.supported)},
          {"well_posedness",
           {{"vertices", report.well_posedness.vertices},
            {"violating_vertices", report.well_posedness.violating_vertices}}},
          {"steps", steps}};
}

void warn_if_not_parabolic(const WellPosedness& w, const std::string& where) {
  if (w.violating_vertices > 0)
    std::fprintf(stderr, "fairsurf: warning: %sthe chosen f is not parabolic at %d of %d vertices of the flow's "
                 "input (method.md §4); the step control kept the flow stable\n", where.c_str(), w.violating_vertices,
                 w.vertices);
}

void warn_if_not_parabolic(const FlowReport& report) { warn_if_not_parabolic(report.well_posedness, ""); }

bool progress_wanted(bool quiet) { return !quiet && ::isatty(STDERR_FILENO); }

void print_progress(const StepRecord& r, const std::string& prefix) {
  std::fprintf(stderr, "\r  %sstep %d  t %.3g  tau %.3g  E %.4g  max|V| %.3g%s   ", prefix.c_str(), r.step, r.time,
               r.tau, r.energy, r.max_velocity, r.accepted ? "" : "  (rejected)");
}

FlowCommandRun::FlowCommandRun(std::string command, std::string log_path, bool quiet, nlohmann::json log,
                               FlowStepKind step_kind)
    : command_(std::move(command)),
      log_path_(std::move(log_path)),
      progress_(progress_wanted(quiet)),
      watch_stagnation_(step_kind == FlowStepKind::implicit_flow),
      log_(std::move(log)) {}

FlowObserver FlowCommandRun::observer() {
  return [this](const StepRecord& r) {
    steps_.push_back(to_json(r));
    if (progress_) print_progress(r);
    if (r.attempt == 1) recent_times_.clear();  // a new run (blend's descent continuation): its own window
    if (!r.accepted || !watch_stagnation_) return;
    recent_times_.push_back(r.time);
    if (static_cast<int>(recent_times_.size()) <= kStagnationWindow) return;
    const double advance = recent_times_.back() - recent_times_.front();
    recent_times_.pop_front();
    if (advance < kStagnantProgress * r.time) {
      char text[400];
      std::snprintf(text, sizeof text, "%s: the flow stagnated at step %d: its last %d steps advanced t by %.3g, "
                    "under %g of t = %.3g (tau now %.3g), so it approaches no steady state and more steps would "
                    "not help (docs/blend.md: regions with no steady state)", command_.c_str(), r.step,
                    kStagnationWindow, advance, kStagnantProgress, r.time, r.tau);
      throw NumericalError(text);
    }
  };
}

void FlowCommandRun::end_progress() const {
  if (progress_) std::fputc('\n', stderr);
}

void FlowCommandRun::fail(const NumericalError& e, const Mesh& mesh, const std::string& output) {
  write_mesh_output(output, mesh);
  log_["error"] = e.what();
  log_["steps"] = steps_;
  write_log();
  throw CliError(kNumerical,
                 std::string(e.what()) + " (the last accepted state was written to " + output + ")");
}

void FlowCommandRun::finish(const nlohmann::json& summary) {
  log_.update(summary);
  write_log();
}

void FlowCommandRun::write_log() const {
  if (!log_path_.empty())
    write_output([&] { write_file_atomically(log_path_, log_.dump(2) + "\n", command_); });
}

}  // namespace fairsurf::cli
