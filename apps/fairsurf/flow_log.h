// The commands that run a flow (smooth, fair, blend): JSON for flow reports, the progress line, the
// per-step log, and the failure path that still writes the last accepted state.
#pragma once

#include <fairsurf/errors.h>
#include <fairsurf/flow.h>
#include <fairsurf/mesh.h>

#include <nlohmann/json.hpp>

#include <string>

namespace fairsurf::cli {

/// One trial step: E, τ, max|d|, max|V|, accepted/rejected and why, solver figures, phase times.
nlohmann::json to_json(const StepRecord& record);
/// The whole run: every step plus the summary figures (stop reason, time, energies, well-posedness).
nlohmann::json to_json(const FlowReport& report);

/// Prints "fairsurf: warning: the chosen f is not parabolic at N of M vertices ..." when the
/// sixth-order flow of `report` was ill-posed on part of its input (METHOD §4); nothing otherwise.
void warn_if_not_parabolic(const FlowReport& report);

/// One flow command's run: a progress line on a terminal (unless quiet), every trial step kept for
/// the log, and the log written to `log_path` (none if empty) when the run ends either way.
class FlowCommandRun {
 public:
  FlowCommandRun(std::string command, std::string log_path, bool quiet, nlohmann::json log);

  /// Records each step (and prints progress); pass it to the library call. It stops a stagnating
  /// flow, one whose accepted steps shrank below kStagnantStepRatio of its largest, by throwing
  /// NumericalError: such a flow approaches no steady state (blend on data/fairing_cross.off crawled
  /// on at tau ~ 1e-15 for thousands of steps), so more steps only waste the run.
  FlowObserver observer();
  static constexpr double kStagnantStepRatio = 1e-6;

  /// Runs `flow` and ends the progress line. On NumericalError nothing is lost: `mesh` (the last
  /// accepted state) is written to `output`, the log gets the error and the steps, and the command
  /// fails with exit code 4 naming the output.
  template <class Flow>
  auto run(Flow&& flow, const Mesh& mesh, const std::string& output) -> decltype(flow()) {
    try {
      auto result = flow();
      end_progress();
      return result;
    } catch (const NumericalError& e) {
      end_progress();
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
  bool progress_;
  nlohmann::json log_;
  nlohmann::json steps_ = nlohmann::json::array();
  double largest_tau_ = 0;
};

}  // namespace fairsurf::cli
