// End-to-end tests of what every command checks before any work (issue #16): output paths, numeric
// ranges, options that take several values, argument errors as one line, `fairsurf help`.
#include <fairsurf/io/io.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "analytic_meshes.h"
#include "scratch_dir.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace fairsurf;

namespace {

class CliArguments : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    write_mesh(path("sphere.obj"), test::icosphere(2));
  }
  std::string path(const std::string& name) const { return file(name); }
  static std::string quoted(const std::string& s) { return "'" + s + "'"; }
  // The sphere as input; a missing file when the test must show that nothing was read.
  std::string sphere() const { return quoted(path("sphere.obj")); }
  std::string missing() const { return quoted(path("missing.obj")); }
};

// The only line of an error run, checked to be exactly one prefixed line.
void expect_one_error_line(const test::CliRun& run, const std::string& contains) {
  EXPECT_TRUE(run.out.starts_with("fairsurf: error: ")) << run.out;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << run.out;
  EXPECT_NE(run.out.find(contains), std::string::npos) << run.out;
}

}  // namespace

// A missing input would exit 2 once read: exit 1 naming the output shows the output was checked
// first, before reading or computing anything.
TEST_F(CliArguments, OutputExtensionIsCheckedBeforeTheInputIsRead) {
  for (const std::string command : {"smooth", "fill", "convert", "repair"}) {
    const auto run = test::run_cli(command + " " + missing() + " -o " + quoted(path("out.xyz")));
    EXPECT_EQ(run.exit_code, 1) << command << ": " << run.out;
    expect_one_error_line(run, command + ": -o '" + path("out.xyz") + "': unknown mesh extension");
  }
  const auto fair = test::run_cli("fair " + missing() + " -o " + quoted(path("out.xyz")) + " --region-property free");
  EXPECT_EQ(fair.exit_code, 1) << fair.out;
  const auto blend = test::run_cli("blend " + missing() + " -o " + quoted(path("out.xyz")));
  EXPECT_EQ(blend.exit_code, 1) << blend.out;
  EXPECT_FALSE(fs::exists(path("out.xyz")));
}

TEST_F(CliArguments, MissingOutputDirectoryIsRefusedBeforeTheInputIsRead) {
  const auto run = test::run_cli("smooth " + missing() + " -o " + quoted(path("nodir/out.obj")));
  EXPECT_EQ(run.exit_code, 5) << run.out;
  expect_one_error_line(run, "the directory '" + path("nodir") + "' does not exist");
  const auto log = test::run_cli("fill " + missing() + " -o " + quoted(path("out.obj")) + " --log " +
                                 quoted(path("nodir/log.json")));
  EXPECT_EQ(log.exit_code, 5) << log.out;
  expect_one_error_line(log, "--log '" + path("nodir/log.json") + "'");
}

TEST_F(CliArguments, RenderRefusesNonPngOutputs) {
  const auto run = test::run_cli("render " + sphere() + " -o " + quoted(path("a.jpg")));
  EXPECT_EQ(run.exit_code, 1) << run.out;
  expect_one_error_line(run, "render writes PNG images only");
  EXPECT_FALSE(fs::exists(path("a.jpg")));
}

