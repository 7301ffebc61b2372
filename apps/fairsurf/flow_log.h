// The commands that run a flow (smooth, fair, blend): JSON for flow reports, the progress line, the
// per-step log, and the failure path that still writes the last accepted state.
#pragma once

#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh.h>

#include "command.h"

#include <nlohmann/json.hpp>

#include <deque>
#include <string>

namespace fairsurf::cli {

/// One trial step: E, τ, max|d|, max|V|, accepted/rejected and why, solver figures, phase times.
nlohmann::json to_json(const StepRecord& record);
/// The whole run: every step plus the summary figures (stop reason, time, energies, well-posedness).
nlohmann::json to_json(const FlowReport& report);

/// Prints "fairsurf: warning: the chosen f is not parabolic at N of M vertices ..." when the
/// sixth-order flow of `report` was ill-posed on part of its input (method.md §4); nothing otherwise.
void warn_if_not_parabolic(const FlowReport& report);
/// The same with a prefix naming where (fill: "hole N: ").
void warn_if_not_parabolic(const WellPosedness& w, const std::string& where);

/// Whether to draw a progress line: not --quiet, and stderr is a terminal.
bool progress_wanted(bool quiet);
/// Redraws the progress line on stderr for one trial step: "\r  <prefix>step N  t  tau  E  max|V|".
/// `prefix` names the part when a command runs several flows (fill: "hole 3  ").
void print_progress(const StepRecord& r, const std::string& prefix = "");

/// One flow command's run: a progress line on a terminal (unless quiet), every trial step kept for
/// the log, and the log written to `log_path` (none if empty) when the run ends either way.
class FlowCommandRun {
 public:
  /// `step_kind`: the flow's (flow.h); only the time-stepped flow is watched for stagnation, since
  /// the energy descent's τ is a trust region, not time, and it stops by itself once E stops falling.
  FlowCommandRun(std::string command, std::string log_path, bool quiet, nlohmann::json log,
                 FlowStepKind step_kind);

  /// Records each step (and prints progress); pass it to the library call. It stops a stagnating
  /// time-stepped flow, one whose last kStagnationWindow accepted steps advanced its time by less than
  /// kStagnantProgress of the time reached, by throwing NumericalError: such a flow approaches no
  /// steady state (blend on data/fairing_cross.off crawled on at tau ~ 1e-15 for thousands of steps),
  /// so more steps only waste the run. A window, not one step, so that a run recovering from a
  /// streak of rejections (tau quartered up to 12 times) is left alone.
  FlowObserver observer();
  static constexpr int kStagnationWindow = 100;
  static constexpr double kStagnantProgress = 1e-6;

  /// Runs `flow` on `mesh`, ends the progress line and recomputes the stored normals of the
  /// vertices the flow moved (refresh_normals). On NumericalError nothing is lost: `mesh` (the last
  /// accepted state, its normals recomputed) is written to `output`, the log gets the error and the
  /// steps, and the command fails with exit code 4 naming the output.
  template <class Flow>
  auto run(Flow&& flow, Mesh& mesh, const std::string& output) -> decltype(flow()) {
    const Vertices before = mesh.FN.rows() > 0 ? mesh.V : Vertices();
    try {
      auto result = flow();
      end_progress();
      refresh_normals(mesh, before, output);
      return result;
    } catch (const NumericalError& e) {
      end_progress();
      refresh_normals(mesh, before, output);
      fail(e, mesh, output);
    }
  }

  /// Adds `summary` to the log and writes it.
  void finish(const nlohmann::json& summary);

 private:
  void end_progress() const;
  [[noreturn]] void fail(const NumericalError& e, const Mesh& mesh, const std::string& output);
  void write_log() const;

  std::string command_, log_path_;
  bool progress_, watch_stagnation_;
  nlohmann::json log_;
  nlohmann::json steps_ = nlohmann::json::array();
  std::deque<double> recent_times_;  ///< flow time after each of the last accepted steps
};

}  // namespace fairsurf::cli
