#include <fairsurf/io/io.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "analytic_meshes.h"
#include "scratch_dir.h"
#include "test_support.h"

using namespace fairsurf;
namespace fs = std::filesystem;

namespace {

class CliRender : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    // A sphere carrying one stored vertex property, "height" (its y coordinate).
    Mesh sphere = test::icosphere(2);
    sphere.vertex_scalars["height"] = sphere.V.col(1);
    write_mesh(path("sphere.ply"), sphere);
  }
  std::string path(const std::string& name) const { return file(name); }
};

}  // namespace

TEST_F(CliRender, RendersABundledMeshToPng) {
  const test::CliRun run =
      test::run_cli("render '" + test::data_path("spot.obj") + "' -o '" + path("spot.png") + "' --color none --size 160x120");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(run.out, "wrote " + path("spot.png") + ": 160x120, none\n");
  EXPECT_EQ(test::read_bytes(path("spot.png")).substr(0, 8), "\x89PNG\r\n\x1a\n");
}

TEST_F(CliRender, StoredQuantityWithEveryOptionIsReproducible) {
  const std::string args = "render '" + path("sphere.ply") + "' --color height --range -0.5,0.5 --views front,top "
                           "--size 240x160 --wire --title 'a sphere' --compare '" + path("sphere.ply") + "' -o '";
  const test::CliRun first = test::run_cli(args + path("a.png") + "'");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  EXPECT_EQ(first.out, "wrote " + path("a.png") + ": 240x160, height on [-0.5, 0.5] (diverging)\n");
  ASSERT_EQ(test::run_cli(args + path("b.png") + "'").exit_code, 0);
  EXPECT_TRUE(test::read_bytes(path("a.png")) == test::read_bytes(path("b.png")));
}

TEST_F(CliRender, FocusFramesABallAndRefusesABadOne) {
  const std::string base = "render '" + path("sphere.ply") + "' --color height --size 120x90 ";
  // A ball on the equator: the automatic (symmetric) range is that of the heights inside it, |y| < 0.4,
  // where the whole sphere's reaches 0.95.
  const auto range_end = [](const std::string& out) { return std::stod(out.substr(out.find("on [-") + 5)); };
  const test::CliRun focused = test::run_cli(base + "--focus 1,0,0,0.4 -o '" + path("f.png") + "'");
  ASSERT_EQ(focused.exit_code, 0) << focused.out;
  const test::CliRun whole = test::run_cli(base + "-o '" + path("w.png") + "'");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  EXPECT_LT(range_end(focused.out), 0.4) << focused.out;
  EXPECT_GT(range_end(whole.out), 0.8) << whole.out;
  EXPECT_NE(test::read_bytes(path("f.png")), test::read_bytes(path("w.png")));
  for (const std::string bad : {"0,1,0", "0,1,0,-1", "0,1,0,r", "0,1,nan,1"}) {
    const test::CliRun run = test::run_cli(base + "--focus " + bad + " -o '" + path("b.png") + "'");
    EXPECT_EQ(run.exit_code, 1) << bad;
    EXPECT_NE(run.out.find("fairsurf: error: render: --focus '" + bad + "' is not x,y,z,r"), std::string::npos) << run.out;
  }
  const test::CliRun empty = test::run_cli(base + "--focus 0,0,0,0.5 -o '" + path("e.png") + "'");
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_NE(empty.out.find("no face has all three vertices inside the focus ball"), std::string::npos) << empty.out;
  EXPECT_FALSE(fs::exists(path("b.png")));
  EXPECT_FALSE(fs::exists(path("e.png")));
}

TEST_F(CliRender, ComputesMeanCurvatureWhenTheFileHasNone) {
  // H = -1/R on an outward sphere (operators.h): the colour range is centred on 0 and reaches 1/R.
  write_mesh(path("sphere2.off"), test::icosphere(3, 2.0));
  const test::CliRun run = test::run_cli("render '" + path("sphere2.off") + "' --size 120x90 -o '" + path("h.png") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const std::string prefix = "wrote " + path("h.png") + ": 120x90, H on [-";
  ASSERT_EQ(run.out.rfind(prefix, 0), 0u) << run.out;
  EXPECT_NEAR(std::stod(run.out.substr(prefix.size())), 0.5, 0.01) << run.out;
}

TEST_F(CliRender, SameBytesForOneThreadAndTwo) {
  const auto run_with_threads = [&](int threads, const std::string& out) {
    const std::string command = "OMP_NUM_THREADS=" + std::to_string(threads) + " '" + test::cli_path() +
                                "' render '" + test::data_path("blub.obj") + "' --views iso,top --wire --size 320x200 -o '" +
                                path(out) + "' >/dev/null 2>&1";
    return std::system(command.c_str());
  };
  ASSERT_EQ(run_with_threads(1, "one.png"), 0);
  ASSERT_EQ(run_with_threads(2, "two.png"), 0);
  const std::string one = test::read_bytes(path("one.png"));
  EXPECT_GT(one.size(), 10000u);
  EXPECT_TRUE(one == test::read_bytes(path("two.png")));
}

TEST_F(CliRender, UnknownQuantityListsTheAvailableOnes) {
  const test::CliRun run = test::run_cli("render '" + path("sphere.ply") + "' --color energy -o '" + path("x.png") + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.out.find("render: unknown quantity 'energy' for '" + path("sphere.ply") + "' (available: "),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("(available: H, K, k1, k2, none, height)"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(CliRender, BadFlagsExitWithUsageError) {
  const std::string base = "render '" + path("sphere.ply") + "' --color height -o '" + path("x.png") + "' ";
  for (const char* bad : {"--size 100", "--size 0x100", "--size axb", "--range 1", "--range 2,1",
                                 "--range 0,nan", "--view sideways", "--view top --views front,iso", "--map jet"}) {
    const test::CliRun run = test::run_cli(base + bad);
    EXPECT_EQ(run.exit_code, 1) << bad << ": " << run.out;
    EXPECT_EQ(run.out.rfind("fairsurf: error: ", 0), 0u) << bad << ": " << run.out;
  }
  EXPECT_FALSE(fs::exists(path("x.png")));
}

// render writes PNG only, so a mesh input can never be its output, not even with --force.
TEST_F(CliRender, NeverWritesAnImageOverAMeshInput) {
  const std::string before = test::read_bytes(path("sphere.ply"));
  const std::string args = "render '" + path("sphere.ply") + "' --color height --size 64x48 -o '" + path("sphere.ply") + "'";
  const test::CliRun refused = test::run_cli(args);
  EXPECT_EQ(refused.exit_code, 1) << refused.out;
  EXPECT_NE(refused.out.find("render writes PNG images only"), std::string::npos) << refused.out;
  EXPECT_EQ(test::run_cli(args + " --force").exit_code, 1);
  EXPECT_TRUE(test::read_bytes(path("sphere.ply")) == before);
}

TEST_F(CliRender, InputAndOutputFailures) {
  EXPECT_EQ(test::run_cli("render '" + path("missing.obj") + "' -o '" + path("x.png") + "'").exit_code, 2);
  EXPECT_EQ(test::run_cli("render '" + path("sphere.ply") + "' --color height --size 64x48 -o '" + path("no/such/dir/x.png") + "'").exit_code, 5);
}