TEST_F(CliArguments, RenderRefusesAMeshWithoutFaces) {
  Mesh points;
  points.V = test::icosphere(1).V;
  write_mesh(path("points.ply"), points);
  const auto run = test::run_cli("render " + quoted(path("points.ply")) + " -o " + quoted(path("p.png")));
  EXPECT_EQ(run.exit_code, 3) << run.out;
  EXPECT_NE(run.out.find("has no faces"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(path("p.png")));
}

// Output and log on one file, or the log over an input (the mesh, --fixed-vertices, --region), are refused
// before the input is read; nothing is written.
TEST_F(CliArguments, CollisionsAmongInputsOutputAndLogAreRefused) {
  const std::string out = quoted(path("out.obj"));
  auto run = test::run_cli("smooth " + missing() + " -o " + out + " --log " + out);
  EXPECT_EQ(run.exit_code, 1) << run.out;
  expect_one_error_line(run, "-o and --log name the same file");

  std::ofstream(path("fixed.txt")) << "0\n";
  run = test::run_cli("smooth " + sphere() + " -o " + out + " --fixed-vertices " + quoted(path("fixed.txt")) +
                      " --log " + quoted(path("fixed.txt")));
  EXPECT_EQ(run.exit_code, 5) << run.out;
  expect_one_error_line(run, "--log would overwrite the input '" + path("fixed.txt") + "'");
  EXPECT_EQ(test::read_bytes(path("fixed.txt")), "0\n");

  std::ofstream(path("region.txt")) << "0 1 2\n";
  run = test::run_cli("fair " + sphere() + " -o " + out + " --region " + quoted(path("region.txt")) + " --log " +
                      quoted(path("region.txt")));
  EXPECT_EQ(run.exit_code, 5) << run.out;
  EXPECT_EQ(test::read_bytes(path("region.txt")), "0 1 2\n");
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

// Each out-of-range value exits 1 naming the option and its range, before the input is read.
TEST_F(CliArguments, OutOfRangeNumbersAreRefusedNamingTheOptionAndRange) {
  const std::string out = " -o " + quoted(path("out.obj"));
  const std::vector<std::pair<std::string, std::string>> cases{
      {"smooth --steps 0", "--steps: must be a whole number >= 1 (got '0')"},
      {"smooth --steps -3", "--steps: must be a whole number >= 1 (got '-3')"},
      {"smooth --time 0", "--time: must be a finite number > 0 (got '0')"},
      {"smooth --time -1", "--time: must be a finite number > 0 (got '-1')"},
      {"smooth --tau 0", "--tau: must be a finite number > 0 (got '0')"},
      {"smooth --tau -1", "--tau: must be a finite number > 0 (got '-1')"},
      {"smooth --tau 2", "--tau: must be <= 1"},
      {"smooth --fixed-rings -1", "--fixed-rings: must be a whole number >= 0 (got '-1')"},
      {"smooth --max-steps 0", "--max-steps: must be a whole number >= 1"},
      {"smooth --steady --steady-tolerance 0", "--steady-tolerance: must be a finite number > 0"},
      {"fill --max-steps 0", "--max-steps: must be a whole number >= 1 (got '0')"},
      {"fill --max-steps -5", "--max-steps: must be a whole number >= 1 (got '-5')"},
      {"fill --max-hole-edges 0", "--max-hole-edges: must be a whole number >= 1"},
      {"fill --holes -1", "--holes: must be a whole number >= 0"},
      {"fair --region-property free --max-steps 0", "--max-steps: must be a whole number >= 1"},
      {"blend --max-steps -2", "--max-steps: must be a whole number >= 1"},
      {"repair --merge-tolerance -1", "--merge-tolerance: must be a finite number >= 0"},
      {"repair --min-component-faces -1", "--min-component-faces: must be a whole number >= 0"},
  };
  for (const auto& [arguments, message] : cases) {
    const auto space = arguments.find(' ');
    const auto run = test::run_cli(arguments.substr(0, space) + " " + missing() + out + arguments.substr(space));
    EXPECT_EQ(run.exit_code, 1) << arguments << ": " << run.out;
    expect_one_error_line(run, message);
  }
  const auto scene = test::run_cli("scene fig7" + out + " --edge-length 0");
  EXPECT_EQ(scene.exit_code, 1) << scene.out;
  expect_one_error_line(scene, "--edge-length: must be a finite number > 0");
}

// The user set --time, not τ_max: the message says why that time cannot be reached.
TEST_F(CliArguments, UnreachableTimeIsExplainedInTermsOfWhatTheUserSet) {
  const auto run = test::run_cli("smooth " + missing() + " -o " + quoted(path("out.obj")) + " --time 1e300");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  expect_one_error_line(run, "smooth: --time 1e+300 cannot be reached: --max-steps 1000 steps");
  EXPECT_EQ(run.out.find("tau_max"), std::string::npos) << run.out;
}

// A flag that takes several values takes one per occurrence (or a comma list): the mesh path that
// follows is the input, not one more value.
TEST_F(CliArguments, RepeatableOptionsDoNotSwallowTheMeshPath) {
  const std::string log = quoted(path("log.json"));
  auto run = test::run_cli("smooth --functions H --functions K " + sphere() + " -o " + quoted(path("s.obj")) +
                           " --steps 1 --quiet --log " + log);
  ASSERT_EQ(run.exit_code, 0) << run.out;
  std::ifstream in(path("log.json"));
  EXPECT_EQ(nlohmann::json::parse(in)["functions"], nlohmann::json({"H", "K"}));

  // An open sphere: remove two faces far apart, two holes.
  Mesh open = test::icosphere(2);
  Faces kept(open.F.rows() - 2, 3);
  for (int f = 1, k = 0; f < open.F.rows(); ++f)
    if (f != open.F.rows() / 2) kept.row(k++) = open.F.row(f);
  open.F = kept;
  write_mesh(path("open.obj"), open);
  run = test::run_cli("fill --holes 0 --holes 1 " + quoted(path("open.obj")) + " -o " + quoted(path("f.obj")) +
                      " --max-steps 5 --quiet");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("filled 2 of 2 selected holes"), std::string::npos) << run.out;
  run = test::run_cli("fill " + quoted(path("open.obj")) + " -o " + quoted(path("f.obj")) +
                      " --holes 0,1 --max-steps 5 --quiet --force");
  EXPECT_NE(run.out.find("filled 2 of 2 selected holes"), std::string::npos) << run.out;

  run = test::run_cli("render --compare " + sphere() + " " + sphere() + " -o " + quoted(path("r.png")) +
                      " --size 120x90");
  EXPECT_EQ(run.exit_code, 0) << run.out;
}

TEST_F(CliArguments, ParseErrorsAreOnePrefixedLine) {
  auto run = test::run_cli("smooth " + sphere());
  EXPECT_EQ(run.exit_code, 1) << run.out;
  expect_one_error_line(run, "smooth: --output is required");
  run = test::run_cli("fill " + sphere() + " -o x.obj --no-such-flag");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  expect_one_error_line(run, "fill: ");
  run = test::run_cli("");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  expect_one_error_line(run, "a command is required");
}

TEST_F(CliArguments, HelpCommandPrintsTheHelp) {
  auto run = test::run_cli("help");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("smooth"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("render"), std::string::npos) << run.out;
  run = test::run_cli("help fill");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("--max-hole-edges"), std::string::npos) << run.out;
  run = test::run_cli("help nope");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  expect_one_error_line(run, "help: unknown command 'nope'");
}
