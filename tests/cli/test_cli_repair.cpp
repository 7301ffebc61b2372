// End-to-end tests of `fairsurf repair`, of --repair on the other commands, of the hint that
// refusals of repairable meshes end with, and of the inputs that once crashed the CLI
// (tests/regressions/: every command must exit with a documented code on each).
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/region_selection.h>
#include <fairsurf/mesh/validate.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "scratch_dir.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace fairsurf;

namespace {

class CliRepair : public test::ScratchDirTest {
 protected:
  std::string path(const std::string& name) const { return file(name); }
  static std::string quoted(const std::string& s) { return "'" + s + "'"; }
  static std::string data(const std::string& name) { return quoted(test::data_path(name)); }
};

TEST_F(CliRepair, RepairsTheHourglassAndSaysWhat) {
  const auto r = test::run_cli("repair " + data("hourglass_ico.obj") + " -o " + quoted(path("out.obj")));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("1 vertex split, 1 vertex copy added"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("23 -> 24 vertices"), std::string::npos) << r.out;
  const ValidationReport v = validate(read_mesh(path("out.obj")));
  EXPECT_TRUE(v.manifold());
  EXPECT_EQ(v.duplicate_vertex_positions.count, 1);
}

TEST_F(CliRepair, JsonHasEveryCountAndTheFindingsLeft) {
  const auto r = test::run_cli("repair --json " + data("moebius_160_10.ply") + " -o " + quoted(path("out.ply")));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"vertices_merged", "duplicate_faces_removed", "caps_flipped", "non_manifold_edges",
                          "vertices_split", "faces_flipped", "non_orientable_components", "changed"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["non_orientable_components"], 1);
  EXPECT_EQ(j["remaining_findings"]["non_orientable_components"], 1);
}

TEST_F(CliRepair, RefusesToOverwriteItsInputAndAnEmptyResult) {
  const std::string copy = path("in.obj");
  fs::copy_file(test::data_path("hourglass_ico.obj"), copy);
  EXPECT_EQ(test::run_cli("repair " + quoted(copy) + " -o " + quoted(copy)).exit_code, 5);
  const auto r = test::run_cli("repair " + quoted(FAIRSURF_REGRESSIONS_DIR "/all_faces_invalid.obj") + " -o " +
                               quoted(path("out.obj")));
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("no valid face"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(CliRepair, RefusalsOfRepairableMeshesEndWithTheHintAndRepairMakesThemPass) {
  const std::string hint = "(run with --repair, or `fairsurf repair`)";
  auto r = test::run_cli("smooth " + data("hourglass_ico.obj") + " -o " + quoted(path("s.obj")) + " --steps 1");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.out.find("smooth: mesh has 1 non-manifold vertex (first: 22) " + hint), std::string::npos) << r.out;
  // Non-orientable: repair cannot help, so no hint, and the message says why.
  r = test::run_cli("smooth " + data("moebius_160_10.ply") + " -o " + quoted(path("m.obj")) + " --steps 1");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.out.find(hint), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 non-orientable component (first: 9) (a one-sided surface, such as a Möbius band, has no "
                       "consistent orientation, and no repair gives it one)"),
            std::string::npos)
      << r.out;

  r = test::run_cli("smooth --repair " + data("hourglass_ico.obj") + " -o " + quoted(path("s.obj")) +
                    " --steps 1 --fixed-rings 0 --quiet --log " + quoted(path("s.json")));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("repaired "), std::string::npos) << r.out;
  std::ifstream log(path("s.json"));
  const auto j = nlohmann::json::parse(log);
  EXPECT_EQ(j["repair"]["vertices_split"], 1);

  r = test::run_cli("fill --repair --method harmonic " + data("lagrange_prout.obj") + " -o " + quoted(path("f.obj")) +
                    " --quiet --log " + quoted(path("f.json")));
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 4) << r.out;  // every refusal is gone; holes may fail
  EXPECT_EQ(r.out.find("mesh has"), std::string::npos) << r.out;
  std::ifstream fill_log(path("f.json"));
  EXPECT_GT(nlohmann::json::parse(fill_log)["repair"]["non_manifold_edges"].get<int>(), 0);

  r = test::run_cli("curvature --repair --json " + data("cube_soup.obj") + " -o " + quoted(path("c.ply")));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out)["repair"]["vertices_merged"], 16);
}

