// The words a FlowReport is told in: rejection and stop reasons, and why a run did not settle.
#include <fairsurf/flow/flow.h>

#include <cstdio>
#include <limits>
#include <string>

namespace fairsurf {

const char* to_string(StepRejection reason) {
  switch (reason) {
    case StepRejection::none: return "none";
    case StepRejection::displacement: return "displacement";
    case StepRejection::energy: return "energy";
    case StepRejection::non_finite: return "non-finite";
    case StepRejection::inverted_face: return "inverted face";
    case StepRejection::solver: return "solver";
    case StepRejection::crossing: return "crossing";
  }
  return "?";
}

const char* to_string(FlowStopReason reason) {
  switch (reason) {
    case FlowStopReason::max_steps: return "max steps";
    case FlowStopReason::end_time: return "end time";
    case FlowStopReason::steady: return "steady";
    case FlowStopReason::interrupted: return "interrupted";
  }
  return "?";
}

namespace {

// The relative decrease of E at the last accepted step (NaN without one).
double last_relative_decrease(const FlowReport& report) {
  double before = report.initial_energy;
  double last = std::numeric_limits<double>::quiet_NaN();
  for (const StepRecord& r : report.records)
    if (r.accepted) {
      last = (before - r.energy) / before;
      before = r.energy;
    }
  return last;
}

}  // namespace

std::string unsettled_reason(const FlowReport& report) {
  const std::string steps = std::to_string(report.accepted_steps) + " steps without a steady state, ";
  char figures[128];
  if (report.step_kind == FlowStepKind::energy_descent) {
    std::snprintf(figures, sizeof figures, "E %.3g -> %.3g, the last step lowering it by %.2g of itself",
                  report.initial_energy, report.final_energy, last_relative_decrease(report));
    return "did not settle (" + steps + figures + ")";
  }
  const bool diverged = !(report.final_max_velocity <= report.initial_max_velocity);
  std::snprintf(figures, sizeof figures, "max|V| %.3g -> %.3g", report.initial_max_velocity,
                report.final_max_velocity);
  return std::string(diverged ? "diverged" : "did not settle") + " (" + steps + figures + ")";
}

}  // namespace fairsurf
