// FlowOptions::interrupted: a caller stops a flow between steps and keeps the last accepted state,
// the same state a run limited to that many steps ends in.
#include "flow_meshes.h"

#include <fairsurf/flow/flow.h>

#include <gtest/gtest.h>

namespace fairsurf {
namespace {

TEST(FlowInterrupt, StopsAfterTheAcceptedStepItWasAskedAt) {
  const Mesh noisy = test::noisy_sphere(3, 1.0, 0.12);
  FlowOptions options;
  options.max_steps = 3;
  Vertices limited = noisy.V;
  const FlowReport reference = run_flow(limited, noisy.F, options);
  ASSERT_EQ(reference.accepted_steps, 3);

  options.max_steps = 1000;
  int accepted = 0;
  options.interrupted = [&] { return accepted == 3; };
  Vertices V = noisy.V;
  const FlowReport stopped =
      run_flow(V, noisy.F, options, [&](const StepRecord& r) { accepted += r.accepted; });
  EXPECT_EQ(stopped.stop_reason, FlowStopReason::interrupted);
  EXPECT_STREQ(to_string(stopped.stop_reason), "interrupted");
  EXPECT_EQ(stopped.accepted_steps, 3);
  EXPECT_EQ(stopped.records.size(), reference.records.size());
  EXPECT_EQ((V - limited).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace fairsurf