// A vertex index file names the vertices of the input as the user has it, also under --repair:
// the repair's removals do not shift it, and a split vertex's copies go with it.
TEST_F(CliRepair, IndexFilesNameTheInputsVerticesAcrossTheRepair) {
  // hand_lowres with an unreferenced vertex in front: --repair removes it, renumbering the rest.
  const Mesh hand = read_mesh(test::data_path("hand_lowres.obj"));
  const int n = hand.num_vertices();
  Mesh shifted;
  shifted.V.resize(n + 1, 3);
  shifted.V.row(0) << 9, 9, 9;
  shifted.V.bottomRows(n) = hand.V;
  shifted.F = hand.F.array() + 1;
  write_mesh(path("shifted.ply"), shifted);
  const double radius = 3.6 * (hand.V.row(401) - hand.V.row(400)).norm();  // about 300 vertices
  std::ofstream region(path("region.txt"));
  for (int v : vertices_in_ball(shifted.V, shifted.V.row(401).transpose(), radius)) region << v << " ";
  region.close();
  auto r = test::run_cli("fair " + quoted(path("shifted.ply")) + " --region " + quoted(path("region.txt")) + " -o " +
                         quoted(path("plain.ply")));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = test::run_cli("fair --repair " + quoted(path("shifted.ply")) + " --region " + quoted(path("region.txt")) +
                    " -o " + quoted(path("repaired.ply")));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("1 unreferenced vertex removed"), std::string::npos) << r.out;
  const Mesh plain = read_mesh(path("plain.ply")), repaired = read_mesh(path("repaired.ply"));
  ASSERT_EQ(repaired.num_vertices(), n);
  EXPECT_EQ(repaired.V, plain.V.bottomRows(n));  // the same region faired, one row up
  EXPECT_NE(repaired.V, hand.V);

  std::ofstream(path("removed.txt")) << "0 401\n";
  r = test::run_cli("fair --repair " + quoted(path("shifted.ply")) + " --region " + quoted(path("removed.txt")) +
                    " -o " + quoted(path("none.ply")));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("removed.txt: vertex 0 was removed by --repair (no face it kept uses it)"), std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(path("none.ply")));

  // hourglass_ico's pinch, vertex 22, is split: held fixed, both its copies stay where they were.
  std::ofstream(path("fixed.txt")) << "22\n";
  r = test::run_cli("smooth --repair " + data("hourglass_ico.obj") + " --fixed-vertices " + quoted(path("fixed.txt")) +
                    " --fixed-rings 0 --steps 2 -o " + quoted(path("s.ply")));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const Mesh hourglass = read_mesh(test::data_path("hourglass_ico.obj")), smoothed = read_mesh(path("s.ply"));
  ASSERT_EQ(smoothed.num_vertices(), 24);  // the copy last
  EXPECT_EQ(smoothed.V.row(22), hourglass.V.row(22));
  EXPECT_EQ(smoothed.V.row(23), hourglass.V.row(22));
  EXPECT_NE(smoothed.V.row(21), hourglass.V.row(21));
}

TEST_F(CliRepair, EveryCommandExitsWithACodeOnEveryRegressionInput) {
  for (const auto& entry : fs::directory_iterator(FAIRSURF_REGRESSIONS_DIR)) {
    const std::string in = quoted(entry.path().string());
    const std::string ext = entry.path().extension().string();
    SCOPED_TRACE(entry.path().filename().string());
    const std::string force = " --force";
    for (const std::string& command :
         {"info " + in, "info --strict --json " + in, "curvature " + in + " -o " + quoted(path("c.ply")) + force,
          "smooth " + in + " -o " + quoted(path("s" + ext)) + " --steps 2 --quiet" + force,
          "smooth --repair " + in + " -o " + quoted(path("s" + ext)) + " --steps 2 --quiet" + force,
          "fill --method harmonic " + in + " -o " + quoted(path("f" + ext)) + " --quiet" + force,
          "fair " + in + " -o " + quoted(path("r" + ext)) + " --region-sphere 0,0,0,0.5 --max-steps 2 --quiet" + force,
          "blend " + in + " -o " + quoted(path("b" + ext)) + " --max-steps 2 --quiet" + force,
          "render " + in + " -o " + quoted(path("r.png")) + force, "repair " + in + " -o " + quoted(path("p" + ext)) + force,
          "convert " + in + " -o " + quoted(path("v.off")) + force}) {
      const auto r = test::run_cli(command);
      EXPECT_GE(r.exit_code, 0) << command << "\n" << r.out;  // -1: killed by a signal
      EXPECT_LE(r.exit_code, 5) << command << "\n" << r.out;
    }
  }
}

TEST_F(CliRepair, SmoothingAMeshWithoutFacesFailsCleanly) {
  for (const char* name : {"empty.off", "all_faces_invalid.obj", "zero_triangles.stl"}) {
    const auto r = test::run_cli("smooth " + quoted(std::string(FAIRSURF_REGRESSIONS_DIR "/") + name) + " -o " +
                                 quoted(path("out.obj")));
    EXPECT_EQ(r.exit_code, 3) << name << ": " << r.out;
    EXPECT_FALSE(fs::exists(path("out.obj"))) << name;
  }
}

}  // namespace
