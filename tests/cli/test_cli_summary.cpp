// The summary line `fair` and `blend` print for a region (cli::summary in
// apps/fairsurf/region_fairing_args.h): built from reports directly, since an energy descent
// delivered unsettled (a blend whose linear tube crosses the mesh too) is rare on real inputs.
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/flow/flow.h>

#include <gtest/gtest.h>

#include <string>

#include "flow_meshes.h"
#include "region_fairing_args.h"

using namespace fairsurf;

namespace {

FairRegionReport unsettled(FlowStepKind kind) {
  FairRegionReport r;
  r.method = FairMethod::flow;
  r.flow = test::unsettled_flow_report(kind);
  return r;
}

}  // namespace
// An unsettled energy descent is told by its energy, which fell at every step, and asks for more
// steps: its max|V| rising says nothing of it (before, such a run read "diverged").
TEST(CliSummary, AnUnsettledDescentIsToldByItsEnergyAndAsksForMoreSteps) {
  const std::string line = cli::summary(unsettled(FlowStepKind::energy_descent));
  EXPECT_NE(line.find("NOT steady: did not settle (2 steps without a steady state, E 10 -> 6, the last step "
                      "lowering it by 0.25 of itself)"),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("(E was still falling: raise --max-steps)"), std::string::npos) << line;
  EXPECT_EQ(line.find("diverged"), std::string::npos) << line;
}

// A time-stepped flow with the same figures drifted away from a steady state.
TEST(CliSummary, AnUnsettledTimeSteppedFlowWhoseMaxVRoseDiverged) {
  const std::string line = cli::summary(unsettled(FlowStepKind::implicit_flow));
  EXPECT_NE(line.find("NOT steady: diverged (2 steps without a steady state, max|V| 1 -> 5)"), std::string::npos)
      << line;
  EXPECT_NE(line.find("more steps drift further from a steady state"), std::string::npos) << line;
}
