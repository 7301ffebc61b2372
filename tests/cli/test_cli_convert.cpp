#include <fairsurf/io/io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scratch_dir.h"
#include "test_support.h"

using namespace fairsurf;
namespace fs = std::filesystem;

namespace {

using test::CliRun;
using test::run_cli;

class CliConvert : public test::ScratchDirTest {};

}  // namespace

TEST_F(CliConvert, RoundTripThroughBinaryPlyAndAsciiStl) {
  const fs::path ply = dir_ / "spot.ply", off = dir_ / "spot.off", stl = dir_ / "spot.stl";
  const CliRun first = run_cli("convert '" + test::data_path("spot.obj") + "' -o '" + ply.string() + "'");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  // spot.obj's texture coordinates have seams (a vertex with two), which PLY's per-vertex u, v cannot hold.
  EXPECT_NE(first.out.find("fairsurf: note: " + ply.string() + ": texture coordinates not written: PLY holds one "
                           "per vertex"), std::string::npos)
      << first.out;
  EXPECT_NE(first.out.find("wrote " + ply.string() + ": 2930 vertices, 5856 triangles\n"), std::string::npos);
  EXPECT_EQ(test::read_bytes(ply).find("format binary_little_endian"), 4u);

  ASSERT_EQ(run_cli("convert '" + ply.string() + "' -o '" + off.string() + "'").exit_code, 0);
  const Mesh original = read_mesh(test::data_path("spot.obj"));
  const Mesh back = read_mesh(off);
  EXPECT_EQ(back.V, original.V);
  EXPECT_EQ(back.F, original.F);

  const CliRun ascii = run_cli("convert '" + off.string() + "' -o '" + stl.string() + "' --ascii");
  ASSERT_EQ(ascii.exit_code, 0) << ascii.out;
  EXPECT_EQ(test::read_bytes(stl).rfind("solid fairsurf\n", 0), 0u);
}

TEST_F(CliConvert, RefusesToOverwriteTheInputWithoutForce) {
  const fs::path mesh = dir_ / "mesh.off";
  fs::copy_file(test::data_path("cgal_degtri_sliding.off"), mesh);
  const std::string before = test::read_bytes(mesh);
  const CliRun refused = run_cli("convert '" + mesh.string() + "' -o '" + mesh.string() + "'");
  EXPECT_EQ(refused.exit_code, 5);
  EXPECT_EQ(refused.out, "fairsurf: error: convert: -o would overwrite the input '" + mesh.string() +
                             "' (pass --force to allow it)\n");
  EXPECT_EQ(test::read_bytes(mesh), before);

  const CliRun forced = run_cli("convert '" + mesh.string() + "' -o '" + mesh.string() + "' --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.out;
  EXPECT_EQ(read_mesh(mesh).num_faces(), 8);
}

TEST_F(CliConvert, MissingInputIsAnInputError) {
  const fs::path missing = dir_ / "missing.obj";
  const CliRun run = run_cli("convert '" + missing.string() + "' -o '" + (dir_ / "out.ply").string() + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "fairsurf: error: read_raw: " + missing.string() + ": cannot open (No such file or directory)\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.ply"));
}

TEST_F(CliConvert, UnwritableOutputIsAnOutputError) {
  fs::create_directory(dir_ / "taken.obj");
  const CliRun run = run_cli("convert '" + test::data_path("cgal_degtri_sliding.off") + "' -o '" +
                          (dir_ / "taken.obj").string() + "'");
  EXPECT_EQ(run.exit_code, 5);
  // Checked before reading the input, not found when the rename fails at the end.
  EXPECT_NE(run.out.find("fairsurf: error: convert: -o '" + (dir_ / "taken.obj").string() + "' is a directory"),
            std::string::npos)
      << run.out;
}
