// End-to-end tests of `fairsurf fill`: per-hole lines, hole selection, the JSON log, exit codes.
#include <fairsurf/applications/fill.h>
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/topology.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "hole_meshes.h"
#include "scratch_dir.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace fairsurf;

namespace {

class CliFill : public test::ScratchDirTest {
 protected:
  std::string path(const std::string& name) const { return file(name); }
  static std::string quoted(const std::string& s) { return "'" + s + "'"; }
};

int loop_count(const Mesh& m) {
  return static_cast<int>(boundary_loops(m.F, build_topology(m.F, m.num_vertices())).size());
}

}  // namespace

TEST_F(CliFill, SelectedHolesAreFilledOneLineEachWithALog) {
  const std::string in = test::data_path("airplane_holes.obj");
  const auto run = test::run_cli("fill " + quoted(in) + " -o " + quoted(path("out.ply")) + " --holes 0,3 --log " +
                                 quoted(path("log.json")));
  ASSERT_EQ(run.exit_code, 0) << run.out;
  for (const char* line : {"hole 0 (", "hole 3 ("}) {
    const auto at = run.out.find(line);
    ASSERT_NE(at, std::string::npos) << run.out;
    EXPECT_NE(run.out.substr(at, run.out.find('\n', at) - at).find("): filled, +"), std::string::npos) << run.out;
  }
  EXPECT_NE(run.out.find("border edges): skipped: not selected"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("filled 2 of 2 selected holes"), std::string::npos) << run.out;

  const Mesh input = read_mesh(in), output = read_mesh(path("out.ply"));
  EXPECT_EQ(loop_count(input), 27);
  EXPECT_EQ(loop_count(output), 25);
  EXPECT_GT(output.num_vertices(), input.num_vertices());

  std::ifstream log_file(path("log.json"));
  const auto log = nlohmann::json::parse(log_file);
  ASSERT_EQ(log["holes"].size(), 27u);
  EXPECT_EQ(log["holes"][0]["status"], "filled");
  EXPECT_EQ(log["holes"][1]["status"], "skipped");
  // The hole gets the flow (on 1-ring or 2-ring boundary fits) or its linear floor, whichever
  // re-predicts the held-out rings best, the floor only by more than the held-out margin; the solve
  // from the patch before its membrane where it does so twice as well as the floor, the flows'
  // start (they are then not tried: null).
  const auto& hole = log["holes"][0];
  ASSERT_TRUE(hole["held_out_linear_error"].is_number()) << hole.dump();
  ASSERT_TRUE(hole["held_out_refined_linear_error"].is_number()) << hole.dump();
  const double linear = hole["held_out_linear_error"].get<double>();
  const bool refined = 2 * hole["held_out_refined_linear_error"].get<double>() < linear;
  EXPECT_EQ(hole["refined_start"], refined) << hole.dump();
  EXPECT_EQ(hole["held_out_flow_error"].is_number(), !refined) << hole.dump();
  EXPECT_EQ(hole["held_out_two_ring_flow_error"].is_number(), !refined) << hole.dump();
  const double one_ring = refined ? 0 : hole["held_out_flow_error"].get<double>();
  const double two_ring = refined ? 0 : hole["held_out_two_ring_flow_error"].get<double>();
  const double margin = FillOptions{}.held_out_margin;
  // The airplane's surroundings are smooth, so the floor may win there (held_out_max_roughness).
  ASSERT_TRUE(hole["held_out_roughness"].is_number()) << hole.dump();
  EXPECT_LT(hole["held_out_roughness"].get<double>(), FillOptions{}.held_out_max_roughness);
  const bool flow_wins = !refined && std::min(one_ring, two_ring) <= margin * linear;
  EXPECT_EQ(hole["delivered"], flow_wins ? "G2" : "C2 (linear)") << hole.dump();
  EXPECT_EQ(hole["linear"], !flow_wins);
  EXPECT_EQ(hole["two_ring_boundary_fits"], flow_wins && two_ring < one_ring) << hole.dump();
  EXPECT_EQ(hole.contains("steps_log"), flow_wins);
  EXPECT_GE(hole["harmonic_solves"].get<int>(), 1);  // the flow's ∆³ start, or the floor itself
  EXPECT_EQ(hole["patch_shared_with"], -1);            // its own patch: no pinch joins it to another loop
  EXPECT_EQ(log["filled"], 2);
}

TEST_F(CliFill, ExitCodes) {
  const std::string out = quoted(path("out.obj"));
  auto run = test::run_cli("fill /nonexistent/mesh.obj -o " + out);
  EXPECT_EQ(run.exit_code, 2) << run.out;

  run = test::run_cli("fill " + quoted(test::data_path("lagrange_prout.obj")) + " -o " + out);
  EXPECT_EQ(run.exit_code, 3) << run.out;
  EXPECT_NE(run.out.find("fairsurf: error: fill_holes: mesh has "), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(path("out.obj")));

  const std::string copy = path("in.off");
  fs::copy_file(test::data_path("cgal_mech_holes_shark.off"), copy);
  run = test::run_cli("fill " + quoted(copy) + " -o " + quoted(copy));
  EXPECT_EQ(run.exit_code, 5) << run.out;

  run = test::run_cli("fill " + quoted(copy) + " -o " + out + " --holes 9");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_NE(run.out.find("fill_holes: hole 9 is outside [0, 4)"), std::string::npos) << run.out;
}

// The bunny scan's five holes get the linear floor by default: it re-predicts the held-out rings
// better than the flow on each. --keep-flow keeps the settled flow on all five (the held-out rings
// only choose its boundary fits), and the log says the flag was given; with --method harmonic there
// is no flow to keep.
TEST_F(CliFill, KeepFlowDeliversTheSettledFlowWhereTheHeldOutRingsChoseTheFloor) {
  const std::string in = quoted(test::data_path("stanford_bunny_zipper.obj"));
  auto run = test::run_cli("fill " + in + " -o " + quoted(path("default.ply")) + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("(5 C2 (linear); 0 failed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("fairsurf: note: 5 holes got the linear solution, which the held-out rings or the fold "
                         "check preferred to the G2 flow; --keep-flow keeps the flow"),
            std::string::npos)
      << run.out;

  run = test::run_cli("fill " + in + " -o " + quoted(path("kept.ply")) + " --keep-flow --log " +
                      quoted(path("log.json")));
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("(5 G2; 0 failed"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("the linear ∆3 solution re-predicts"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("--keep-flow keeps"), std::string::npos) << run.out;
  std::ifstream log_file(path("log.json"));
  const auto log = nlohmann::json::parse(log_file);
  EXPECT_EQ(log["keep_flow"], true);
  for (const auto& hole : log["holes"]) {
    EXPECT_EQ(hole["delivered"], "G2") << hole.dump();
    EXPECT_FALSE(hole["checks_chose_linear"].get<bool>()) << hole.dump();
    EXPECT_FALSE(hole["flow_folded_back"].get<bool>()) << hole.dump();  // kept: none folds back
    // The held-out rings still weigh the flow's 1-ring and 2-ring boundary fits.
    EXPECT_TRUE(hole["held_out_flow_error"].is_number()) << hole.dump();
    EXPECT_TRUE(hole["held_out_two_ring_flow_error"].is_number()) << hole.dump();
    EXPECT_TRUE(hole["held_out_other_flow_error"].is_null()) << hole.dump();  // no --other-functions
    EXPECT_FALSE(hole["other_functions_chosen"].get<bool>()) << hole.dump();
    EXPECT_LT(hole["continuity"]["max_normal_angle"].get<double>(), std::numbers::pi / 2) << hole.dump();
  }
  const Mesh kept = read_mesh(path("kept.ply"));
  EXPECT_EQ(loop_count(kept), 0);

  run = test::run_cli("fill " + in + " -o " + quoted(path("linear.ply")) + " --keep-flow --method harmonic");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_NE(run.out.find("fill: --keep-flow keeps the flow's result; --method harmonic runs no flow"),
            std::string::npos)
      << run.out;
  EXPECT_FALSE(fs::exists(path("linear.ply")));
}

// --other-functions H --other-functions K/kappa on the bunny scan: the held-out rings weigh the
// flow with the Gaussian curvature term at every hole, and on the largest (hole 4, 80 edges) it
// re-predicts them better than the flow with f = H and than ∆³, so that hole is G2 with it. Each
// hole's log gives both flows' errors and which one ran.
TEST_F(CliFill, OtherFunctionsAreWeighedAtEachHoleAndTheLogSaysWhichFlowRan) {
  const std::string in = quoted(test::data_path("stanford_bunny_zipper.obj"));
  const auto run = test::run_cli("fill " + in + " -o " + quoted(path("other.ply")) +
                                 " --other-functions H --other-functions K/kappa --log " + quoted(path("log.json")));
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("(4 C2 (linear), 1 G2; 0 failed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("with f = {H, K/kappa} the flow re-predicts the 2 rings around the region better"),
            std::string::npos)
      << run.out;
  std::ifstream log_file(path("log.json"));
  const auto log = nlohmann::json::parse(log_file);
  EXPECT_EQ(log["other_functions"], nlohmann::json({"H", "K/kappa"}));
  ASSERT_EQ(log["holes"].size(), 5u);
  for (const auto& hole : log["holes"]) {
    ASSERT_TRUE(hole["held_out_other_flow_error"].is_number()) << hole.dump();
    EXPECT_TRUE(hole["held_out_other_two_ring_flow_error"].is_number()) << hole.dump();
  }
  const auto& chosen = log["holes"][4];
  EXPECT_EQ(chosen["delivered"], "G2") << chosen.dump();
  EXPECT_TRUE(chosen["other_functions_chosen"].get<bool>()) << chosen.dump();
  const double other = std::min(chosen["held_out_other_flow_error"].get<double>(),
                                chosen["held_out_other_two_ring_flow_error"].get<double>());
  EXPECT_LT(other, chosen["held_out_flow_error"].get<double>()) << chosen.dump();
  EXPECT_LT(other, chosen["held_out_two_ring_flow_error"].get<double>()) << chosen.dump();
  EXPECT_LT(other, chosen["held_out_linear_error"].get<double>()) << chosen.dump();
  for (int i = 0; i < 4; ++i) {
    const auto& hole = log["holes"][i];
    EXPECT_EQ(hole["delivered"], "C2 (linear)") << hole.dump();
    EXPECT_FALSE(hole["other_functions_chosen"].get<bool>()) << hole.dump();
  }
}

TEST_F(CliFill, SomeHolesFailingExitsFourAndKeepsTheFilledOnes) {
  // test::grid_with_chained_pinches: hole B, which a lone triangle pinches (its patch alone would
  // close the fan there into a cone), fails; hole A, touching B at a corner, is filled alone.
  const Mesh holed = test::grid_with_chained_pinches();
  write_mesh(path("pinched.obj"), holed);
  const auto loops = boundary_loops(holed.F, build_topology(holed.F, holed.num_vertices()));
  int a = -1, b = -1;
  for (int i = 0; i < static_cast<int>(loops.size()); ++i) {
    if (loops[i].size() <= 3 || loops[i].size() >= 40) continue;  // the lone triangle, the outer border
    if (std::count(loops[i].begin(), loops[i].end(), 4 * 17 + 4)) a = i;
    if (std::count(loops[i].begin(), loops[i].end(), 10 * 17 + 10)) b = i;
  }
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  const auto run = test::run_cli("fill " + quoted(path("pinched.obj")) + " -o " + quoted(path("out.obj")) +
                                 " --holes " + std::to_string(a) + "," + std::to_string(b));
  EXPECT_EQ(run.exit_code, 4) << run.out;
  EXPECT_NE(run.out.find("hole " + std::to_string(b) + " (16 border edges): failed: non-manifold border: vertex "),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("still holds the 1 hole that was filled; a lone triangle hangs at a pinch"), std::string::npos)
      << run.out;
  const Mesh out = read_mesh(path("out.obj"));
  EXPECT_GT(out.num_faces(), holed.num_faces());

  // --repair keeps the corner where A and B touch joined (it splits off the lone triangle only), and
  // fill closes both; repair's default would split the corner, and the joined loop would fail.
  const auto repaired = test::run_cli("fill " + quoted(path("pinched.obj")) + " -o " + quoted(path("repaired.obj")) +
                                      " --repair --skip-largest --method harmonic");
  EXPECT_EQ(repaired.exit_code, 0) << repaired.out;
  EXPECT_NE(repaired.out.find("1 vertex split"), std::string::npos) << repaired.out;
  EXPECT_EQ(loop_count(read_mesh(path("repaired.obj"))), 1);  // the grid's outer border
}

// A hole with a lone triangle hanging at its border (test::sphere_hole_with_lone_triangle): fill
// takes the triangle into the hole's patch, exit 0, no loop left. Where the triangle's loop is not
// selected, the hole fails at that pinch; the hint is --repair, not --skip-largest (the hole is far
// longer than the triangle's loop, but it is no outer border), and with --repair the hole is filled.
TEST_F(CliFill, AHoleFailingAtALoneTriangleHintsAtRepair) {
  const Mesh debris = test::sphere_hole_with_lone_triangle();
  write_mesh(path("debris.obj"), debris);
  const auto taken_in = test::run_cli("fill " + quoted(path("debris.obj")) + " -o " + quoted(path("in.obj")) +
                                      " --method harmonic");
  EXPECT_EQ(taken_in.exit_code, 0) << taken_in.out;
  EXPECT_EQ(loop_count(read_mesh(path("in.obj"))), 0);

  const auto loops = boundary_loops(debris.F, build_topology(debris.F, debris.num_vertices()));
  const auto hole = std::find_if(loops.begin(), loops.end(), [](const auto& l) { return l.size() > 3; });
  ASSERT_NE(hole, loops.end());
  const auto run = test::run_cli("fill " + quoted(path("debris.obj")) + " -o " + quoted(path("out.obj")) +
                                 " --method harmonic --holes " + std::to_string(hole - loops.begin()));
  EXPECT_EQ(run.exit_code, 4) << run.out;
  EXPECT_NE(run.out.find("still holds the 0 holes that were filled; a lone triangle hangs at a pinch of a failed "
                         "hole's border: --repair splits the vertex and removes it"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("--skip-largest"), std::string::npos) << run.out;
  const auto repaired = test::run_cli("fill " + quoted(path("debris.obj")) + " -o " + quoted(path("repaired.obj")) +
                                      " --method harmonic --repair");
  EXPECT_EQ(repaired.exit_code, 0) << repaired.out;
  EXPECT_EQ(loop_count(read_mesh(path("repaired.obj"))), 0);
}

// The outer border of an S-bent sheet cannot be filled (test::s_sheet_with_hole), the small hole
// beside it can, alone: exit 4, the small hole written, and the hint that the failed loop, three
// times longer than the other, is the outer border of an open surface; with --skip-largest, exit 0.
TEST_F(CliFill, AFailedOuterBorderIsNamedAsSuchWhereTheHoleBesideItIsFilled) {
  write_mesh(path("sheet.obj"), test::s_sheet_with_hole());
  const auto run = test::run_cli("fill " + quoted(path("sheet.obj")) + " -o " + quoted(path("out.obj")));
  EXPECT_EQ(run.exit_code, 4) << run.out;
  EXPECT_NE(run.out.find("filled alone"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("still holds the 1 hole that was filled; the largest loop looks like the outer border of "
                         "an open surface: use --skip-largest"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(loop_count(read_mesh(path("out.obj"))), 1);
  const auto skipped = test::run_cli("fill " + quoted(path("sheet.obj")) + " -o " + quoted(path("skipped.obj")) +
                                     " --skip-largest --quiet");
  EXPECT_EQ(skipped.exit_code, 0) << skipped.out;
  EXPECT_EQ(loop_count(read_mesh(path("skipped.obj"))), 1);
}
