// The CLI's stagnation stop (FlowCommandRun in apps/fairsurf/flow_log.h, issue #16): driven with step
// records directly, since a real flow needs minutes of steps to crawl for 100 of them.
#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/errors.h>

#include <gtest/gtest.h>

#include <string>

#include "flow_log.h"

using namespace fairsurf;
using fairsurf::cli::FlowCommandRun;

namespace {

StepRecord record(int step, int attempt, double time, bool accepted = true) {
  StepRecord r;
  r.step = step;
  r.attempt = attempt;
  r.time = time;
  r.tau = 1e-12;
  r.accepted = accepted;
  return r;
}

FlowCommandRun make_run(FlowStepKind kind) {
  return FlowCommandRun("blend", "", true, nlohmann::json::object(), kind);
}

// Feeds `steps` accepted records from step `first`, each advancing t by `advance` from `time`;
// returns the step at which the observer threw NumericalError (0 if it never did), with its message.
int stagnation_step(const FlowObserver& observe, int first, int steps, double& time, double advance,
                    std::string* message = nullptr, int attempt_offset = 0) {
  for (int s = first; s < first + steps; ++s) {
    time += advance;
    try {
      observe(record(s, s + attempt_offset, time));
    } catch (const NumericalError& e) {
      if (message) *message = e.what();
      return s;
    }
  }
  return 0;
}

}  // namespace

TEST(CliStagnation, AHundredStepsAdvancingTimeByUnderAMillionthOfItStopTheFlow) {
  FlowCommandRun run = make_run(FlowStepKind::implicit_flow);
  const FlowObserver observe = run.observer();
  double time = 1.0;
  std::string message;
  // The window holds the times after the last 100 accepted steps: the 101st record is the first
  // that can compare 100 steps of progress.
  EXPECT_EQ(stagnation_step(observe, 1, 200, time, 1e-9, &message), FlowCommandRun::kStagnationWindow + 1);
  EXPECT_EQ(message.rfind("blend: the flow stagnated at step 101: its last 100 steps advanced t by", 0), 0u)
      << message;
}

TEST(CliStagnation, AFlowAdvancingFasterOrRejectedStepsAreLeftAlone) {
  FlowCommandRun run = make_run(FlowStepKind::implicit_flow);
  const FlowObserver observe = run.observer();
  double time = 1.0;
  // 2e-8 per step: 2e-6 of t over the window, above the 1e-6 threshold.
  EXPECT_EQ(stagnation_step(observe, 1, 500, time, 2e-8), 0);
  // Rejected trials do not fill the window.
  for (int attempt = 501; attempt < 800; ++attempt) EXPECT_NO_THROW(observe(record(501, attempt, time, false)));
}

TEST(CliStagnation, ANewRunStartsItsOwnWindow) {
  FlowCommandRun run = make_run(FlowStepKind::implicit_flow);
  const FlowObserver observe = run.observer();
  double time = 1.0;
  EXPECT_EQ(stagnation_step(observe, 1, 100, time, 1e-9), 0);
  // blend's energy-descent continuation reports attempt 1 again: its steps start a fresh window.
  EXPECT_EQ(stagnation_step(observe, 1, 101, time, 1e-9), FlowCommandRun::kStagnationWindow + 1);
}

TEST(CliStagnation, TheEnergyDescentIsNotWatched) {
  FlowCommandRun run = make_run(FlowStepKind::energy_descent);
  const FlowObserver observe = run.observer();
  double time = 1.0;
  EXPECT_EQ(stagnation_step(observe, 1, 300, time, 0.0), 0);
}
