// Walks docs/cli.md's exit-code table command by command: for each command, one run per code the
// docs give it (0 success, 1 usage, 2 input, 3 invalid mesh, 4 numerical failure, 5 output).
#include <fairsurf/io/io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "analytic_meshes.h"
#include "scratch_dir.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace fairsurf;

namespace {

class CliExitCodes : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    write_mesh(file("sphere.ply"), test::icosphere(2));
    Mesh open = test::icosphere(2);
    open.F = open.F.bottomRows(open.F.rows() - 1).eval();
    write_mesh(file("open.obj"), open);
    Mesh points;
    points.V = test::icosphere(1).V;
    write_mesh(file("points.ply"), points);
  }
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "'" + a temporary string.
  std::string path(const std::string& name) const { return std::string("'").append(file(name)).append("'"); }
  static std::string data(const std::string& name) {
    return std::string("'").append(test::data_path(name)).append("'");
  }

  // Runs each command line and checks its exit code and that an error is one prefixed line.
  void expect_codes(const std::vector<std::pair<std::string, int>>& runs) const {
    for (const auto& [arguments, code] : runs) {
      const auto run = test::run_cli(arguments);
      EXPECT_EQ(run.exit_code, code) << arguments << "\n" << run.out;
      if (code != 0) {
        EXPECT_NE(run.out.find("fairsurf: error: "), std::string::npos) << arguments << "\n" << run.out;
      }
    }
  }
};

}  // namespace

TEST_F(CliExitCodes, Info) {
  expect_codes({{"info " + path("sphere.ply"), 0},
                {"info " + path("sphere.ply") + " --no-such-flag", 1},
                {"info " + path("missing.obj"), 2},
                {"info " + data("hourglass_ico.obj") + " --strict", 3}});
}

TEST_F(CliExitCodes, Curvature) {
  expect_codes({{"curvature " + path("sphere.ply") + " -o " + path("c.ply"), 0},
                {"curvature " + path("sphere.ply") + " -o " + path("c.obj"), 1},
                {"curvature " + path("missing.obj") + " -o " + path("c.ply"), 2},
                {"curvature " + path("points.ply") + " -o " + path("c.ply") + " --force", 3},
                {"curvature " + path("sphere.ply") + " -o " + path("sphere.ply"), 5}});
}

TEST_F(CliExitCodes, Smooth) {
  expect_codes({{"smooth " + path("sphere.ply") + " -o " + path("s.ply") + " --steps 1 --quiet", 0},
                {"smooth " + path("sphere.ply") + " -o " + path("s.ply") + " --flow curly", 1},
                {"smooth " + path("missing.obj") + " -o " + path("s.ply"), 2},
                {"smooth " + data("hourglass_ico.obj") + " -o " + path("s.ply") + " --force", 3},
                {"smooth " + data("torus.obj") + " -o " + path("k.obj") +
                     " --functions K --tau 0.9 --steps 30 --quiet",
                 4},
                {"smooth " + path("sphere.ply") + " -o " + path("sphere.ply"), 5}});
}

TEST_F(CliExitCodes, Fill) {
  expect_codes({{"fill " + path("open.obj") + " -o " + path("f.obj") + " --max-steps 5 --quiet", 0},
                {"fill " + path("open.obj") + " -o " + path("f.obj") + " --holes 9", 1},
                {"fill " + path("missing.obj") + " -o " + path("f.obj"), 2},
                {"fill " + data("hourglass_ico.obj") + " -o " + path("f.obj") + " --force", 3},
                {"fill " + path("open.obj") + " -o " + path("open.obj"), 5}});
}

TEST_F(CliExitCodes, Render) {
  expect_codes({{"render " + path("sphere.ply") + " -o " + path("r.png") + " --size 80x60", 0},
                {"render " + path("sphere.ply") + " -o " + path("r.png") + " --color nope", 1},
                {"render " + path("missing.obj") + " -o " + path("r.png"), 2},
                {"render " + path("points.ply") + " -o " + path("r.png") + " --force", 3},
                {"render " + path("sphere.ply") + " -o " + path("r.png") + " --compare " + path("r.png"), 5}});
}

TEST_F(CliExitCodes, Convert) {
  expect_codes({{"convert " + path("sphere.ply") + " -o " + path("c.off"), 0},
                {"convert " + path("sphere.ply") + " -o " + path("c.off") + " --no-such-flag", 1},
                {"convert " + path("missing.obj") + " -o " + path("c.off"), 2},
                {"convert " + path("sphere.ply") + " -o " + path("sphere.ply"), 5}});
}

TEST_F(CliExitCodes, Fair) {
  std::ofstream(file("region.txt")) << "0 1 99999\n";
  std::ofstream(file("one.txt")) << "0\n";
  expect_codes({{"fair " + path("sphere.ply") + " -o " + path("f.ply") + " --region-sphere 0,0,1,0.5 --quiet", 0},
                {"fair " + path("sphere.ply") + " -o " + path("f.ply") + " --region-sphere 0,0,9,0.1", 1},
                {"fair " + path("sphere.ply") + " -o " + path("f.ply") + " --region " + path("region.txt"), 2},
                {"fair " + data("hourglass_ico.obj") + " -o " + path("f.ply") + " --region " + path("one.txt") + " --force", 3},
                {"fair " + path("sphere.ply") + " -o " + path("sphere.ply") + " --region-sphere 0,0,1,0.5", 5}});
}

TEST_F(CliExitCodes, Blend) {
  ASSERT_EQ(test::run_cli("scene fig4 -o " + path("fig4.ply") + " --edge-length 0.3").exit_code, 0);
  expect_codes({{"blend " + path("fig4.ply") + " -o " + path("b.ply") + " --max-steps 3 --quiet", 0},
                {"blend " + path("fig4.ply") + " -o " + path("b.ply") + " --loops 0,0 --force", 1},
                {"blend " + path("missing.obj") + " -o " + path("b.ply"), 2},
                {"blend " + data("lagrange_prout.obj") + " -o " + path("b.ply") + " --force", 3},
                {"blend " + data("moebius_160_10.ply") + " -o " + path("b.ply") + " --force", 3},
                {"blend " + path("fig4.ply") + " -o " + path("fig4.ply"), 5}});
}

TEST_F(CliExitCodes, Repair) {
  expect_codes({{"repair " + data("hourglass_ico.obj") + " -o " + path("r.obj"), 0},
                {"repair " + path("sphere.ply") + " -o " + path("r.obj") + " --no-such-flag", 1},
                {"repair " + path("missing.obj") + " -o " + path("r.obj"), 2},
                {"repair " + path("points.ply") + " -o " + path("r.obj") + " --force", 3},
                {"repair " + path("sphere.ply") + " -o " + path("sphere.ply"), 5}});
}

TEST_F(CliExitCodes, Scene) {
  expect_codes({{"scene fig8 -o " + path("s.ply"), 0},
                {"scene nope -o " + path("s.ply"), 1},
                {"scene fig8 -o " + path("nodir/s.ply"), 5}});
}
