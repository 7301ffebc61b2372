// Tests of the applications' option structs (issue #15): a fill and a blend are region fairings,
// their FairRegionOptions base set to the defaults each has always run with.
#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fill.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace fairsurf;

namespace {

// The fields in which harmonic_started() differs from the plain defaults, compared one by one.
void expect_same_fairing(const FairRegionOptions& a, const FairRegionOptions& b) {
  EXPECT_EQ(a.continuity, b.continuity);
  EXPECT_EQ(a.method, b.method);
  EXPECT_EQ(a.harmonic_start_iterations, b.harmonic_start_iterations);
  EXPECT_EQ(a.linear_floor, b.linear_floor);
  EXPECT_EQ(a.held_out_rings, b.held_out_rings);
  EXPECT_EQ(a.held_out_may_choose_linear, b.held_out_may_choose_linear);
  EXPECT_EQ(a.max_border_angle_ratio, b.max_border_angle_ratio);
  EXPECT_EQ(a.held_out_two_ring_fits, b.held_out_two_ring_fits);
  EXPECT_EQ(a.flow.two_ring_boundary_fits, b.flow.two_ring_boundary_fits);
  EXPECT_EQ(a.harmonic_solver.ordering, b.harmonic_solver.ordering);
  EXPECT_EQ(a.flow.tau, b.flow.tau);
  EXPECT_EQ(a.flow.step_kind, b.flow.step_kind);
  EXPECT_EQ(a.flow.steady_energy_tolerance, b.flow.steady_energy_tolerance);
  EXPECT_EQ(a.flow.max_consecutive_rejections, b.flow.max_consecutive_rejections);
  EXPECT_EQ(a.flow.solver.ordering, b.flow.solver.ordering);
  EXPECT_EQ(a.flow.functions, b.flow.functions);
  EXPECT_EQ(a.flow.max_steps, b.flow.max_steps);
}

}  // namespace

// A patch starts as a membrane: the fill's ∆^k start is re-evaluated up to 8 times, the rest is
// harmonic_started() (fill.h).
TEST(ApplicationOptions, FillStartsFromTheHarmonicStartedFairingReEvaluated) {
  FairRegionOptions expected = FairRegionOptions::harmonic_started();
  expected.harmonic_start_iterations = 8;
  expect_same_fairing(FillOptions{}, expected);
  EXPECT_EQ(FillOptions{}.flow.step_kind, FlowStepKind::energy_descent);
  EXPECT_TRUE(FillOptions{}.held_out_two_ring_fits);  // the flow on 2-ring boundary fits is weighed
  EXPECT_FALSE(FillOptions{}.flow.two_ring_boundary_fits);  // and delivered only where it wins
}

// A blend's tube flows from the tube as built, with fair_region's plain defaults (fair_region.h:
// the ∆³ re-evaluation can fold a tube around a corner).
TEST(ApplicationOptions, BlendStartsFromThePlainFairingDefaults) {
  expect_same_fairing(BlendOptions{}, FairRegionOptions{});
  EXPECT_EQ(BlendOptions{}.harmonic_start_iterations, 0);
}

// keep_settled_flow switches off the two checks that weigh a settled flow against its floor and
// nothing else: the held-out rings still choose the flow's boundary fits, and the floor stays for a
// flow that does not settle.
TEST(ApplicationOptions, KeepingTheSettledFlowSwitchesOffTheLinearChoiceAndTheFoldCheckOnly) {
  FillOptions kept;
  keep_settled_flow(kept);
  EXPECT_FALSE(kept.held_out_may_choose_linear);
  EXPECT_TRUE(std::isinf(kept.max_border_angle_ratio));
  EXPECT_TRUE(kept.linear_floor);
  EXPECT_EQ(kept.held_out_rings, FillOptions{}.held_out_rings);
  EXPECT_NE(kept.held_out_rings, 0);
  EXPECT_TRUE(kept.held_out_two_ring_fits);
  FillOptions expected;
  expected.held_out_may_choose_linear = false;
  expected.max_border_angle_ratio = kept.max_border_angle_ratio;
  expect_same_fairing(kept, expected);
  EXPECT_TRUE(FillOptions{}.held_out_may_choose_linear);  // so the test above changes something
  EXPECT_FALSE(std::isinf(FillOptions{}.max_border_angle_ratio));
}
