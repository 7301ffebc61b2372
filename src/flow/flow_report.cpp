// The words a FlowReport is told in: rejection and stop reasons, and why a run did not settle.
#include <fairsurf/flow/flow.h>

#include <cstdio>
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

std::string unsettled_reason(const FlowReport& report) {
  const bool diverged = !(report.final_max_velocity <= report.initial_max_velocity);
  char velocities[64];
  std::snprintf(velocities, sizeof velocities, "%.3g -> %.3g", report.initial_max_velocity,
                report.final_max_velocity);
  return std::string(diverged ? "diverged" : "did not settle") + " (" +
         std::to_string(report.accepted_steps) + " steps without a steady state, max|V| " + velocities + ")";
}

}  // namespace fairsurf
